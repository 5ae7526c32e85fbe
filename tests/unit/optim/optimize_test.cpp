// optimize_motion (optim/optimize.h) in a few iterations: the problem it builds has the size the
// layout predicts, "before" is the interpolation, and the optimised motion it returns reloads to
// exactly its "after". The largest control turn against control_turn over the controls. (Whole
// optimisations: tests/integration/optimizer_control_test.cpp, optimize_examples_test.cpp.)

#include "saltus/optim/optimize.h"

#include <gtest/gtest.h>

#include <stdexcept>

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
  const BodyModel model = test::bundled_model();
  const Motion motion = test::tuck_motion(model);
  const OptimizationResult r = optimize_motion(motion, model, few_iterations());
  ASSERT_EQ(r.solve.iterations, 3);
  // Variables: 3 per control point of the root curve and of each joint's curve, plus the
  // interior keyframe times (DESIGN §5).
  const int k = r.knots_per_interval;
  const int controls = (static_cast<int>(motion.keyframes.size()) - 1) * k + 3;
  EXPECT_EQ(r.variables, controls * 3 * (model.size() + 1) + 3);
  // "before" is the interpolation on the same grid.
  EvaluateOptions grid;
  grid.samples = 31;
  grid.interpolation.knots_per_interval = k;
  const MotionEvaluation before = evaluate_motion(motion, model, grid);
  EXPECT_EQ(r.before.metrics.objective, before.metrics.objective);
  // The optimised motion carries its spline and times: loading it gives "after" exactly.
  ASSERT_TRUE(r.optimized_motion.spline);
  const MotionEvaluation reloaded = evaluate_motion(r.optimized_motion, model, grid);
  ASSERT_EQ(reloaded.samples.size(), r.after.samples.size());
  for (std::size_t s = 0; s < reloaded.samples.size(); ++s)
    EXPECT_EQ(reloaded.samples[s].root_wrench, r.after.samples[s].root_wrench) << s;
  EXPECT_EQ(reloaded.keyframe_times, r.after.keyframe_times);
  // Its keyframe times are where its spline's keyframe knots sit (knot 3 + i·K), moved by the
  // timing optimisation.
  bool moved = false;
  for (std::size_t i = 0; i < motion.keyframes.size(); ++i) {
    EXPECT_EQ(r.optimized_motion.keyframes[i].time, r.optimized_motion.spline->knots[3 + i * k]);
    moved |= r.optimized_motion.keyframes[i].time != motion.keyframes[i].time;
  }
  EXPECT_TRUE(moved);
  EXPECT_NE(r.after.metrics.objective, r.before.metrics.objective);
}

TEST(OptimizeMotion, RejectsKnotsPerIntervalBelowOne) {
  const BodyModel model = test::bundled_model();
  OptimizeOptions options = few_iterations();
  options.nlp.knots_per_interval = 0;
  EXPECT_THROW(optimize_motion(test::tuck_motion(model), model, options), std::invalid_argument);
}

}  // namespace
}  // namespace saltus
