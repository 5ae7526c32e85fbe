// evaluate_motion (evaluation/evaluate.h): what it samples and on which trajectory — the keyframe
// interpolation, or the spline stored with an optimised motion, which must win over the
// interpolation options — and the options it refuses.

#include "saltus/evaluation/evaluate.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(EvaluateMotion, RejectsOptionsOutOfRange) {
  EvaluateOptions options;
  options.samples = 1;
  EXPECT_THROW(check_evaluate_options(options), std::invalid_argument);
  options.samples = 2;
  options.interpolation.knots_per_interval = 0;
  EXPECT_THROW(check_evaluate_options(options), std::invalid_argument);
  const BodyModel model = test::bundled_model();
  EXPECT_THROW(evaluate_motion(test::pike_motion(model), model, options), std::invalid_argument);
}

TEST(EvaluateMotion, SamplesTheInterpolationUniformlyAndSummarisesTheSamples) {
  const BodyModel model = test::bundled_model();
  const Motion motion = test::pike_motion(model);
  EvaluateOptions options;
  options.samples = 41;
  options.interpolation.knots_per_interval = 2;
  const MotionEvaluation e = evaluate_motion(motion, model, options);
  EXPECT_EQ(e.samples.size(), 41u);
  EXPECT_EQ(e.samples.back().time, motion.flight_time());
  EXPECT_EQ(e.trajectory.knots, interpolate_keyframes(motion, model, options.interpolation).knots);
  // The figures are the dense check's on the evaluated trajectory (force_metrics_test checks
  // the dense check itself), not the coarser samples'.
  const DenseCheck check = dense_check(model, e.trajectory, 41);
  EXPECT_EQ(e.check.points, check.points);
  EXPECT_EQ(e.metrics.objective, check.metrics.objective);
  EXPECT_EQ(e.metrics.max_force_N, check.metrics.max_force_N);
  EXPECT_EQ(e.check.metrics.objective, e.metrics.objective);
  EXPECT_NEAR(e.metrics.objective, force_metrics(e.samples).objective, 0.05 * e.metrics.objective);
  ASSERT_EQ(e.keyframe_times.size(), motion.keyframes.size());
  for (std::size_t i = 0; i < motion.keyframes.size(); ++i)
    EXPECT_EQ(e.keyframe_times[i], motion.keyframes[i].time);
  EXPECT_EQ(e.root_targets, keyframe_root_targets(motion, model));
  // The interpolation passes through the keyframes (paper §5.2).
  EXPECT_LT(e.keyframe_errors.max_rotation_error_deg, 1e-4);
}

TEST(EvaluateMotion, UsesTheStoredSplineOfAnOptimisedMotion) {
  const BodyModel model = test::bundled_model();
  Motion motion = test::pike_motion(model);
  InterpolationOptions fine;
  fine.knots_per_interval = 3;
  const Trajectory<double> stored = interpolate_keyframes(motion, model, fine);
  motion.spline = to_stored_spline(stored);
  // Evaluated with the default K = 1, the motion still runs on its stored K = 3 curve.
  const MotionEvaluation e = evaluate_motion(motion, model, {});
  EXPECT_EQ(e.trajectory.knots, stored.knots);
  for (double t : {0.0, 0.7, 1.3, 2.04}) {
    EXPECT_EQ(e.trajectory.root_translation.evaluate(t).position,
              stored.root_translation.evaluate(t).position);
    EXPECT_EQ(e.trajectory.rotations[4].evaluate(t).q.coeffs(),
              stored.rotations[4].evaluate(t).q.coeffs());
  }
}

}  // namespace
}  // namespace saltus
