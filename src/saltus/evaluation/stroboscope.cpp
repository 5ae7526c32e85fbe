#include "saltus/evaluation/stroboscope.h"

#include <algorithm>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/body/mass_properties.h"
#include "saltus/evaluation/rotation_metrics.h"

namespace saltus {

namespace {

/// The vector's horizontal part (y is up).
Eigen::Vector3d horizontal(const Eigen::Vector3d& v) {
  return {v.x(), 0.0, v.z()};
}

}  // namespace

Stroboscope stroboscope(const BodyModel& model, const Trajectory<double>& trajectory,
                        int pose_count) {
  if (pose_count < 2) throw std::invalid_argument("a stroboscopic figure needs at least 2 poses");
  if (trajectory.segment_count() != model.size())
    throw std::invalid_argument("the trajectory does not match the model's segments");
  const double duration = trajectory.duration();
  const std::vector<SampleRecord> samples =
      evaluate_trajectory(model, trajectory, uniform_times(duration, pose_count));
  const std::vector<RotationSample> rotation = rotation_metrics(model, samples);

  Stroboscope out;
  const SampleRecord& takeoff = samples.front();
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  // The take-off horizontal velocity as the CoM's mean over the flight: equal to it in a
  // ballistic flight, and free of the end effects an interpolated motion's first sample has.
  const Eigen::Vector3d velocity =
      duration > 0.0 ? Eigen::Vector3d(horizontal(samples.back().com - takeoff.com) / duration)
                     : Eigen::Vector3d::Zero();
  if (velocity.norm() >= kStroboscopeStillSpeed) {
    // Across the CoM's plane, the flight running to the right: right = view × up.
    out.along_velocity = true;
    out.right = velocity.normalized();
    out.view_direction = up.cross(out.right);
  } else {
    // From the athlete's right: looking along the body's left (the root's x axis).
    const Eigen::Vector3d left =
        horizontal(takeoff.segment_rotation.front() * Eigen::Vector3d::UnitX());
    out.view_direction = left.norm() > 1e-6 ? left.normalized() : Eigen::Vector3d::UnitX();
    out.right = out.view_direction.cross(up);
  }
  out.travel_m = (samples.back().com - takeoff.com).dot(out.right);

  // Poses that would stand closer than the spacing rule are spread evenly along `right`: a shift
  // growing linearly with time, as if the athlete travelled faster, keeps the path a parabola.
  const double steps = static_cast<double>(pose_count - 1);
  const double wanted = kStroboscopeSpacingPerHeight * standing_body(model).height();
  const double natural = out.travel_m / steps;
  out.spread_m = std::max(0.0, wanted - natural);
  out.step_m = natural + out.spread_m;
  const double spread_speed = duration > 0.0 ? out.spread_m * steps / duration : 0.0;

  for (std::size_t i = 0; i < samples.size(); ++i) {
    StroboscopePose pose;
    pose.time = samples[i].time;
    pose.shift = out.spread_m * static_cast<double>(i) * out.right;
    pose.sample = samples[i];
    for (Eigen::Vector3d& p : pose.sample.segment_position)
      p += pose.shift;
    pose.sample.com += pose.shift;
    pose.spin_rev_per_s = rotation[i].angular_velocity.norm() / (2.0 * kPi);
    out.poses.push_back(std::move(pose));
  }
  for (const SampleRecord& s :
       evaluate_trajectory(model, trajectory, uniform_times(duration, kDefaultSamples)))
    out.com_path.push_back(s.com + spread_speed * s.time * out.right);
  return out;
}

}  // namespace saltus
