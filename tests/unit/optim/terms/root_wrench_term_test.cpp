// The relaxed model's root-wrench term (mean squared root wrench, eq. 1) with its damped
// Gauss–Newton curvature (optim/terms/root_wrench_term.h) against central finite differences,
// through the term and block interfaces (support/term_checks.h).

#include "saltus/optim/terms/root_wrench_term.h"

#include <gtest/gtest.h>

#include "support/term_checks.h"

namespace saltus {
namespace {

TEST(RootWrenchTerm, ValueGradientAndDampedGaussNewtonMatchFiniteDifferences) {
  test::RandomPoint p(Formulation::kRelaxed);
  test::check_term(p, p.term("root wrench"), p.x, p.nlp->damping_factor());
}

}  // namespace
}  // namespace saltus
