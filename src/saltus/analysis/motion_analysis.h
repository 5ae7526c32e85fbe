#pragma once
/// @file
/// The two whole-motion jobs behind `saltus evaluate` and `saltus simulate` (and the GUI's views
/// of them): one library call each, so no front end re-implements any physics.

#include <map>
#include <string>
#include <vector>

#include "saltus/analysis/evaluation.h"
#include "saltus/motion/interpolate.h"
#include "saltus/motion/motion.h"

namespace saltus {

struct EvaluateOptions {
  int samples = kDefaultSamples;  ///< time samples on [0, T], both ends included
  InterpolationOptions interpolation;
};

/// A motion as interpolated (or as stored, for optimised motions) and its dynamics.
struct MotionEvaluation {
  Trajectory<double> trajectory;
  std::vector<double> keyframe_times;
  std::vector<Eigen::Vector3d> root_targets;  ///< B̄ per keyframe
  std::vector<SampleRecord> samples;
  ForceMetrics metrics;
  KeyframeErrors keyframe_errors;
};

/// Throws std::invalid_argument for options out of range (samples < 2, knots per interval < 1).
MotionEvaluation evaluate_motion(const Motion& motion, const BodyModel& model,
                                 const EvaluateOptions& options = {});

/// A free flight with the motion's joint movements (DESIGN §5).
struct SimulationResult {
  std::vector<SampleRecord> samples;
  ForceMetrics metrics;  ///< of the simulated flight: ≈ 0 up to integration error
  Eigen::Vector3d angular_momentum = Eigen::Vector3d::Zero();  ///< take-off L used
  bool angular_momentum_from_file = false;  ///< else implied by the keyframes at t = 0
  /// Landing pose versus the last keyframe: per joint (name -> degrees) the angle between the
  /// simulated and the keyframe rotation; the root's is the whole body's orientation error.
  std::map<std::string, double> landing_joint_error_deg;
  double landing_root_error_deg = 0.0;
  double landing_com_error_m = 0.0;  ///< simulated CoM vs the ballistic parabola at T
};

SimulationResult simulate_motion(const Motion& motion, const BodyModel& model,
                                 const EvaluateOptions& options = {});

}  // namespace saltus
