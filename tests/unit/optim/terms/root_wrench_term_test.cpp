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

// Least joint effort's polish weighs the root moment 100 times (kPolishRootMomentWeight; 300 in
// one of its tries): the weighted term's derivatives still match finite differences, its value
// is J with the moment's share multiplied by the weight, and force_objective() stays the
// paper's J.
TEST(RootWrenchTerm, AWeightedMomentKeepsTheDerivativesAndTheReportedJ) {
  test::RandomPoint plain(Formulation::kRelaxed, 11, 2, 1.0);
  test::RandomPoint weighted(Formulation::kRelaxed, 11, 2, 100.0);
  ASSERT_EQ(plain.x, weighted.x);
  test::check_term(weighted, weighted.term("root wrench"), weighted.x,
                   weighted.nlp->damping_factor());
  const double j = plain.nlp->force_objective(plain.x.data());
  EXPECT_DOUBLE_EQ(weighted.nlp->force_objective(weighted.x.data()), j);
  // J = force share + moment share; weighted = force share + 100 × moment share.
  NlpEvaluations& at = weighted.nlp->evaluations();
  at.load(weighted.x.data());
  const double value = weighted.term("root wrench").value(at);
  const std::vector<double> r = weighted.term("root wrench").residuals(at);
  double force_share = 0.0, moment_share = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i)
    (i % 6 < 3 ? force_share : moment_share) += r[i] * r[i];
  EXPECT_NEAR(value, force_share + moment_share, 1e-9 * value);
  EXPECT_NEAR(j, force_share + moment_share / 100.0, 1e-9 * j);
  EXPECT_GT(moment_share, 0.0);
}

}  // namespace
}  // namespace saltus
