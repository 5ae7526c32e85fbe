#pragma once
/// @file
/// Sampling a motion through inverse dynamics: every quantity the outputs need at each time.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/dynamics/body_state.h"
#include "saltus/dynamics/spatial.h"
#include "saltus/motion/trajectory.h"

namespace saltus {

/// Everything the outputs need about one time sample.
struct SampleRecord {
  double time = 0.0;
  std::vector<Eigen::Vector3d> segment_position;     ///< segment origins, world, m
  std::vector<Eigen::Quaterniond> segment_rotation;  ///< world_from_segment
  Eigen::Vector3d com = Eigen::Vector3d::Zero();     ///< whole-body CoM, world
  Eigen::Vector3d com_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_momentum = Eigen::Vector3d::Zero();  ///< about the CoM, world
  Vector6d root_wrench = Vector6d::Zero();  ///< F1..F6: force, moment; root frame, root origin
  Vector6d residual = Vector6d::Zero();     ///< force, moment; world, about the CoM
  std::vector<Vector6d> joint_wrench;       ///< per segment, force first, child frame
  /// Per segment, the largest share of the athlete's strength its joint needs now
  /// (strength_demand.h); 0 for the root and where no direction has a strength curve.
  std::vector<double> strength_share;
};

/// Default time grid of every verb: 101 samples, 20.4 ms apart over the paper's 2.04 s flight,
/// 8 or more per knot span at K = 1; with many keyframes and --knots-per-interval 3, ask for
/// more. Measurement: docs/optimizer.md, "Measurement history" (Default samples).
inline constexpr int kDefaultSamples = 101;

/// Uniform grid of `count` >= 2 times from 0 to duration, both ends included.
std::vector<double> uniform_times(double duration, int count);

/// Inverse dynamics at each given state.
std::vector<SampleRecord> evaluate_states(const BodyModel& model, const std::vector<double>& times,
                                          const std::vector<BodyState<double>>& states);

/// Samples the trajectory on `times` and runs inverse dynamics at each.
std::vector<SampleRecord> evaluate_trajectory(const BodyModel& model,
                                              const Trajectory<double>& trajectory,
                                              const std::vector<double>& times);

}  // namespace saltus
