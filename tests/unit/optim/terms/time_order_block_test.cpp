// The ordered-keyframe-time constraints (optim/terms/time_order_block.h) against central finite
// differences, through the term and block interfaces (support/term_checks.h).

#include "saltus/optim/terms/time_order_block.h"

#include <gtest/gtest.h>

#include "support/term_checks.h"

namespace saltus {
namespace {

TEST(TimeOrderBlock, JacobianMatchesFiniteDifferencesAndItsSparsity) {
  test::RandomPoint p(Formulation::kRelaxed);
  test::check_block(p, p.block("time order"), p.x);
}

}  // namespace
}  // namespace saltus
