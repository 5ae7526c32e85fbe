#pragma once
// Ground truth for the optimiser (docs/testing.md): a tucked back somersault simulated in free
// flight, keyframed at evenly spaced times, the interior times then disturbed. The poses really
// occur at `true_times`; a physically exact motion through them exists, so the residual must fall
// to (nearly) zero and timing optimisation must move the times back. Shared by the ground-truth
// test and the scaling benchmark.

#include <cmath>
#include <vector>

#include "saltus/dynamics/free_flight.h"
#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus::test {

struct GroundTruth {
  BodyModel model = bundled_model();
  Motion motion;                   ///< keyframes at disturbed times
  std::vector<double> true_times;  ///< where the keyframe poses really occur
};

/// Keyframes of a free flight in which the joints move as in `source` (its root is ignored).
/// @param angular_momentum  take-off L about the CoM, world, kg·m²/s
/// @param count             keyframes, >= 3; consecutive root poses must stay < 180° apart
/// @param max_shift_s       interior times are moved by up to this much, alternating in sign
///                          with a fixed pattern (deterministic, no random generator)
inline GroundTruth make_ground_truth(const Motion& source, const Eigen::Vector3d& angular_momentum,
                                     int count, double max_shift_s) {
  GroundTruth g;
  const Trajectory<double> joints = interpolate_keyframes(source, g.model);
  FreeFlightInitialState initial;
  initial.com_position = source.takeoff.com_position;
  initial.com_velocity = source.takeoff.com_velocity;
  initial.angular_momentum = angular_momentum;
  initial.root_orientation = joints.rotations[0].evaluate(0.0).q;
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
  // Shifts of 1.0, 0.875, 0.625, 1.0, 0.75 ... of max_shift_s with alternating signs.
  const double pattern[] = {1.0, -0.875, 0.625, -1.0, 0.75, -0.625, 1.0, -0.75, 0.875};
  g.motion = base_motion("ground truth");
  for (int i = 0; i < count; ++i) {
    Keyframe k;
    const bool interior = i > 0 && i + 1 < count;
    k.time = g.true_times[i] + (interior ? max_shift_s * pattern[(i - 1) % 9] : 0.0);
    for (const auto& j : states[i].joints)
      k.rotations.push_back(j.q);
    g.motion.keyframes.push_back(k);
  }
  return g;
}

/// The tucked back somersault (L = −30 kg·m²/s, ~1.4 turns: 9 or more keyframes).
inline GroundTruth make_ground_truth(int count, double max_shift_s) {
  return make_ground_truth(tuck_motion(bundled_model()), Eigen::Vector3d(-30, 0, 0), count,
                           max_shift_s);
}

/// Σ |t_i − t_i,true| over the keyframes, s.
inline double time_error(const std::vector<double>& times, const std::vector<double>& truth) {
  double sum = 0;
  for (std::size_t i = 0; i < times.size(); ++i)
    sum += std::abs(times[i] - truth[i]);
  return sum;
}

}  // namespace saltus::test
