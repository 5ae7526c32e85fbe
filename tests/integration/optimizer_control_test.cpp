// The solver's controls: a cancel request stops Ipopt cleanly at the next iteration with a
// complete result, progress is reported once per iteration, and the same input gives the same
// output bit for bit.

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>

#include "saltus/formats/motion_file.h"
#include "saltus/optim/optimize.h"
#include "saltus/studies/convergence_study.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

OptimizeOptions quick_options() {
  OptimizeOptions o;
  o.nlp.samples = 41;
  o.solver.max_iterations = 30;
  return o;
}

TEST(OptimizerControl, ProgressCountsOnAcrossTheResolutionLevels) {
  // The automatic resolution solves one problem per level; the progress a caller sees (the
  // app's iteration counter, the CLI's lines) counts on across them instead of starting again.
  const MotionFile file = load_motion_file(test::m1_path());
  std::vector<int> seen;
  std::vector<double> clock;
  const OptimizationResult r =
      optimize_motion(file.motion, file.model, {}, [&](const ProgressInfo& info) {
        seen.push_back(info.iteration);
        clock.push_back(info.elapsed_seconds);
      });
  ASSERT_GE(r.levels.size(), 2u) << "M1 is refined at least once";
  ASSERT_FALSE(seen.empty());
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_TRUE(std::is_sorted(clock.begin(), clock.end()));
  EXPECT_EQ(seen.back(), r.solve.iterations);
}

TEST(OptimizerControl, CancelStopsCleanlyWithACompleteResult) {
  const MotionFile file = load_motion_file(test::m1_path());
  std::atomic<bool> cancel{false};
  std::vector<int> iterations_seen;
  const ProgressCallback progress = [&](const ProgressInfo& info) {
    iterations_seen.push_back(info.iteration);
    EXPECT_GE(info.elapsed_seconds, 0.0);
    if (info.iteration == 3) cancel = true;
  };
  const OptimizationResult r =
      optimize_motion(file.motion, file.model, quick_options(), progress, &cancel);
  EXPECT_EQ(r.solve.status, "cancelled");
  EXPECT_FALSE(r.solve.solved);
  EXPECT_EQ(r.solve.iterations, 3);
  ASSERT_EQ(iterations_seen.size(), 4u);  // iterations 0..3, once each
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(iterations_seen[i], i);
  // The result is still whole: the last iterate (better than any earlier one that met the
  // keyframes), evaluated on the full grid.
  EXPECT_EQ(r.after.samples.size(), 41u);
  EXPECT_EQ(r.after.keyframe_times.size(), file.motion.keyframes.size());
  EXPECT_LT(r.after.metrics.avg_root_force, r.before.metrics.avg_root_force);
}

TEST(OptimizerControl, SameInputSameOutput) {
  const MotionFile file = load_motion_file(test::m1_path());
  OptimizeOptions options = quick_options();
  options.solver.max_iterations = 8;
  const OptimizationResult a = optimize_motion(file.motion, file.model, options);
  const OptimizationResult b = optimize_motion(file.motion, file.model, options);
  EXPECT_EQ(a.solve.iterations, b.solve.iterations);
  EXPECT_EQ(a.solve.x, b.solve.x);  // bit for bit
  EXPECT_EQ(a.after.metrics.objective, b.after.metrics.objective);
  EXPECT_EQ(a.after.keyframe_times, b.after.keyframe_times);
}

TEST(OptimizerControl, AnIpoptOptionsFileInTheWorkingFolderChangesNothing) {
  // Ipopt reads ./ipopt.opt unless told not to; a stray one must not change our solver.
  const MotionFile file = load_motion_file(test::m1_path());
  OptimizeOptions options = quick_options();
  options.solver.max_iterations = 8;
  const OptimizationResult plain = optimize_motion(file.motion, file.model, options);
  test::TempDir dir;
  test::write_text(dir / "ipopt.opt", "max_iter 1\nprint_level 12\n");
  const std::filesystem::path previous = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());
  const OptimizationResult with_file = optimize_motion(file.motion, file.model, options);
  std::filesystem::current_path(previous);
  EXPECT_EQ(with_file.solve.iterations, plain.solve.iterations);
  EXPECT_EQ(with_file.solve.x, plain.solve.x);
}

TEST(OptimizerControl, RefinesTheKnotsWhenTheInterpolationMissesTheKeyframes) {
  // M3 (tucked double) with its interior keyframe times 0.1 s off: two keyframes 2.3 rad apart
  // end up 0.08 s apart, next to 2.4 rad in 0.28 s. With knots at the keyframes only, the
  // quaternion spline would need more than 180° between control points and cannot pass through
  // them; one refinement (K = 2) can.
  const MotionFile file = load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                           "/motions/M3-tucked-double-back.motion.json");
  const Motion disturbed = disturb_keyframe_times(file.motion, 0.1, 1);
  OptimizeOptions options;
  options.automatic_resolution = false;  // the paper's knots, refined only by this rule
  options.solver.max_iterations = 0;     // only the start matters here
  options.refine_when_keyframes_missed = false;
  const OptimizationResult as_asked = optimize_motion(disturbed, file.model, options);
  EXPECT_EQ(as_asked.knots_per_interval, 1);
  EXPECT_GT(as_asked.before.keyframe_errors.max_quaternion_error, 0.05);

  options.refine_when_keyframes_missed = true;
  const OptimizationResult refined = optimize_motion(disturbed, file.model, options);
  EXPECT_EQ(refined.knots_per_interval, 2);
  EXPECT_LE(refined.before.keyframe_errors.max_quaternion_error, 0.05);
  EXPECT_LE(refined.before.keyframe_errors.max_translation_error_m, 0.25);
  EXPECT_GT(refined.variables, as_asked.variables);  // more control points

  // The undisturbed motion is met on knots at the keyframes: no refinement.
  const OptimizationResult plain = optimize_motion(file.motion, file.model, options);
  EXPECT_EQ(plain.knots_per_interval, 1);
}

TEST(OptimizerControl, KeepsEveryJointWithinHalfATurnBetweenControlPoints) {
  // At the paper's resolution the root force hardly cares about light limbs, and without the
  // joint-turn penalty the optimum spun them: on M3 seven segments turned 4.8-6.2 rad between
  // two control points (the spline's log has its branch point at 2π).
  const MotionFile file = load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                           "/motions/M3-tucked-double-back.motion.json");
  OptimizeOptions paper;
  paper.automatic_resolution = false;
  const OptimizationResult result = optimize_motion(file.motion, file.model, paper);
  ASSERT_TRUE(result.solve.solved) << result.solve.status;
  ASSERT_EQ(result.knots_per_interval, 1);
  // Root (segment 0) excluded: the whole body somersaults.
  for (std::size_t k = 1; k < result.after.trajectory.rotations.size(); ++k) {
    const double limit =
        std::max(M_PI, result.before.trajectory.rotations[k].largest_control_turn());
    // A soft limit: 1000 N²/rad² lets a turn pass it by a few hundredths of a radian.
    EXPECT_LE(result.after.trajectory.rotations[k].largest_control_turn(), limit + 0.1)
        << "segment " << file.model.segments[k].name;
  }
}

TEST(OptimizerControl, SolvesTheStudyCaseThatUsedToSpinAForearmOntoTheBranchPoint) {
  // M3 with the right thigh 10 % light and keyframe times 0.05 s off: the optimiser drove the
  // left forearm to exactly 2π between two control points, the dual infeasibility reached 1e17
  // and the run ended at 300 iterations, not solved.
  const MotionFile file = load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                           "/motions/M3-tucked-double-back.motion.json");
  const Motion disturbed = disturb_keyframe_times(file.motion, 0.05, 1);
  const BodyModel light_thigh = scale_segment_mass(file.model, "thigh_r", 0.9);
  const OptimizationResult result = optimize_motion(disturbed, light_thigh, {});
  EXPECT_TRUE(result.solve.solved) << result.solve.status;
  EXPECT_LT(result.solve.iterations, 150);
  EXPECT_LE(result.after.keyframe_errors.max_quaternion_error, 0.05);
}

TEST(OptimizerControl, RefinesTheKnotsWhenTheInterpolationTurnsNearlyAFullTurn) {
  // M5 with its interior keyframe times 0.05 s off puts two keyframes 0.05 s apart; the fit on
  // knots at the keyframes meets every keyframe but turns the arms by 2π between two control
  // points, where the log map's derivative is unbounded (the root force's gradient there was
  // 1e17 and Ipopt wandered for 300 iterations). One refinement gives an ordinary curve.
  const MotionFile file =
      load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                       "/motions/M5-front-somersault-one-and-a-half-twists.motion.json");
  const Motion disturbed = disturb_keyframe_times(file.motion, 0.05, 1);
  OptimizeOptions options;
  options.automatic_resolution = false;
  options.solver.max_iterations = 0;
  options.refine_when_keyframes_missed = false;
  const OptimizationResult as_asked = optimize_motion(disturbed, file.model, options);
  EXPECT_LE(as_asked.before.keyframe_errors.max_quaternion_error, 0.05);  // not a missed keyframe
  EXPECT_GT(largest_control_turn(as_asked.before.trajectory), kMaxControlTurn);

  options.refine_when_keyframes_missed = true;
  const OptimizationResult refined = optimize_motion(disturbed, file.model, options);
  EXPECT_EQ(refined.knots_per_interval, 2);
  EXPECT_LE(largest_control_turn(refined.before.trajectory), kMaxControlTurn);
  EXPECT_LE(refined.before.keyframe_errors.max_quaternion_error, 0.05);
}

}  // namespace
}  // namespace saltus
