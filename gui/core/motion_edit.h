#pragma once
/// @file
/// Editing a motion's keyframes: joint angles as Euler angles in degrees, keyframe times, adding
/// and deleting keyframes. Every edit returns a new Motion and is checked by the library's own
/// parser (parse_motion of motion_to_json), so the app never holds a motion the library would
/// reject; the library's message (InputError) is what the user sees.

#include <Eigen/Core>
#include <optional>
#include <string>

#include "saltus/evaluation/sampling.h"
#include "saltus/formats/motion_file.h"
#include "saltus/motion/motion.h"

namespace saltus::gui {

/// Intrinsic X-Y-Z Euler angles in degrees of a rotation (R = Rx(a) Ry(b) Rz(c), the inverse of
/// quat_from_euler_deg(angles, "XYZ")); b in [-90, 90].
Eigen::Vector3d euler_xyz_deg(const Eigen::Quaterniond& q);

/// Why `time` cannot be keyframe `index`'s time (first fixed at 0, last at T, times strictly
/// increasing), or nullopt if it can.
std::optional<std::string> keyframe_time_problem(const Motion& motion, int index, double time);
/// Why a keyframe cannot be added at `time` (strictly inside (0, T), not on another keyframe).
std::optional<std::string> new_keyframe_time_problem(const Motion& motion, double time);

/// Each returns the edited copy, checked by the library (throws InputError with its message, or
/// std::invalid_argument with the problem above). An edit drops a stored optimised spline: the
/// keyframes no longer describe it.
Motion with_joint_angles(const Motion& motion, const BodyModel& model, int keyframe, int segment,
                         const Eigen::Vector3d& euler_deg);
Motion with_keyframe_time(const Motion& motion, const BodyModel& model, int keyframe, double time);
/// A keyframe at `time` with the pose of `pose` (a sample of the motion at that time): joint
/// rotations relative to the parent, as stored in keyframes.
Motion with_keyframe_added(const Motion& motion, const BodyModel& model, double time,
                           const SampleRecord& pose);
/// The first and last keyframes cannot be deleted (they fix the flight's start and end).
Motion with_keyframe_deleted(const Motion& motion, const BodyModel& model, int keyframe);

/// Runs the library's parser on the motion as it would be written; throws InputError.
void validate_motion(const Motion& motion, const BodyModel& model);

}  // namespace saltus::gui
