#pragma once
/// @file
/// Free-flight forward simulation (Yeadon-style): the joints follow prescribed motions, the root
/// moves as physics dictates, i.e. with zero root wrench. The result obeys Newton's laws up to
/// integration error — the ground truth for tests and the "what would really happen" view.

#include <functional>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/dynamics/body_state.h"

namespace saltus {

/// Fills joints[1..n-1] of `state` (q, omega, alpha) at time t. joints[0] and the root
/// translation are ignored: the simulator owns them.
using JointMotion = std::function<void(double t, BodyState<double>& state)>;

struct FreeFlightInitialState {
  Eigen::Vector3d com_position = Eigen::Vector3d::Zero();                ///< world, m
  Eigen::Vector3d com_velocity = Eigen::Vector3d::Zero();                ///< world, m/s
  Eigen::Vector3d angular_momentum = Eigen::Vector3d::Zero();            ///< about the CoM, world
  Eigen::Quaterniond root_orientation = Eigen::Quaterniond::Identity();  ///< world_from_root
};

struct FreeFlightOptions {
  double max_step = 1e-3;  ///< s; RK4 step (sub-divides the gaps between output times)
  /// Times where the joint motion's acceleration is not smooth (a spline's knots): steps end
  /// there instead of straddling them.
  std::vector<double> breakpoints;
};

/// The root state that makes the root wrench vanish for the given joint state: fills
/// state.joints[0].alpha and state.root_acceleration from q, ω, position and velocity of the
/// root (a_root = −I_c⁻¹·bias).
void solve_free_root_acceleration(const BodyModel& model, BodyState<double>& state);

/// Sets the root's velocity and angular velocity so that the whole body has the given CoM
/// velocity and angular momentum, and its position so that the CoM is at com_position; the
/// root orientation and the joints' state are taken from `state`.
void set_root_from_momentum(const BodyModel& model, const Eigen::Vector3d& com_position,
                            const Eigen::Vector3d& com_velocity,
                            const Eigen::Vector3d& angular_momentum, BodyState<double>& state);

/// Integrates from t = times.front() with RK4 and returns one full state per output time, each
/// with the root acceleration that zeroes the root wrench. `times` must be non-decreasing.
std::vector<BodyState<double>> simulate_free_flight(const BodyModel& model,
                                                    const JointMotion& joint_motion,
                                                    const FreeFlightInitialState& initial,
                                                    const std::vector<double>& times,
                                                    const FreeFlightOptions& options = {});

}  // namespace saltus
