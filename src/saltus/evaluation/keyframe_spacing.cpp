#include "saltus/evaluation/keyframe_spacing.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "saltus/base/constants.h"
#include "saltus/base/text_format.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/evaluation/yeadon_angles.h"
#include "saltus/motion/interpolate.h"

namespace saltus {
namespace {

/// Times every ≤ 5 ms over the flight with the keyframe times among them (ψ is read there).
std::vector<double> grid_with_keyframes(const Motion& motion) {
  const double duration = motion.flight_time();
  const int steps = static_cast<int>(std::ceil(duration / 0.005));
  std::vector<double> times;
  for (int i = 0; i <= steps; ++i)
    times.push_back(duration * i / steps);
  for (const Keyframe& k : motion.keyframes)
    times.push_back(k.time);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

/// Yeadon's ψ (rad, unwrapped) of `rotations` at the samples `at`.
std::vector<double> twist_at(const std::vector<Eigen::Quaterniond>& rotations,
                             const std::vector<std::size_t>& at) {
  const std::vector<Eigen::Vector3d> angles = unwrapped_angles(rotations);
  std::vector<double> out;
  for (const std::size_t k : at)
    out.push_back(angles[k].z());
  return out;
}

}  // namespace

std::vector<SparseTwistInterval> sparse_twist_intervals(const Motion& motion,
                                                        const BodyModel& model) {
  const Trajectory<double> interpolation = motion_trajectory(motion, model);
  const PrescribedJoints joints = trajectory_joints(interpolation);
  FreeFlightInitialState initial;
  initial.com_position = motion.takeoff.com_position;
  initial.com_velocity = motion.takeoff.com_velocity;
  initial.root_orientation = joints.takeoff_root;
  initial.angular_momentum = motion.takeoff.angular_momentum
                                 ? *motion.takeoff.angular_momentum
                                 : takeoff_angular_momentum(motion, model, interpolation).value;
  FreeFlightOptions integration;
  integration.breakpoints = joints.breakpoints;
  const std::vector<double> times = grid_with_keyframes(motion);
  const std::vector<BodyState<double>> states =
      simulate_free_flight(model, joints.motion, initial, times, integration);

  std::vector<Eigen::Quaterniond> flown, interpolated;
  for (std::size_t i = 0; i < times.size(); ++i) {
    flown.push_back(states[i].joints[0].q);
    interpolated.push_back(interpolation.rotations[0].evaluate(times[i]).q);
  }
  // The sample of each keyframe time (the grid holds them all).
  std::vector<std::size_t> key_samples;
  for (const Keyframe& k : motion.keyframes)
    key_samples.push_back(static_cast<std::size_t>(
        std::lower_bound(times.begin(), times.end(), k.time) - times.begin()));
  const std::vector<double> flight_twist = twist_at(flown, key_samples);
  const std::vector<double> interpolation_twist = twist_at(interpolated, key_samples);

  std::vector<SparseTwistInterval> out;
  for (std::size_t i = 0; i + 1 < key_samples.size(); ++i) {
    SparseTwistInterval interval;
    interval.first_keyframe = static_cast<int>(i);
    interval.start_s = motion.keyframes[i].time;
    interval.end_s = motion.keyframes[i + 1].time;
    interval.flight_twist_deg = (flight_twist[i + 1] - flight_twist[i]) * kDegreesPerRadian;
    interval.interpolation_twist_deg =
        (interpolation_twist[i + 1] - interpolation_twist[i]) * kDegreesPerRadian;
    if (std::abs(interval.flight_twist_deg - interval.interpolation_twist_deg) <=
        kSparseTwistLimitDeg)
      continue;
    const std::size_t first = key_samples[i], last = key_samples[i + 1];
    // The flight must turn from one keyframe's orientation to the next's as the keyframes do,
    // only another way round; else it is the flight that disagrees with the keyframes.
    const Eigen::Quaterniond flight_turn = flown[last] * flown[first].conjugate();
    const Eigen::Quaterniond key_turn =
        motion.keyframes[i + 1].rotations[0] * motion.keyframes[i].rotations[0].conjugate();
    if (flight_turn.angularDistance(key_turn) * kDegreesPerRadian > kSparseTwistSameTurnDeg)
      continue;
    double turn = 0.0;
    for (std::size_t k = first; k < last; ++k)
      turn += flown[k].angularDistance(flown[k + 1]);
    const int guides = std::max(1, static_cast<int>(std::ceil(turn / (0.5 * kPi))) - 1);
    const Eigen::Quaterniond& key_root = motion.keyframes[i].rotations[0];
    for (int g = 1; g <= guides; ++g) {
      const std::size_t k = first + (last - first) * g / (guides + 1);
      interval.flight_roots.emplace_back(
          times[k], (flown[k] * flown[first].conjugate() * key_root).normalized());
    }
    out.push_back(interval);
  }
  return out;
}

std::string sparse_twist_words(const SparseTwistInterval& interval) {
  return "keyframes " + std::to_string(interval.first_keyframe + 1) + "-" +
         std::to_string(interval.first_keyframe + 2) + format_number(" (%.2f-", interval.start_s) +
         format_number("%.2f s) ", interval.end_s) +
         "are too far apart for the twist: the free flight from the take-off twists " +
         format_number("%+.0f deg between them, ", interval.flight_twist_deg) +
         format_number("the interpolation %+.0f deg; ", interval.interpolation_twist_deg) +
         format_number("add a keyframe near t = %.2f s", 0.5 * (interval.start_s + interval.end_s));
}

}  // namespace saltus
