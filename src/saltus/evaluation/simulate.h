#pragma once
/// @file
/// `simulate_motion`: the free flight the motion's joint movements would really produce
/// (docs/method.md), the one call behind `saltus simulate`.

#include <map>
#include <string>
#include <vector>

#include "saltus/dynamics/free_flight.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/flight_state.h"

namespace saltus {

/// A free flight with the motion's joint movements (docs/method.md).
struct SimulationResult {
  std::vector<SampleRecord> samples;
  ForceMetrics metrics;  ///< of the simulated flight: ≈ 0 up to integration error
  Eigen::Vector3d angular_momentum = Eigen::Vector3d::Zero();  ///< take-off L used
  /// Where L came from: the motion file, or else the constant that best fits the motion's own
  /// L(t) over the flight (its time average; L(0) alone can be far off, e.g. a captured flip).
  bool angular_momentum_from_file = false;
  /// RMS over the flight of the motion's own L(t) about that constant, kg·m²/s: how far the
  /// keyframed (or optimised) motion is from conserving angular momentum.
  double angular_momentum_spread = 0.0;
  /// Landing pose versus the last keyframe: per joint (name -> degrees) the angle between the
  /// simulated and the keyframe rotation; the root's is the whole body's orientation error.
  std::map<std::string, double> landing_joint_error_deg;
  double landing_root_error_deg = 0.0;
  double landing_com_error_m = 0.0;  ///< simulated CoM vs the ballistic parabola at T
  /// The simulated whole-body orientation at T against the motion's own (its root spline at T),
  /// degrees: small when the motion obeys Newton's laws and its take-off state is its own.
  double landing_vs_motion_deg = 0.0;
};

SimulationResult simulate_motion(const Motion& motion, const BodyModel& model,
                                 const EvaluateOptions& options = {});

/// The take-off angular momentum simulate_motion flies a motion with, and where it came from.
struct TakeoffMomentum {
  Eigen::Vector3d value = Eigen::Vector3d::Zero();  ///< about the CoM, world, kg·m²/s
  bool from_file = false;  ///< the motion file's, else the constant nearest its own L(t)
  double spread = 0.0;     ///< RMS of the motion's own L(t) about that constant, kg·m²/s
};

/// The motion file's take-off angular momentum, or else the constant that best fits the
/// trajectory's own L(t) (its time average over 201 samples); `trajectory` is the motion's.
TakeoffMomentum takeoff_angular_momentum(const Motion& motion, const BodyModel& model,
                                         const Trajectory<double>& trajectory);

/// The joint movements of a free flight and the root orientations around them.
struct PrescribedJoints {
  JointMotion motion;  ///< fills joints 1..n−1 (q, ω, α) at a time
  /// Where the joints' acceleration is not smooth (a spline's knots): integration steps end there.
  std::vector<double> breakpoints;
  Eigen::Quaterniond takeoff_root = Eigen::Quaterniond::Identity();  ///< world_from_root at 0
  /// The motion's own whole-body orientation at landing (landing_vs_motion_deg is against it).
  Eigen::Quaterniond own_landing_root = Eigen::Quaterniond::Identity();
};

/// The joints of a trajectory: its curves 1..n−1, its knots, its root at 0 and at T. The joint
/// motion refers to `trajectory`, which must outlive it.
PrescribedJoints trajectory_joints(const Trajectory<double>& trajectory);

/// simulate_motion's flight for given joint movements: the body starts with `joints`' root
/// orientation, the motion's take-off CoM position and velocity and `angular_momentum`, and
/// flies for the motion's flight time; the landing errors are against the motion's last keyframe
/// and `joints.own_landing_root`. For flights with other joint movements from the same take-off
/// (what_if.h); simulate_motion is this with the motion's own trajectory. The result's
/// angular_momentum is `angular_momentum`; from_file and spread are left false and 0.
SimulationResult simulate_joint_motion(const Motion& motion, const BodyModel& model,
                                       const PrescribedJoints& joints,
                                       const Eigen::Vector3d& angular_momentum,
                                       const EvaluateOptions& options = {});

}  // namespace saltus
