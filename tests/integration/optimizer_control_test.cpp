// The solver's controls: a cancel request stops Ipopt cleanly at the next iteration with a
// complete result, progress is reported once per iteration, and the same input gives the same
// output bit for bit.

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>

#include "saltus/optim/optimize.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

OptimizeOptions quick_options() {
  OptimizeOptions o;
  o.nlp.samples = 41;
  o.solver.max_iterations = 30;
  return o;
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
  // The result is still whole: the last iterate, evaluated on the full grid.
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

}  // namespace
}  // namespace saltus
