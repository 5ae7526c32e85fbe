/// Tests of the cubic B-spline curves in R³ (root translation): derivatives by finite
/// differences, exact reproduction of a cubic polynomial by the least-squares fit, and AD with
/// respect to a control point against the basis weight.

#include "saltus/math/vector_spline.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <vector>

#include "support/spline_fixtures.h"

namespace saltus {
namespace {

using test::AdFixed;
using test::kNonUniformTimes;
using test::knots_for;

std::vector<Eigen::Vector3d> random_points(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < n; ++i)
    p.emplace_back(uniform(rng), uniform(rng), uniform(rng));
  return p;
}

TEST(VectorSpline, ConstructorChecksControlCount) {
  const std::vector<double> k = knots_for(kNonUniformTimes, 1);
  EXPECT_THROW(VectorSpline<double>(k, random_points(control_count(k) + 1, 1)),
               std::invalid_argument);
}

TEST(VectorSpline, DerivativesMatchFiniteDifferences) {
  const std::vector<double> k = knots_for(kNonUniformTimes, 2);
  const VectorSpline<double> s(k, random_points(control_count(k), 3));
  const double h = 1e-6;
  for (double t = 0.017; t < 2.04 - h; t += 0.0531) {
    const VectorSample<double> x = s.evaluate(t);
    const VectorSample<double> p = s.evaluate(t + h), m = s.evaluate(t - h);
    EXPECT_LT((x.velocity - (p.position - m.position) / (2 * h)).norm(),
              1e-6 * (1 + x.velocity.norm()));
    EXPECT_LT((x.acceleration - (p.velocity - m.velocity) / (2 * h)).norm(),
              1e-5 * (1 + x.acceleration.norm()));
  }
  EXPECT_LT((s.evaluate(0.0).position - s.control().front()).norm(), 1e-15);
  EXPECT_LT((s.evaluate(2.04).position - s.control().back()).norm(), 1e-15);
}

TEST(VectorSpline, FitReproducesCubicPolynomial) {
  // A cubic polynomial lies in the spline space, so the fit must be exact.
  const auto cubic = [](double t) {
    return Eigen::Vector3d(1.0 - 2.0 * t + 0.5 * t * t * t, 0.3 + 4.0 * t - 4.905 * t * t,
                           -0.2 + 0.7 * t * t - 0.1 * t * t * t);
  };
  const auto cubic_velocity = [](double t) {
    return Eigen::Vector3d(-2.0 + 1.5 * t * t, 4.0 - 9.81 * t, 1.4 * t - 0.3 * t * t);
  };
  for (int refine = 1; refine <= 3; ++refine) {
    const std::vector<double> k = knots_for(kNonUniformTimes, refine);
    std::vector<double> times;
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i <= 200; ++i) {
      times.push_back(2.04 * i / 200.0);
      points.push_back(cubic(times.back()));
    }
    const VectorSpline<double> s(k, fit_vector_spline(k, times, points, 0.0));
    for (double t = 0.0; t <= 2.04; t += 0.0097) {
      EXPECT_LT((s.evaluate(t).position - cubic(t)).norm(), 1e-9);
      EXPECT_LT((s.evaluate(t).velocity - cubic_velocity(t)).norm(), 1e-8);
    }
    // The default regulariser (1e-9) biases the fit by O(1e-9) only.
    const VectorSpline<double> r(k, fit_vector_spline(k, times, points));
    for (double t = 0.0; t <= 2.04; t += 0.0097)
      EXPECT_LT((r.evaluate(t).position - cubic(t)).norm(), 1e-8);
  }
}

TEST(VectorSpline, FitRejectsBadInput) {
  const std::vector<double> k = knots_for(kNonUniformTimes, 1);
  EXPECT_THROW(fit_vector_spline(k, {0.0, 1.0}, random_points(3, 1)), std::invalid_argument);
  EXPECT_THROW(fit_vector_spline(k, {0.0, 3.0}, random_points(2, 1)), std::invalid_argument);
  // Two samples cannot fix seven control points without the regulariser.
  EXPECT_THROW(fit_vector_spline(k, {0.0, 1.0}, random_points(2, 1), 0.0), std::invalid_argument);
}

TEST(VectorSpline, AutoDiffWithRespectToControlPoint) {
  const std::vector<double> k = knots_for(kNonUniformTimes, 1);
  const std::vector<Eigen::Vector3d> c = random_points(control_count(k), 9);
  std::vector<AdFixed> kad(k.begin(), k.end());
  std::vector<Vec3<AdFixed>> cad;
  for (std::size_t i = 0; i < c.size(); ++i) {
    cad.push_back(c[i].cast<AdFixed>());
    if (i == 3)
      for (int a = 0; a < 3; ++a)
        cad.back()[a] = AdFixed(c[i][a], 3, a);
  }
  const VectorSpline<AdFixed> s(kad, cad);
  for (double t = 0.0; t <= 2.04; t += 0.1) {
    const SpanBasis<double> b = cubic_basis(k, t);
    const int j = 3 - b.first_control();
    const double weight = (j >= 0 && j < 4) ? b.value[0][j] : 0.0;
    const VectorSample<AdFixed> x = s.evaluate(AdFixed(t));
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(x.position[a].derivatives()[a], weight, 1e-15);
  }
}

}  // namespace
}  // namespace saltus
