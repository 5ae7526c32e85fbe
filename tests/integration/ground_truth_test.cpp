// DESIGN §7: keyframes sampled from a simulated free flight, with their times disturbed, must
// optimise back to a near-zero residual, and timing optimisation must move the times back
// towards the truth.

#include <gtest/gtest.h>

#include "saltus/dynamics/free_flight.h"
#include "saltus/motion/interpolate.h"
#include "saltus/optim/optimize.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

struct GroundTruth {
  BodyModel model = test::bundled_model();
  Motion motion;                   ///< keyframes at disturbed times
  std::vector<double> true_times;  ///< where the keyframe poses really occur
};

/// A tucked back somersault simulated in free flight; 11 keyframes read off it (consecutive
/// ones well under 180° apart, which quaternion keyframes need); interior times disturbed by up
/// to ±0.08 s (the bound), 40 % of the keyframe spacing.
GroundTruth make_ground_truth() {
  GroundTruth g;
  const Motion source = test::tuck_motion(g.model);
  const Trajectory<double> joints = interpolate_keyframes(source, g.model);
  FreeFlightInitialState initial;
  initial.com_position = source.takeoff.com_position;
  initial.com_velocity = source.takeoff.com_velocity;
  initial.angular_momentum = Eigen::Vector3d(-30, 0, 0);
  initial.root_orientation = joints.rotations[0].evaluate(0.0).q;
  const int count = 11;
  const double duration = source.flight_time();
  for (int i = 0; i < count; ++i)
    g.true_times.push_back(duration * i / (count - 1));
  const auto states = simulate_free_flight(
      g.model,
      [&joints](double t, BodyState<double>& s) {
        for (int k = 1; k < joints.segment_count(); ++k) {
          const auto q = joints.rotations[k].evaluate(t);
          s.joints[k] = {q.q, q.omega, q.alpha};
        }
      },
      initial, g.true_times);
  const double disturbance[count] = {0,     0.08, -0.07, 0.05, -0.08, 0.06,
                                     -0.05, 0.08, -0.06, 0.07, 0};
  g.motion = test::base_motion("ground truth");
  for (int i = 0; i < count; ++i) {
    Keyframe k;
    k.time = g.true_times[i] + disturbance[i];
    for (const auto& j : states[i].joints)
      k.rotations.push_back(j.q);
    g.motion.keyframes.push_back(k);
  }
  return g;
}

double time_error(const std::vector<double>& times, const std::vector<double>& truth) {
  double sum = 0;
  for (std::size_t i = 0; i < times.size(); ++i)
    sum += std::abs(times[i] - truth[i]);
  return sum;
}

TEST(GroundTruth, DisturbedTimesOptimiseBackToFreeFlight) {
  const GroundTruth g = make_ground_truth();
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
      "ground truth: %s after %d iterations, %.2f s; avg root force %.3f -> %.3f N; "
      "time error %.3f -> %.3f s\n",
      r.solve.status.c_str(), r.solve.iterations, r.solve.seconds, before, after,
      time_error(r.before.keyframe_times, g.true_times),
      time_error(r.after.keyframe_times, g.true_times));
  EXPECT_GT(before, 5.0);  // the disturbed timing really breaks the physics
  EXPECT_LT(after, before / 100);
  EXPECT_LT(after, 1.0);
  EXPECT_LT(time_error(r.after.keyframe_times, g.true_times),
            time_error(r.before.keyframe_times, g.true_times));
}

}  // namespace
}  // namespace saltus
