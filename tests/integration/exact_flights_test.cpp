// The test of truth (docs/testing.md): flights made by the free-flight simulator, whose true root
// wrench is zero, keyframed at times a user would type. Nobody tuned Saltus for them: default
// `optimize_motion` must bring each one's true residual (the dense check) near zero, the files it
// writes must agree with the motion (simulating the optimised motion lands where it lands), the
// keyframe times it cannot pin down it must say so, and times typed wrong must come back.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "saltus/evaluation/joint_loads.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/evaluation/yeadon_angles.h"
#include "saltus/optim/optimize.h"
#include "saltus/studies/exact_flights.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

class ExactFlightFamily : public ::testing::TestWithParam<int> {};

TEST_P(ExactFlightFamily, DefaultOptimisationFindsTheFlightNearZero) {
  const BodyModel model = test::bundled_model();
  // Each case runs three seeds, so the family in CI is 3 × the instantiated count.
  int near_zero = 0, interior = 0, beyond_spread = 0;
  for (int j = 0; j < 3; ++j) {
    const std::uint64_t seed = 3 * static_cast<std::uint64_t>(GetParam()) + j;
    const ExactFlight f = make_exact_flight(model, seed);
    SCOPED_TRACE(f.description());
    const OptimizationResult r = optimize_motion(f.motion, model, {});
    const double force = r.after.metrics.avg_root_force;
    std::printf("%s: %s, %d iterations, %.2f -> %.3f N\n", f.description().c_str(),
                r.solve.status.c_str(), r.solve.iterations, r.before.metrics.avg_root_force, force);
    EXPECT_TRUE(r.solve.solved) << r.solve.status;
    if (!r.solve.solved) continue;
    near_zero += force <= 0.5;
    // The optimiser's own integral is the motion's true residual.
    EXPECT_TRUE(optimizer_agrees_with_check(r))
        << std::sqrt(r.optimizer_objective_after / 6) << " N vs the check's " << force;
    EXPECT_LE(r.after.keyframe_errors.max_quaternion_error, f.motion.tolerances.quaternion + 1e-4);
    EXPECT_LE(r.after.keyframe_errors.max_translation_error_m,
              f.motion.tolerances.translation_m + 1e-6);
    // The optimised motion file is consistent: its own take-off state makes `simulate` end
    // within 2° of where the optimised motion ends.
    if (force <= 0.5) {
      const SimulationResult s = simulate_motion(r.optimized_motion, model);
      EXPECT_LE(s.landing_vs_motion_deg, 2.0);
    }
    // A time the optimiser moved further from the truth than its reported spread was given a
    // precision it did not have; the spread is a local estimate, so some miss it (another
    // minimum of the same depth), most must not.
    for (std::size_t i = 1; i + 1 < f.motion.keyframes.size(); ++i) {
      ++interior;
      beyond_spread += std::abs(r.after.keyframe_times[i] - f.motion.keyframes[i].time) >
                       r.keyframe_time_spreads[i] + 0.01;
    }
  }
  EXPECT_LE(beyond_spread, interior / 3) << beyond_spread << " of " << interior;
  // The issue's bar is 95 % of the family at or below 0.5 N; per group of three, all of them.
  EXPECT_EQ(near_zero, 3);
}

// 8 groups of 3 = 24 flights (seeds 3-26) in CI; the benchmark sweeps more.
INSTANTIATE_TEST_SUITE_P(Seeds, ExactFlightFamily, ::testing::Range(1, 9));

TEST(ExactFlightFamily, DisturbedKeyframeTimesComeBack) {
  // The issue's bar: with the interior times moved by up to ±0.1 s (first and last fixed),
  // default optimisation cuts the total timing error by ≥ 70 % on average. Seeds 201-212: the
  // keyframe prior's weight was chosen on seeds 1-12, so these were never looked at.
  const BodyModel model = test::bundled_model();
  double cut_sum = 0.0;
  int flights = 0;
  for (std::uint64_t seed = 201; seed <= 212; ++seed) {
    const ExactFlight f = make_exact_flight(model, seed);
    SCOPED_TRACE(f.description());
    const Motion typed = disturb_interior_times(f.motion, 0.1, seed);
    const OptimizationResult r = optimize_motion(typed, model, {});
    EXPECT_TRUE(r.solve.solved) << r.solve.status;
    EXPECT_LE(r.after.metrics.avg_root_force, 0.5);
    double before = 0.0, after = 0.0;
    for (std::size_t i = 1; i + 1 < f.motion.keyframes.size(); ++i) {
      before += std::abs(typed.keyframes[i].time - f.motion.keyframes[i].time);
      after += std::abs(r.after.keyframe_times[i] - f.motion.keyframes[i].time);
    }
    std::printf("%s: timing error %.3f -> %.3f s, %.3f N\n", f.description().c_str(), before, after,
                r.after.metrics.avg_root_force);
    if (before <= 0.0) continue;
    cut_sum += 1.0 - after / before;
    ++flights;
  }
  ASSERT_GT(flights, 8);
  EXPECT_GE(cut_sum / flights, 0.7) << "mean cut of the total timing error";
}

/// Default optimisation of an exact flight, held to the bars every flight of these tests meets:
/// solved, at most 0.5 N, every joint within 1.5x of its input's peak. The result, for each
/// test's own checks.
OptimizationResult optimised_to_issue_24s_bars(const ExactFlight& f, const BodyModel& model) {
  const OptimizationResult r = optimize_motion(f.motion, model, {});
  EXPECT_TRUE(r.solve.solved) << r.solve.status;
  EXPECT_LE(r.after.metrics.avg_root_force, 0.5);
  const JointLoadRise rise = largest_joint_load_rise(model, r.before.check, r.after.check);
  EXPECT_LE(rise.ratio(), 1.5) << joint_load_rise_words(rise, body_weight_N(model));
  return r;
}

// The polish bounds the joints' loads at nodes of each knot span; on these three flights the
// loads rose between the first span's nodes (1.65x, 1.88x, 2.89x at 0.01-0.03 s after take-off)
// or, with nodes added on the first span alone, at the landing; the end spans now have six each.
TEST(ExactFlightFamily, JointLoadsStayWithinTheBarAtTheEndsOfTheFlight) {
  const BodyModel model = test::bundled_model();
  for (std::uint64_t seed : {23, 58, 71}) {
    const ExactFlight f = make_exact_flight(model, seed);
    SCOPED_TRACE(f.description());
    optimised_to_issue_24s_bars(f, model);
  }
}

// Two ways the polish's bounded try fell short of the joint bar, each on the flight that showed
// it. Seed 72 (a pike without a somersault, whose times the levels moved by up to 0.19 s at one
// or two knot spans an interval) had no bounded try hold 0.5 N (0.78 N) and kept the unbounded
// one with its right knee at 3.46x: the best bounded try is solved again on finer knots. Seed
// 38's kept bounded try had its left elbow at 1.51x between two bounded nodes: it is solved
// again with that bound lowered by the overshoot.
TEST(ExactFlightFamily, ABoundedPolishThatFallsShortIsSolvedAgain) {
  const BodyModel model = test::bundled_model();
  for (std::uint64_t seed : {72, 38}) {
    const ExactFlight f = make_exact_flight(model, seed);
    SCOPED_TRACE(f.description());
    const OptimizationResult r = optimised_to_issue_24s_bars(f, model);
    ASSERT_TRUE(r.joint_load_polish);
    const JointLoadPolish& polish = *r.joint_load_polish;
    EXPECT_TRUE(polish.kept);
    EXPECT_GT(polish.joint_bound, 0.0) << "a bounded try is kept";
    EXPECT_EQ(polish.knots_refined, seed == 72);
    EXPECT_EQ(polish.bounds_tightened, seed == 38);
    // The refined knots are the returned motion's, and its residual is what they give.
    EXPECT_EQ(r.after.trajectory.rotations.front().knots().size(),
              std::accumulate(r.subdivisions.begin(), r.subdivisions.end(), std::size_t{7}));
    EXPECT_TRUE(optimizer_agrees_with_check(r));
  }
}

// Issue 24's truth on twisting skills (the benchmark sweeps 40 of the twisting family), held in
// CI on three flights: seed 4 twists from the take-off, seed 8 from one arm, and seed 32's 23
// keyframes, 0.04-0.08 s apart, left the first level (one knot span each) alternating between two
// points until Ipopt's iteration limit, where the resolution used to stop: 3.96 N, its free
// flight landing 11° from it. It must refine past a level that did not converge.
TEST(TwistingExactFlights, EachIsFoundNearZeroAtItsOwnTimesWithHumanJoints) {
  const BodyModel model = test::bundled_model();
  for (std::uint64_t seed : {4, 8, 32}) {
    const ExactFlight f = make_twisting_flight(model, seed);
    SCOPED_TRACE(f.description());
    const OptimizationResult r = optimised_to_issue_24s_bars(f, model);
    std::printf("%s: %s, %zu levels (first: %s), %.2f -> %.3f N\n", f.description().c_str(),
                r.solve.status.c_str(), r.levels.size(), r.levels.front().status.c_str(),
                r.before.metrics.avg_root_force, r.after.metrics.avg_root_force);
    EXPECT_TRUE(optimizer_agrees_with_check(r));
    EXPECT_LE(simulate_motion(r.optimized_motion, model).landing_vs_motion_deg, 3.0);
    for (std::size_t i = 1; i + 1 < f.motion.keyframes.size(); ++i)
      EXPECT_LE(std::abs(r.after.keyframe_times[i] - f.motion.keyframes[i].time),
                r.keyframe_time_spreads[i] + 0.01)
          << "keyframe " << i;
    if (seed == 32) {
      EXPECT_GE(r.levels.size(), 2u);
    }
  }
}

// Issue 45's held-out kind: 2 and 3 twists on 7 keyframes, 100-270 deg of twist between
// neighbours, where the short way between two keyframes twists the other way. The optimiser
// starts there from the free flight's way round (evaluation/keyframe_spacing.h) and finds the
// flight: issue 24's bars, the landing of a free flight run here within 3 deg, and as many twists
// as the simulator flew (Yeadon's angles of the optimised spline; the interpolation had lost one
// and three). Without the guided start: 0.69 and 0.52 N after 80 s each.
TEST(HardTwistingFlights, ASparselyKeyedTwistIsFoundTheFlightsWayRound) {
  const BodyModel model = test::bundled_model();
  for (std::uint64_t seed : {12, 14}) {
    const ExactFlight f = make_hard_twisting_flight(model, seed);
    SCOPED_TRACE(f.description());
    const OptimizationResult r = optimised_to_issue_24s_bars(f, model);
    EXPECT_FALSE(r.twist_guided_intervals.empty());
    EXPECT_LE(simulate_motion(r.optimized_motion, model).landing_vs_motion_deg, 3.0);
    EXPECT_NEAR(yeadon_summary(r.after.trajectory).twists, f.flown_twists, 0.25);
    EXPECT_GT(std::abs(yeadon_summary(r.before.trajectory).twists - f.flown_twists), 0.75)
        << "the interpolation lost a twist";
  }
}

}  // namespace
}  // namespace saltus
