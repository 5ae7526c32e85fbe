#pragma once
/// @file
/// Keyframe interpolation (paper §5): the optimiser's starting point, "before".
///  1. each joint's quaternion spline is fitted through its keyframe rotations (§5.2);
///  2. the CoM follows the ballistic parabola s(t) = S0 + v t + ½ g t² (eq. 9);
///  3. the root translation is s(t) − s'(t), where s'(t) is the CoM with the root at the world
///     origin (eq. 10), represented as a cubic B-spline on the same knots.

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/motion/motion.h"
#include "saltus/motion/trajectory.h"

namespace saltus {

struct InterpolationOptions {
  /// Knot sub-intervals per keyframe interval: 1 = knots at the keyframe times (the paper).
  int knots_per_interval = 1;
  /// Knot spans per keyframe interval (one entry per interval); replaces the uniform
  /// knots_per_interval when given.
  std::vector<int> subdivisions;
  /// Samples per knot span for the least-squares fit of the root translation.
  int root_fit_samples_per_span = 24;
  /// Root orientations (world_from_root) at times strictly between keyframes that the root's
  /// curve is fitted through besides the keyframes': where two keyframes are too far apart for
  /// the short way between them to be the way the body turned (evaluation/keyframe_spacing.h).
  std::vector<std::pair<double, Eigen::Quaterniond>> root_guides;
};

/// Ballistic CoM position at time t (eq. 9).
Eigen::Vector3d ballistic_com(const Takeoff& takeoff, double t);
/// Ballistic CoM velocity at time t (derivative of eq. 9).
Eigen::Vector3d ballistic_com_velocity(const Takeoff& takeoff, double t);

/// CoM of the body in the given segment rotations with the root origin at the world origin
/// (eq. 10's s'). `rotations` has one parent_from_child quaternion per segment.
Eigen::Vector3d com_with_root_at_origin(const BodyModel& model,
                                        const std::vector<Eigen::Quaterniond>& rotations);

/// Root positions the keyframes ask for, B̄(t_i): the keyframe's root_position when given,
/// otherwise s(t_i) − s'(t_i) from the keyframe pose.
std::vector<Eigen::Vector3d> keyframe_root_targets(const Motion& motion, const BodyModel& model);

/// Keyframe interpolation (steps 1-3 above). Throws std::invalid_argument for options out of
/// range (knots_per_interval < 1).
Trajectory<double> interpolate_keyframes(const Motion& motion, const BodyModel& model,
                                         const InterpolationOptions& options = {});

/// `trajectory` on other knots (the same time range): each curve fitted by least squares to
/// `samples_per_span` points per span of the new knots (exact for the root translation when the
/// new knots refine the old ones). For starting a finer resolution from a coarser optimum.
Trajectory<double> refit_trajectory(const Trajectory<double>& trajectory,
                                    const std::vector<double>& knots, int samples_per_span = 8);

/// The trajectory stored in a motion file's "spline" member. Throws InputError-free
/// std::invalid_argument if the counts do not fit the model (parse_motion checks them first).
Trajectory<double> trajectory_from_stored_spline(const StoredSpline& spline,
                                                 const BodyModel& model);

/// The inverse of trajectory_from_stored_spline.
StoredSpline to_stored_spline(const Trajectory<double>& trajectory);

/// The trajectory a motion file describes: its stored spline when present, else interpolation.
Trajectory<double> motion_trajectory(const Motion& motion, const BodyModel& model,
                                     const InterpolationOptions& options = {});

}  // namespace saltus
