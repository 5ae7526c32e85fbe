// The keyframe rotation constraints (eq. 3), and their curvature where they are met
// (optim/terms/keyframe_rotation_block.h) against central finite differences, through the term and
// block interfaces (support/term_checks.h).

#include "saltus/optim/terms/keyframe_rotation_block.h"

#include <gtest/gtest.h>

#include <random>

#include "support/term_checks.h"

namespace saltus {
namespace {

TEST(KeyframeRotationBlock, JacobianMatchesFiniteDifferencesAndItsSparsity) {
  test::RandomPoint p(Formulation::kRelaxed);
  test::check_block(p, p.block("keyframe rotation"), p.x);
}

TEST(KeyframeRotationBlock, CurvatureIsGaussNewtonWhereTheKeyframesAreMet) {
  // At the interpolation the keyframe rotations are met to rounding, so there ∇²g equals its
  // Gauss–Newton part: compare λᵀ∇²g along v with differences of the rows' Jacobian.
  test::RandomPoint p(Formulation::kRelaxed);
  ConstraintBlock& block = p.block("keyframe rotation");
  NlpEvaluations& at = p.nlp->evaluations();
  const int n = p.nlp->variable_count(), rows = block.rows();
  std::vector<double> multipliers(rows);
  for (int r = 0; r < rows; ++r)
    multipliers[r] = 0.5 + 0.01 * r;
  const HessianBand band(p.nlp->layout());
  std::vector<double> values(band.nonzeros(), 0.0);
  at.load(p.start.data());
  block.add_curvature(at, multipliers.data(), band, values.data());
  std::mt19937 rng(9);
  std::normal_distribution<double> g;
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i)
    v[i] = g(rng);
  // d/dε of λᵀ J(x + εv) v, J v by differences of the rows along v.
  auto weighted_rows = [&](const std::vector<double>& y) {
    at.load(y.data());
    std::vector<double> r(rows);
    block.values(at, r.data());
    double sum = 0.0;
    for (int i = 0; i < rows; ++i)
      sum += multipliers[i] * r[i];
    return sum;
  };
  const double h = 1e-4;
  const double second = (weighted_rows(test::along(p.start, v, h)) - 2.0 * weighted_rows(p.start) +
                         weighted_rows(test::along(p.start, v, -h))) /
                        (h * h);
  const double actual = band.quadratic_form(values, v.data());
  EXPECT_NEAR(actual, second, 1e-3 * std::abs(second));
  EXPECT_GT(actual, 0.0);
}

}  // namespace
}  // namespace saltus
