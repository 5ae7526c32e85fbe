// docs/testing.md: keyframes sampled from a simulated free flight, with their times disturbed, must
// optimise back to a near-zero residual, and timing optimisation must move the times back
// towards the truth.

#include <gtest/gtest.h>

#include "saltus/optim/optimize.h"
#include "support/ground_truth.h"

namespace saltus {
namespace {

class GroundTruth : public ::testing::TestWithParam<int> {};

TEST_P(GroundTruth, DisturbedTimesOptimiseBackToFreeFlight) {
  // GetParam() keyframes, interior times disturbed by up to ±0.08 s (the bound; 30-40 %
  // of the keyframe spacing).
  const test::GroundTruth g = test::make_ground_truth(GetParam(), 0.08);
  // Knots at the keyframes only (K = 1) cannot represent this flight: even from the true times
  // the best K = 1 motion needs other times. With K = 3 the truth is (nearly) in the space.
  OptimizeOptions options;
  options.nlp.knots_per_interval = 3;
  options.nlp.samples = 121;
  options.solver.max_iterations = 100;
  const OptimizationResult r = optimize_motion(g.motion, g.model, options);
  const double before = r.before.metrics.avg_root_force;
  const double after = r.after.metrics.avg_root_force;
  std::printf(
      "ground truth, %d keyframes: %s after %d iterations, %.2f s; avg root force %.3f -> %.3f N; "
      "time error %.3f -> %.3f s\n",
      GetParam(), r.solve.status.c_str(), r.solve.iterations, r.solve.seconds, before, after,
      test::time_error(r.before.keyframe_times, g.true_times),
      test::time_error(r.after.keyframe_times, g.true_times));
  EXPECT_TRUE(r.solve.solved) << r.solve.status;
  EXPECT_GT(before, 5.0);  // the disturbed timing really breaks the physics
  EXPECT_LT(after, before / 100);
  EXPECT_LT(after, 0.5);  // the target with --knots-per-interval 3
  EXPECT_LT(test::time_error(r.after.keyframe_times, g.true_times),
            test::time_error(r.before.keyframe_times, g.true_times));
}

// The tuck turns ~1.4 somersaults: fewer than 9 keyframes would put consecutive root poses more
// than 180° apart, which no keyframe interpolation can tell from the short way round.
INSTANTIATE_TEST_SUITE_P(Keyframes, GroundTruth, ::testing::Values(9, 11));

}  // namespace
}  // namespace saltus
