#pragma once
/// @file
/// Yeadon's orientation angles ("The simulation of aerial movement I", J. Biomech. 23(1), 1990):
/// the body's orientation as a somersault φ about the lateral axis, then a tilt θ about the
/// frontal axis, then a twist ψ about the body's longitudinal axis, the sequence coaches and
/// researchers read a twisting somersault in. Here the body is the root segment (abdomen, the
/// trunk's middle) and, with Saltus's axes (docs/method.md, "Conventions"),
///   world_from_root = Rx(φ)·Rz(θ)·Ry(ψ)   (x lateral, z frontal, y longitudinal).
/// Signs follow the axes: φ < 0 about world x (as M1, a back somersault of a body facing +z),
/// ψ > 0 twists to the left (anticlockwise seen from above the head), θ > 0 leans the head
/// toward +x. Summaries count somersaults as forward or backward for the athlete.
/// φ and ψ are unwrapped over time, so they count turns; θ stays within ±90°.

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "saltus/motion/trajectory.h"

namespace saltus {

/// (φ, θ, ψ) of one orientation, rad: φ, ψ in (−π, π], θ in [−π/2, π/2].
Eigen::Vector3d somersault_tilt_twist(const Eigen::Quaterniond& world_from_root);

/// (φ̇, θ̇, ψ̇), rad/s, from the angles and the root's body-frame angular velocity: solves
/// ω = Ryᵀ·Rzᵀ·x̂·φ̇ + Ryᵀ·ẑ·θ̇ + ŷ·ψ̇. Undefined at θ = ±90° (Cardan's lock).
Eigen::Vector3d somersault_tilt_twist_rates(const Eigen::Vector3d& angles,
                                            const Eigen::Vector3d& omega_body);

/// The angles of orientations in time order, φ and ψ made continuous (each step taken as the
/// nearest turn): needs samples closer than half a turn of either angle apart.
std::vector<Eigen::Vector3d> unwrapped_angles(const std::vector<Eigen::Quaterniond>& rotations);

/// +1 when a positive somersault φ is a forward somersault of an athlete whose root has this
/// orientation at take-off, −1 when it is a backward one: forward carries the head towards the
/// side the body faces, i.e. it is positive about the body's left axis, the root's x axis.
double forward_somersault_sign(const Eigen::Quaterniond& world_from_root_at_takeoff);

/// A flight in a coach's words and its extremes.
struct YeadonSummary {
  /// ±(φ(T) − φ(0))/2π, revolutions, signed so that > 0 is forward (forward_somersault_sign)
  double somersaults = 0.0;
  double twists = 0.0;        ///< (ψ(T) − ψ(0))/2π, revolutions (signed: > 0 to the left)
  double max_tilt_deg = 0.0;  ///< max |θ|
  double peak_twist_rate_rev_s = 0.0;   ///< max |ψ̇|, revolutions per second
  double peak_twist_rate_time_s = 0.0;  ///< when
  /// "1½ back somersaults with 2 twists to the left", to the nearest quarter somersault and
  /// half twist ("no somersault", "a ¼ front somersault", "with ½ twist to the right").
  std::string description;
};

/// The summary of a trajectory, sampled at least every 2.5 ms (and on `min_points`) so that the
/// peak rate is the trajectory's, not a grid's.
YeadonSummary yeadon_summary(const Trajectory<double>& trajectory, int min_points = 0);

/// The same from the root's rotations at the samples of a flight (in time order), without the rate
/// (the samples hold no angular velocity): peak_twist_rate_rev_s is left 0.
YeadonSummary yeadon_summary(const std::vector<Eigen::Quaterniond>& root_rotations);

/// The words for these counts (YeadonSummary::description); `somersaults` > 0 forward.
std::string somersault_twist_words(double somersaults, double twists);

}  // namespace saltus
