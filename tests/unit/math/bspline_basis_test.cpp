/// Tests of the cubic B-spline basis: knot layout, span conventions, partition of unity, and every
/// derivative (time, keyframe time) cross-checked by an independent path (a naive recursive
/// Cox-de Boor, finite differences, automatic differentiation) rather than against stored numbers.

#include "saltus/math/bspline_basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "support/spline_fixtures.h"

namespace saltus {
namespace {

using test::AdDynamic;
using test::AdFixed;
using test::kNonUniformTimes;
using test::knots_for;

/// Naive recursive Cox-de Boor (de Boor 1972) on the whole knot vector, right-continuous, with
/// the last non-empty span closed on the right: an independent path for the span algorithm.
double naive_basis(const std::vector<double>& k, int i, int p, double t) {
  if (p == 0) {
    const int n = static_cast<int>(k.size()) - 4;
    if (t == k[n]) return (i == n - 1) ? 1.0 : 0.0;
    return (k[i] <= t && t < k[i + 1]) ? 1.0 : 0.0;
  }
  double result = 0.0;
  if (k[i + p] != k[i]) result += (t - k[i]) / (k[i + p] - k[i]) * naive_basis(k, i, p - 1, t);
  if (k[i + p + 1] != k[i + 1])
    result += (k[i + p + 1] - t) / (k[i + p + 1] - k[i + 1]) * naive_basis(k, i + 1, p - 1, t);
  return result;
}

TEST(BsplineBasis, KnotLayoutAndRefinement) {
  const std::vector<double> b = refine_breakpoints(std::vector<double>{0.0, 1.0, 3.0}, 2);
  ASSERT_EQ(b.size(), 5u);
  EXPECT_DOUBLE_EQ(b[1], 0.5);
  EXPECT_DOUBLE_EQ(b[3], 2.0);
  const std::vector<double> k = clamped_cubic_knots(b);
  ASSERT_EQ(k.size(), b.size() + 6);
  EXPECT_EQ(control_count(k), static_cast<int>(b.size()) + 2);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(k[i], 0.0);
    EXPECT_EQ(k[k.size() - 1 - i], 3.0);
  }
  EXPECT_THROW(refine_breakpoints(std::vector<double>{0.0, 1.0}, 0), std::invalid_argument);
  EXPECT_THROW(clamped_cubic_knots(std::vector<double>{1.0}), std::invalid_argument);
}

TEST(BsplineBasis, RefinementPerInterval) {
  // Interval i split into K_i equal parts; the keyframe times themselves stay breakpoints.
  const std::vector<double> times = {0.0, 1.0, 3.0, 3.5};
  const std::vector<double> b = refine_breakpoints(times, std::vector<int>{1, 4, 2});
  const std::vector<double> expected = {0.0, 1.0, 1.5, 2.0, 2.5, 3.0, 3.25, 3.5};
  ASSERT_EQ(b.size(), expected.size());
  for (std::size_t i = 0; i < b.size(); ++i)
    EXPECT_NEAR(b[i], expected[i], 1e-15) << i;
  EXPECT_EQ(b[1], 1.0);
  EXPECT_EQ(b[5], 3.0);
  EXPECT_EQ(refine_breakpoints(times, std::vector<int>{3, 3, 3}), refine_breakpoints(times, 3));
  EXPECT_THROW(refine_breakpoints(times, std::vector<int>{1, 1}), std::invalid_argument);
  EXPECT_THROW(refine_breakpoints(times, std::vector<int>{1, 0, 1}), std::invalid_argument);
}

TEST(BsplineBasis, FindSpanConventions) {
  const std::vector<double> k = knots_for(kNonUniformTimes, 1);  // n = 7, spans 3..6
  EXPECT_EQ(find_span(k, 0.0), 3);
  EXPECT_EQ(find_span(k, -1.0), 3);
  EXPECT_EQ(find_span(k, 0.30), 3);
  EXPECT_EQ(find_span(k, 0.31), 4);  // an interior knot belongs to the span on its right
  EXPECT_EQ(find_span(k, 1.0), 5);
  EXPECT_EQ(find_span(k, 1.2), 6);
  EXPECT_EQ(find_span(k, 2.04), 6);  // t = T uses the last span
  EXPECT_EQ(find_span(k, 5.0), 6);
  EXPECT_THROW(cubic_basis_on_span(k, 7, 1.0), std::out_of_range);
  EXPECT_THROW(cubic_basis_on_span(k, 2, 1.0), std::out_of_range);
}

TEST(BsplineBasis, PartitionOfUnityAndCumulative) {
  for (int refine = 1; refine <= 3; ++refine) {
    const std::vector<double> k = knots_for(kNonUniformTimes, refine);
    for (double t = 0.0; t <= 2.04; t += 0.0123) {
      const SpanBasis<double> b = cubic_basis(k, t);
      double sum[3] = {0, 0, 0};
      for (int d = 0; d < 3; ++d)
        for (int j = 0; j < 4; ++j)
          sum[d] += b.value[d][j];
      EXPECT_NEAR(sum[0], 1.0, 1e-14);
      EXPECT_NEAR(sum[1], 0.0, 1e-11);
      EXPECT_NEAR(sum[2], 0.0, 1e-9);
      for (int j = 0; j < 4; ++j)
        EXPECT_GE(b.value[0][j], -1e-15);
      for (int d = 0; d < 3; ++d) {
        for (int j = 0; j < 4; ++j) {
          double tail = 0.0;
          for (int i = j; i < 4; ++i)
            tail += b.value[d][i];
          EXPECT_NEAR(b.cumulative[d][j], tail, 1e-9 * (1 + std::abs(tail)));
        }
      }
    }
  }
}

TEST(BsplineBasis, MatchesNaiveRecursion) {
  const std::vector<double> k = knots_for(kNonUniformTimes, 2);
  const int n = control_count(k);
  for (double t : {0.0, 0.05, 0.155, 0.31, 0.6, 0.899, 1.2, 1.7, 2.04}) {
    const SpanBasis<double> b = cubic_basis(k, t);
    for (int i = 0; i < n; ++i) {
      const int j = i - b.first_control();
      const double expected = naive_basis(k, i, 3, t);
      const double got = (j >= 0 && j < 4) ? b.value[0][j] : 0.0;
      EXPECT_NEAR(got, expected, 1e-14) << "i=" << i << " t=" << t;
    }
  }
}

TEST(BsplineBasis, TimeDerivativesMatchFiniteDifferences) {
  const std::vector<double> k = knots_for(kNonUniformTimes, 3);
  const double h = 1e-6;
  for (double t = 0.013; t < 2.04; t += 0.0371) {
    const SpanBasis<double> b = cubic_basis(k, t);
    // Stay on the span: the polynomial piece is what the derivatives describe.
    const SpanBasis<double> plus = cubic_basis_on_span(k, b.span, t + h);
    const SpanBasis<double> minus = cubic_basis_on_span(k, b.span, t - h);
    for (int d = 0; d < 2; ++d) {
      for (int j = 0; j < 4; ++j) {
        const double fd = (plus.value[d][j] - minus.value[d][j]) / (2 * h);
        EXPECT_NEAR(b.value[d + 1][j], fd, 1e-6 * (1 + std::abs(fd))) << "d=" << d << " t=" << t;
        const double fdc = (plus.cumulative[d][j] - minus.cumulative[d][j]) / (2 * h);
        EXPECT_NEAR(b.cumulative[d + 1][j], fdc, 1e-6 * (1 + std::abs(fdc)));
      }
    }
  }
}

TEST(BsplineBasis, DerivativeWithRespectToKeyframeTimeMatchesFiniteDifferences) {
  // Differentiate through refine_breakpoints and clamped_cubic_knots, as timing optimisation
  // does: the interior keyframe times are the AD variables.
  for (int refine : {1, 3}) {
    for (int which = 1; which <= 3; ++which) {
      // Every value carries a derivative vector of size 1: Eigen's AutoDiffScalar reads past an
      // empty one when it meets a sized one inside an expression (UBSan saw it).
      std::vector<AdDynamic> times;
      for (std::size_t i = 0; i < kNonUniformTimes.size(); ++i)
        times.emplace_back(kNonUniformTimes[i],
                           Eigen::VectorXd::Constant(1, static_cast<int>(i) == which ? 1.0 : 0.0));
      const std::vector<AdDynamic> k = clamped_cubic_knots(refine_breakpoints(times, refine));
      const double h = 1e-6;
      std::vector<double> plus_times = kNonUniformTimes, minus_times = kNonUniformTimes;
      plus_times[which] += h;
      minus_times[which] -= h;
      const std::vector<double> kp = knots_for(plus_times, refine);
      const std::vector<double> km = knots_for(minus_times, refine);
      for (double t : {0.1, 0.35, 0.8, 1.05, 1.5, 1.99}) {
        const SpanBasis<AdDynamic> b = cubic_basis(k, AdDynamic(t, Eigen::VectorXd::Zero(1)));
        const SpanBasis<double> bp = cubic_basis_on_span(kp, b.span, t);
        const SpanBasis<double> bm = cubic_basis_on_span(km, b.span, t);
        for (int d = 0; d < 3; ++d) {
          for (int j = 0; j < 4; ++j) {
            const double fd = (bp.value[d][j] - bm.value[d][j]) / (2 * h);
            const auto& der = b.value[d][j].derivatives();
            const double ad = der.size() > 0 ? der[0] : 0.0;
            EXPECT_NEAR(ad, fd, 1e-5 * (1 + std::abs(fd)))
                << "refine=" << refine << " keyframe=" << which << " t=" << t << " d=" << d;
          }
        }
      }
    }
  }
}

TEST(BsplineBasis, DerivativeOfBasisWithRespectToTimeByAd) {
  const std::vector<double> kd = knots_for(kNonUniformTimes, 1);
  std::vector<AdFixed> k(kd.begin(), kd.end());
  for (double t = 0.02; t < 2.04; t += 0.1) {
    const SpanBasis<AdFixed> b = cubic_basis(k, AdFixed(t, 3, 0));
    for (int d = 0; d < 2; ++d)
      for (int j = 0; j < 4; ++j)
        EXPECT_NEAR(b.value[d][j].derivatives()[0], b.value[d + 1][j].value(), 1e-10);
  }
}

}  // namespace
}  // namespace saltus
