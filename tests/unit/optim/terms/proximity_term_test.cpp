// The proximity term that keeps the joints near the keyframed motion (optim/terms/proximity_term.h)
// against central finite differences, through the term and block interfaces
// (support/term_checks.h).

#include "saltus/optim/terms/proximity_term.h"

#include <gtest/gtest.h>

#include "support/term_checks.h"

namespace saltus {
namespace {

TEST(ProximityTerm, ValueGradientAndCurvatureMatchFiniteDifferences) {
  test::RandomPoint p(Formulation::kRelaxed);
  test::check_term(p, p.term("proximity"), p.x);
}

}  // namespace
}  // namespace saltus
