#include "core/motion_edit.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "saltus/formats/motion_file.h"

namespace saltus::gui {

namespace {

constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;
/// Keyframes closer than this (s) are one keyframe for the user.
constexpr double kMinGap = 1e-3;

std::string seconds(double t) {
  std::ostringstream out;
  out.precision(4);
  out << t << " s";
  return out.str();
}

void check_index(const Motion& motion, int keyframe) {
  if (keyframe < 0 || keyframe >= static_cast<int>(motion.keyframes.size()))
    throw std::invalid_argument("no keyframe " + std::to_string(keyframe + 1));
}

Motion checked(Motion edited, const BodyModel& model) {
  edited.spline.reset();
  validate_motion(edited, model);
  return edited;
}

}  // namespace

Eigen::Vector3d euler_xyz_deg(const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d r = q.normalized().toRotationMatrix();
  // R = Rx(a) Ry(b) Rz(c): R(0,2) = sin b, R(1,2) = -sin a cos b, R(2,2) = cos a cos b,
  // R(0,1) = -cos b sin c, R(0,0) = cos b cos c.
  const double b = std::asin(std::clamp(r(0, 2), -1.0, 1.0));
  double a, c;
  if (std::abs(r(0, 2)) < 1.0 - 1e-9) {
    a = std::atan2(-r(1, 2), r(2, 2));
    c = std::atan2(-r(0, 1), r(0, 0));
  } else {
    // Gimbal lock: only a ± c is defined; put it all in a.
    a = std::atan2(r(2, 1), r(1, 1));
    c = 0.0;
  }
  return Eigen::Vector3d(a, b, c) * kDegPerRad;
}

std::optional<std::string> keyframe_time_problem(const Motion& motion, int index, double time) {
  const int n = static_cast<int>(motion.keyframes.size());
  if (index < 0 || index >= n) return "no keyframe " + std::to_string(index + 1);
  if (!std::isfinite(time)) return std::string("the time must be a number");
  if (index == 0)
    return time == 0.0 ? std::nullopt
                       : std::optional<std::string>("the first keyframe stays at 0 s");
  const double previous = motion.keyframes[static_cast<std::size_t>(index - 1)].time;
  if (time <= previous + kMinGap)
    return "keyframe " + std::to_string(index + 1) + " must come after keyframe " +
           std::to_string(index) + " (" + seconds(previous) + ")";
  if (index + 1 < n) {
    const double next = motion.keyframes[static_cast<std::size_t>(index + 1)].time;
    if (time >= next - kMinGap)
      return "keyframe " + std::to_string(index + 1) + " must come before keyframe " +
             std::to_string(index + 2) + " (" + seconds(next) + ")";
  }
  return std::nullopt;
}

std::optional<std::string> new_keyframe_time_problem(const Motion& motion, double time) {
  if (!std::isfinite(time)) return std::string("the time must be a number");
  const double end = motion.flight_time();
  if (time <= kMinGap || time >= end - kMinGap)
    return "a new keyframe must lie strictly between 0 s and the end (" + seconds(end) + ")";
  for (std::size_t i = 0; i < motion.keyframes.size(); ++i)
    if (std::abs(motion.keyframes[i].time - time) <= kMinGap)
      return "keyframe " + std::to_string(i + 1) + " is already at " +
             seconds(motion.keyframes[i].time);
  return std::nullopt;
}

void validate_motion(const Motion& motion, const BodyModel& model) {
  parse_motion(motion_to_json(motion, model), "the edited motion \"" + motion.name + "\"", model);
}

Motion with_joint_angles(const Motion& motion, const BodyModel& model, int keyframe, int segment,
                         const Eigen::Vector3d& euler_deg) {
  check_index(motion, keyframe);
  if (segment < 0 || segment >= model.size())
    throw std::invalid_argument("no segment " + std::to_string(segment));
  if (!euler_deg.allFinite()) throw std::invalid_argument("the angles must be numbers");
  Motion edited = motion;
  const Eigen::Vector3d r = euler_deg / kDegPerRad;
  edited.keyframes[static_cast<std::size_t>(keyframe)].rotations.at(
      static_cast<std::size_t>(segment)) = Eigen::AngleAxisd(r.x(), Eigen::Vector3d::UnitX()) *
                                           Eigen::AngleAxisd(r.y(), Eigen::Vector3d::UnitY()) *
                                           Eigen::AngleAxisd(r.z(), Eigen::Vector3d::UnitZ());
  return checked(std::move(edited), model);
}

Motion with_keyframe_time(const Motion& motion, const BodyModel& model, int keyframe, double time) {
  if (const auto problem = keyframe_time_problem(motion, keyframe, time))
    throw std::invalid_argument(*problem);
  Motion edited = motion;
  edited.keyframes[static_cast<std::size_t>(keyframe)].time = time;
  return checked(std::move(edited), model);
}

Motion with_keyframe_added(const Motion& motion, const BodyModel& model, double time,
                           const SampleRecord& pose) {
  if (const auto problem = new_keyframe_time_problem(motion, time))
    throw std::invalid_argument(*problem);
  if (static_cast<int>(pose.segment_rotation.size()) != model.size())
    throw std::invalid_argument("the pose does not match the model");
  Keyframe k;
  k.time = time;
  for (int i = 0; i < model.size(); ++i) {
    const Eigen::Quaterniond& world_from_segment =
        pose.segment_rotation[static_cast<std::size_t>(i)];
    const int parent = model.segments[static_cast<std::size_t>(i)].parent;
    // Keyframes store each segment relative to its parent (the root: to the world).
    k.rotations.push_back(
        parent < 0 ? world_from_segment
                   : (pose.segment_rotation[static_cast<std::size_t>(parent)].conjugate() *
                      world_from_segment)
                         .normalized());
  }
  // Motions that place the root at keyframes get this one's placement too.
  const bool placed = std::any_of(motion.keyframes.begin(), motion.keyframes.end(),
                                  [](const Keyframe& kf) { return kf.root_position.has_value(); });
  if (placed && !pose.segment_position.empty()) k.root_position = pose.segment_position.front();
  Motion edited = motion;
  const auto at = std::upper_bound(edited.keyframes.begin(), edited.keyframes.end(), time,
                                   [](double t, const Keyframe& kf) { return t < kf.time; });
  edited.keyframes.insert(at, std::move(k));
  return checked(std::move(edited), model);
}

Motion with_keyframe_deleted(const Motion& motion, const BodyModel& model, int keyframe) {
  check_index(motion, keyframe);
  if (keyframe == 0 || keyframe + 1 == static_cast<int>(motion.keyframes.size()))
    throw std::invalid_argument("the first and last keyframes fix the flight; they stay");
  Motion edited = motion;
  edited.keyframes.erase(edited.keyframes.begin() + keyframe);
  return checked(std::move(edited), model);
}

}  // namespace saltus::gui
