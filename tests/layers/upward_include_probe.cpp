// Built only by the test layers_upward_include_fails: a file of the body layer that includes
// the optimiser must not compile, because saltus_body does not see the layers above it.
#include "saltus/optim/optimize.h"
