#include "saltus/motion/interpolate.h"

#include <algorithm>
#include <future>
#include <stdexcept>

#include "saltus/dynamics/inverse_dynamics.h"

namespace saltus {

namespace {

/// Runs fit(k) for every curve k in [0, count), half of them on a second thread: the curves'
/// fits are independent, and between two levels of the automatic resolution they are all the
/// optimiser does (5 % of M6's CPU time, serial). The results do not depend on the split. An
/// exception from either half propagates once both have finished.
template <typename Fit>
void fit_each_curve(int count, const Fit& fit) {
  const auto fit_range = [&fit](int begin, int end) {
    for (int k = begin; k < end; ++k)
      fit(k);
  };
  const int half = count / 2;
  std::future<void> second_half = std::async(std::launch::async, fit_range, half, count);
  fit_range(0, half);
  second_half.get();
}

}  // namespace

Eigen::Vector3d ballistic_com(const Takeoff& takeoff, double t) {
  return takeoff.com_position + takeoff.com_velocity * t + 0.5 * gravity() * t * t;
}

Eigen::Vector3d ballistic_com_velocity(const Takeoff& takeoff, double t) {
  return takeoff.com_velocity + gravity() * t;
}

Eigen::Vector3d com_with_root_at_origin(const BodyModel& model,
                                        const std::vector<Eigen::Quaterniond>& rotations) {
  BodyState<double> state(model.size());
  for (int i = 0; i < model.size(); ++i)
    state.joints[i].q = rotations[i];
  DynamicsData<double> data(model);
  inverse_dynamics(model, data, state);
  return data.com;
}

std::vector<Eigen::Vector3d> keyframe_root_targets(const Motion& motion, const BodyModel& model) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(motion.keyframes.size());
  for (const Keyframe& k : motion.keyframes) {
    if (k.root_position) {
      out.push_back(*k.root_position);
    } else {
      out.push_back(ballistic_com(motion.takeoff, k.time) -
                    com_with_root_at_origin(model, k.rotations));
    }
  }
  return out;
}

Trajectory<double> interpolate_keyframes(const Motion& motion, const BodyModel& model,
                                         const InterpolationOptions& options) {
  if (options.knots_per_interval < 1)
    throw std::invalid_argument("knots per interval must be at least 1");
  if (motion.keyframes.size() < 2) throw std::invalid_argument("a motion needs two keyframes");

  std::vector<double> times;
  for (const Keyframe& k : motion.keyframes)
    times.push_back(k.time);
  Trajectory<double> trajectory;
  trajectory.knots = clamped_cubic_knots(options.subdivisions.empty()
                                             ? refine_breakpoints(times, options.knots_per_interval)
                                             : refine_breakpoints(times, options.subdivisions));

  // Step 1 (§5.2): one quaternion spline per joint through its keyframe rotations.
  std::vector<std::vector<Eigen::Quaterniond>> control(model.size());
  fit_each_curve(model.size(), [&](int seg) {
    std::vector<std::pair<double, Eigen::Quaterniond>> targets;
    for (std::size_t i = 0; i < times.size(); ++i)
      targets.emplace_back(times[i], motion.keyframes[i].rotations[seg]);
    if (seg == 0) {
      targets.insert(targets.end(), options.root_guides.begin(), options.root_guides.end());
      std::stable_sort(targets.begin(), targets.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
    }
    std::vector<double> at;
    std::vector<Eigen::Quaterniond> rotations;
    for (const auto& [t, q] : targets) {
      at.push_back(t);
      rotations.push_back(q);
    }
    control[seg] = fit_quaternion_spline(trajectory.knots, at, rotations);
  });
  for (auto& c : control)
    trajectory.rotations.emplace_back(trajectory.knots, std::move(c));

  // Steps 2-3 (eqs. 9-10): root translation s(t) − s'(t), sampled densely and fitted.
  const int spans = control_count(trajectory.knots) - 3;
  const int n_fit = spans * options.root_fit_samples_per_span + 1;
  const double duration = times.back();
  std::vector<double> fit_times;
  std::vector<Eigen::Vector3d> fit_points;
  std::vector<Eigen::Quaterniond> pose(model.size());
  for (int s = 0; s < n_fit; ++s) {
    // The last time is T itself: duration·s/(n − 1) can round past the last knot (1.83 s).
    const double t = s + 1 == n_fit ? duration : std::min(duration, duration * s / (n_fit - 1));
    for (int seg = 0; seg < model.size(); ++seg)
      pose[seg] = trajectory.rotations[seg].evaluate(t).q;
    fit_times.push_back(t);
    fit_points.push_back(ballistic_com(motion.takeoff, t) - com_with_root_at_origin(model, pose));
  }
  trajectory.root_translation = VectorSpline<double>(
      trajectory.knots, fit_vector_spline(trajectory.knots, fit_times, fit_points));
  return trajectory;
}

Trajectory<double> refit_trajectory(const Trajectory<double>& trajectory,
                                    const std::vector<double>& knots, int samples_per_span) {
  std::vector<double> times;
  for (std::size_t s = 3; s + 4 < knots.size(); ++s)
    for (int i = 0; i < samples_per_span; ++i)
      times.push_back(knots[s] + (knots[s + 1] - knots[s]) * i / samples_per_span);
  times.push_back(knots.back());
  Trajectory<double> out;
  out.knots = knots;
  std::vector<Eigen::Vector3d> positions;
  for (double t : times)
    positions.push_back(trajectory.root_translation.evaluate(t).position);
  out.root_translation = VectorSpline<double>(knots, fit_vector_spline(knots, times, positions));
  const int curves = static_cast<int>(trajectory.rotations.size());
  std::vector<std::vector<Eigen::Quaterniond>> control(curves);
  fit_each_curve(curves, [&](int k) {
    std::vector<Eigen::Quaterniond> rotations(times.size());
    for (std::size_t i = 0; i < times.size(); ++i)
      rotations[i] = trajectory.rotations[k].evaluate(times[i]).q;
    control[k] = fit_quaternion_spline(knots, times, rotations);
  });
  for (auto& c : control)
    out.rotations.emplace_back(knots, std::move(c));
  return out;
}

Trajectory<double> trajectory_from_stored_spline(const StoredSpline& spline,
                                                 const BodyModel& model) {
  if (static_cast<int>(spline.joint_control.size()) != model.size())
    throw std::invalid_argument("stored spline has a different number of joints than the model");
  Trajectory<double> trajectory;
  trajectory.knots = spline.knots;
  trajectory.root_translation = VectorSpline<double>(spline.knots, spline.root_translation);
  for (const auto& control : spline.joint_control)
    trajectory.rotations.emplace_back(spline.knots, control);
  return trajectory;
}

StoredSpline to_stored_spline(const Trajectory<double>& trajectory) {
  StoredSpline out;
  out.knots = trajectory.knots;
  out.root_translation = trajectory.root_translation.control();
  for (const auto& r : trajectory.rotations)
    out.joint_control.push_back(r.control());
  return out;
}

Trajectory<double> motion_trajectory(const Motion& motion, const BodyModel& model,
                                     const InterpolationOptions& options) {
  if (motion.spline) return trajectory_from_stored_spline(*motion.spline, model);
  return interpolate_keyframes(motion, model, options);
}

}  // namespace saltus
