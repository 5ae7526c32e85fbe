// The root-force figures (evaluation/force_metrics.h) on wrenches whose integrals are known in
// closed form: constant wrenches, and squared forces linear in time, which the trapezoidal rule
// integrates exactly on any grid. The dense check against the trapezoidal rule on a grid a
// hundred times finer, on interpolated motions with uneven knot spans.

#include "saltus/evaluation/force_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

std::vector<SampleRecord> samples_at(const std::vector<double>& times) {
  std::vector<SampleRecord> out(times.size());
  for (std::size_t k = 0; k < times.size(); ++k)
    out[k].time = times[k];
  return out;
}

TEST(ForceMetrics, ConstantWrenchOnAnUnevenGrid) {
  std::vector<SampleRecord> samples = samples_at({0.0, 0.5, 2.0, 2.04});
  for (SampleRecord& s : samples)
    s.root_wrench << 1, 2, 2, 0, 3, 4;  // |F| = 3 N, |M| = 5 N·m
  const ForceMetrics m = force_metrics(samples);
  EXPECT_NEAR(m.objective, 9.0 + 25.0, 1e-12);
  EXPECT_NEAR(m.avg_root_force, std::sqrt(34.0 / 6.0), 1e-12);
  EXPECT_NEAR(m.rms_force_N, 3.0, 1e-12);
  EXPECT_NEAR(m.rms_moment_Nm, 5.0, 1e-12);
  EXPECT_NEAR(m.max_force_N, 3.0, 1e-12);
  EXPECT_NEAR(m.max_moment_Nm, 5.0, 1e-12);
}

TEST(ForceMetrics, SquaredForcesLinearInTimeAverageExactlyOnRandomGrids) {
  // F_x = sqrt(t − t0) and M_z = sqrt(2·(t1 − t)) on [t0, t1]: |F|² and |M|² are linear in t, so
  // their time means are (t1 − t0)/2 and (t1 − t0) whatever the grid; J is the sum.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> gap(0.001, 0.1);
  for (int trial = 0; trial < 20; ++trial) {
    const double t0 = 0.3 * trial / 20.0;
    std::vector<double> times{t0};
    while (times.size() < 5 || times.back() < t0 + 1.5)
      times.push_back(times.back() + gap(rng));
    const double t1 = times.back(), length = t1 - t0;
    std::vector<SampleRecord> samples = samples_at(times);
    for (SampleRecord& s : samples) {
      s.root_wrench.setZero();
      s.root_wrench[0] = std::sqrt(s.time - t0);
      s.root_wrench[5] = -std::sqrt(std::max(0.0, 2.0 * (t1 - s.time)));
    }
    const ForceMetrics m = force_metrics(samples);
    EXPECT_NEAR(m.rms_force_N, std::sqrt(length / 2), 1e-12) << trial;
    EXPECT_NEAR(m.rms_moment_Nm, std::sqrt(length), 1e-12) << trial;
    EXPECT_NEAR(m.objective, 1.5 * length, 1e-12) << trial;
    EXPECT_NEAR(m.avg_root_force, std::sqrt(1.5 * length / 6), 1e-12) << trial;
    EXPECT_NEAR(m.max_force_N, std::sqrt(length), 1e-12) << trial;
    EXPECT_NEAR(m.max_moment_Nm, std::sqrt(2 * length), 1e-12) << trial;
  }
}

TEST(ForceMetrics, FewerThanTwoSamplesSpanNoTime) {
  const ForceMetrics none = force_metrics({});
  std::vector<SampleRecord> one = samples_at({0.4});
  one[0].root_wrench.setConstant(7.0);
  const ForceMetrics single = force_metrics(one);
  for (const ForceMetrics& m : {none, single}) {
    EXPECT_EQ(m.objective, 0.0);
    EXPECT_EQ(m.avg_root_force, 0.0);
    EXPECT_EQ(m.max_force_N, 0.0);
  }
}

TEST(DenseCheck, IsTheIntegralOfTheRootWrenchSpanBySpan) {
  const BodyModel model = test::bundled_model();
  for (const Motion& motion : {test::pike_motion(model), test::tuck_motion(model)}) {
    SCOPED_TRACE(motion.name);
    InterpolationOptions options;
    options.subdivisions.assign(motion.keyframes.size() - 1, 1);
    options.subdivisions[1] = 3;
    const Trajectory<double> trajectory = interpolate_keyframes(motion, model, options);
    const DenseCheck check = dense_check(model, trajectory, 200);
    const ForceMetrics fine = force_metrics(
        evaluate_trajectory(model, trajectory, uniform_times(trajectory.duration(), 20001)));
    // Simpson per span against a fine trapezoid (error ~h²·|F²''|, here well below 1e-6).
    EXPECT_NEAR(check.metrics.objective, fine.objective, 1e-6 * fine.objective);
    EXPECT_NEAR(check.metrics.rms_force_N, fine.rms_force_N, 1e-6 * fine.rms_force_N);
    EXPECT_NEAR(check.metrics.rms_moment_Nm, fine.rms_moment_Nm, 1e-6 * fine.rms_moment_Nm);
    EXPECT_NEAR(check.metrics.avg_root_force, std::sqrt(check.metrics.objective / 6), 1e-12);
    EXPECT_TRUE(check.converged);
    EXPECT_GE(check.halvings, 1);
    // Peaks over points at most kCheckMaxSpacing apart: within a hair of the fine grid's.
    EXPECT_LE(check.metrics.max_force_N, fine.max_force_N * (1 + 1e-9));
    EXPECT_GT(check.metrics.max_force_N, fine.max_force_N * (1 - 1e-3));
    // One entry per knot span, the spans tile the flight, and their integrals make up J·T.
    const int spans = static_cast<int>(trajectory.knots.size()) - 7;
    ASSERT_EQ(static_cast<int>(check.span_integral.size()), spans);
    EXPECT_EQ(check.span_start.front(), 0.0);
    EXPECT_EQ(check.span_end.back(), trajectory.duration());
    for (int s = 0; s < spans; ++s) {
      EXPECT_EQ(check.span_start[s], trajectory.knots[3 + s]);
      EXPECT_EQ(check.span_end[s], trajectory.knots[4 + s]);
      EXPECT_GT(check.span_integral[s], 0.0);
    }
    const double total =
        std::accumulate(check.span_integral.begin(), check.span_integral.end(), 0.0);
    EXPECT_NEAR(total / trajectory.duration(), check.metrics.objective,
                1e-12 * check.metrics.objective);
    EXPECT_GE(check.points, 200);
    EXPECT_GE(check.points, spans * (kCheckPointsPerSpan + 1));
    EXPECT_GE(check.points, static_cast<int>(trajectory.duration() / kCheckMaxSpacing));
  }
}

TEST(ResidualShares, ASpanCountsInTheKeyframeIntervalHoldingItsMiddle) {
  DenseCheck check;
  // Three spans over keyframes at 0, 0.5 and 1 s; the second straddles 0.5 s with its middle
  // at 0.45 s, so it counts in the first interval.
  check.span_start = {0.0, 0.3, 0.6};
  check.span_end = {0.3, 0.6, 1.0};
  check.span_integral = {1.0, 2.0, 4.0};
  EXPECT_EQ(residual_per_interval(check, {0.0, 0.5, 1.0}), (std::vector<double>{3.0, 4.0}));
  const std::vector<double> shares = residual_shares(check, {0.0, 0.5, 1.0});
  EXPECT_NEAR(shares[0], 3.0 / 7.0, 1e-15);
  EXPECT_NEAR(shares[1], 4.0 / 7.0, 1e-15);
  EXPECT_EQ(
      residual_location_words(shares, {0.0, 0.5, 1.0}),
      "the largest share of the root force left is between keyframes 2 and 3 (0.50-1.00 s): 57 % "
      "of its integral");
  check.span_integral = {0.0, 0.0, 0.0};
  EXPECT_EQ(residual_shares(check, {0.0, 0.5, 1.0}), (std::vector<double>{0.0, 0.0}));
}

TEST(ResidualShares, AreEachKeyframeIntervalsShareOfTheWrenchIntegralOnAFineGrid) {
  // Independent path: the trapezoidal rule on 8001 points, between the
  // keyframe times, against the dense check's span integrals summed per interval.
  const BodyModel model = test::bundled_model();
  for (const Motion& motion : {test::pike_motion(model), test::tuck_motion(model)}) {
    SCOPED_TRACE(motion.name);
    InterpolationOptions options;
    options.subdivisions.assign(motion.keyframes.size() - 1, 2);
    const Trajectory<double> trajectory = interpolate_keyframes(motion, model, options);
    std::vector<double> keyframe_times;
    for (const Keyframe& k : motion.keyframes)
      keyframe_times.push_back(k.time);
    const std::vector<double> shares =
        residual_shares(dense_check(model, trajectory, 200), keyframe_times);
    const std::vector<SampleRecord> fine =
        evaluate_trajectory(model, trajectory, uniform_times(trajectory.duration(), 8001));
    std::vector<double> by_hand(keyframe_times.size() - 1, 0.0);
    double total = 0.0;
    for (std::size_t k = 0; k + 1 < fine.size(); ++k) {
      const double middle = 0.5 * (fine[k].time + fine[k + 1].time);
      const std::size_t i = static_cast<std::size_t>(
          std::upper_bound(keyframe_times.begin(), keyframe_times.end(), middle) -
          keyframe_times.begin() - 1);
      const double piece =
          0.5 * (fine[k + 1].time - fine[k].time) *
          (fine[k].root_wrench.squaredNorm() + fine[k + 1].root_wrench.squaredNorm());
      by_hand[std::min(i, by_hand.size() - 1)] += piece;
      total += piece;
    }
    ASSERT_EQ(shares.size(), by_hand.size());
    for (std::size_t i = 0; i < shares.size(); ++i)
      EXPECT_NEAR(shares[i], by_hand[i] / total, 1e-4) << "interval " << i;
  }
}

}  // namespace
}  // namespace saltus
