// optimize_motion (optim/optimize.h) in a few iterations: the problem it builds has the size the
// layout predicts, "before" is the interpolation, and the optimised motion it returns reloads to
// exactly its "after". The largest control turn against control_turn over the controls. (Whole
// optimisations: tests/integration/optimizer_control_test.cpp, optimize_examples_test.cpp.)

#include "saltus/optim/optimize.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "support/test_motions.h"

namespace saltus {
namespace {

/// max over segments >= first and consecutive controls of control_turn.
double turn_by_hand(const Trajectory<double>& t, int first) {
  double largest = 0.0;
  for (int s = first; s < t.segment_count(); ++s) {
    const auto& c = t.rotations[s].control();
    for (std::size_t j = 1; j < c.size(); ++j)
      largest = std::max(largest, control_turn(c[j - 1], c[j]));
  }
  return largest;
}

TEST(LargestControlTurn, IsTheLargestTurnBetweenConsecutiveControlsFromTheGivenSegmentOn) {
  const BodyModel model = test::bundled_model();
  const Trajectory<double> tuck = interpolate_keyframes(test::tuck_motion(model), model);
  const double all = largest_control_turn(tuck), joints = largest_control_turn(tuck, 1);
  EXPECT_NEAR(all, turn_by_hand(tuck, 0), 1e-12);
  EXPECT_NEAR(joints, turn_by_hand(tuck, 1), 1e-12);
  // The somersault turns the root more between two controls than any joint turns.
  EXPECT_GT(all, joints);
}

OptimizeOptions few_iterations() {
  OptimizeOptions options;
  options.nlp.samples = 31;
  options.solver.max_iterations = 3;
  return options;
}

TEST(OptimizeMotion, BuildsTheLayoutsProblemAndReloadsToItsAfter) {
  // With the paper's uniform K and with the automatic resolution (its first level: three
  // iterations do not solve it, so it is not refined).
  const BodyModel model = test::bundled_model();
  const Motion motion = test::tuck_motion(model);
  const int intervals = static_cast<int>(motion.keyframes.size()) - 1;
  for (bool automatic : {false, true}) {
    SCOPED_TRACE(automatic ? "automatic resolution" : "uniform K");
    OptimizeOptions options = few_iterations();
    options.automatic_resolution = automatic;
    const OptimizationResult r = optimize_motion(motion, model, options);
    ASSERT_EQ(r.solve.iterations, 3);
    ASSERT_EQ(static_cast<int>(r.subdivisions.size()), intervals);
    if (automatic) {
      ASSERT_EQ(r.levels.size(), 1u);
      EXPECT_EQ(r.levels[0].subdivisions, r.subdivisions);
      EXPECT_EQ(r.knots_per_interval,
                *std::max_element(r.subdivisions.begin(), r.subdivisions.end()));
    } else {
      EXPECT_EQ(r.subdivisions, std::vector<int>(intervals, r.knots_per_interval));
    }
    // Variables: 3 per control point of the root curve and of each joint's curve, plus the
    // interior keyframe times (docs/method.md).
    const int controls = std::accumulate(r.subdivisions.begin(), r.subdivisions.end(), 0) + 3;
    EXPECT_EQ(r.variables, controls * 3 * (model.size() + 1) + 3);
    // "before" is the interpolation: on the same knots with a uniform K, on the paper's knots at
    // the keyframes with the automatic resolution.
    EvaluateOptions grid;
    grid.samples = 31;
    grid.interpolation.subdivisions = automatic ? std::vector<int>(intervals, 1) : r.subdivisions;
    const MotionEvaluation before = evaluate_motion(motion, model, grid);
    EXPECT_EQ(r.before.metrics.objective, before.metrics.objective);
    // The optimised motion carries its spline and times: loading it gives "after" exactly.
    ASSERT_TRUE(r.optimized_motion.spline);
    const MotionEvaluation reloaded = evaluate_motion(r.optimized_motion, model, grid);
    ASSERT_EQ(reloaded.samples.size(), r.after.samples.size());
    for (std::size_t s = 0; s < reloaded.samples.size(); ++s)
      EXPECT_EQ(reloaded.samples[s].root_wrench, r.after.samples[s].root_wrench) << s;
    EXPECT_EQ(reloaded.keyframe_times, r.after.keyframe_times);
    EXPECT_EQ(r.after.metrics.objective, reloaded.metrics.objective);
    // Its keyframe times are where its spline's keyframe knots sit (knot 3 + the spans before
    // it), moved by the timing optimisation.
    const std::vector<double>& knots = r.optimized_motion.spline->knots;
    ASSERT_EQ(static_cast<int>(knots.size()), controls + 4);
    bool moved = false;
    int knot = 3;
    for (int i = 0; i <= intervals; ++i) {
      EXPECT_EQ(r.optimized_motion.keyframes[i].time, knots[knot]) << i;
      moved |= r.optimized_motion.keyframes[i].time != motion.keyframes[i].time;
      if (i < intervals) knot += r.subdivisions[i];
    }
    EXPECT_TRUE(moved);
    EXPECT_NE(r.after.metrics.objective, r.before.metrics.objective);
  }
}

TEST(OptimizeMotion, ReportsItsStagesAndACancelAfterASolvedLevelIsCalledCancelled) {
  // The progress names each solve's stage, levels first; a cancel once the first level has
  // solved stops the run, which is then "cancelled", not solved: it did not finish the policy.
  const BodyModel model = test::bundled_model();
  const Motion motion = test::tuck_motion(model);
  OptimizeOptions options;
  options.nlp.samples = 31;
  std::vector<ProgressInfo> seen;
  std::atomic<bool> cancel{false};
  const OptimizationResult r = optimize_motion(
      motion, model, options,
      [&](const ProgressInfo& p) {
        seen.push_back(p);
        cancel = cancel || p.stage != seen.front().stage;
      },
      &cancel);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front().stage.kind, SolveStage::Kind::kLevel);
  EXPECT_EQ(seen.front().stage.step, 1);
  EXPECT_EQ(seen.front().stage.max_steps, AutomaticResolution{}.max_refinements + 1);
  EXPECT_FALSE(seen.front().stage.landing_pass);
  ASSERT_GE(r.levels.size(), 1u);
  EXPECT_EQ(r.levels.front().status, "solved");
  ASSERT_NE(seen.back().stage, seen.front().stage);  // it went on to another stage
  EXPECT_EQ(r.solve.status, "cancelled");
  EXPECT_FALSE(r.solve.solved);
  // The run's count goes on across solves; each solve counts its own from 1.
  for (std::size_t i = 1; i < seen.size(); ++i) {
    EXPECT_GE(seen[i].iteration, seen[i - 1].iteration) << i;
    EXPECT_LE(seen[i].stage_iteration, seen[i].iteration) << i;
  }
  EXPECT_EQ(seen.back().stage_iteration, 0);  // its first report stopped it
}

TEST(OptimizeMotion, RejectsKnotsPerIntervalBelowOne) {
  const BodyModel model = test::bundled_model();
  OptimizeOptions options = few_iterations();
  options.nlp.knots_per_interval = 0;
  EXPECT_THROW(optimize_motion(test::tuck_motion(model), model, options), std::invalid_argument);
}

TEST(OptimizeMotion, RefusesMoreKeyframesThanItsCostAllows) {
  const BodyModel model = test::bundled_model();
  Motion motion = test::tuck_motion(model);
  const Keyframe first = motion.keyframes.front();
  const double duration = motion.flight_time();
  motion.keyframes.clear();
  for (int i = 0; i <= kMaxOptimizedKeyframes; ++i) {
    Keyframe k = first;
    k.time = duration * i / kMaxOptimizedKeyframes;
    motion.keyframes.push_back(k);
  }
  try {
    optimize_motion(motion, model, {});
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("at most 64"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace saltus
