#pragma once
/// @file
/// `simulate_motion`: the free flight the motion's joint movements would really produce
/// (docs/method.md), the one call behind `saltus simulate`.

#include <map>
#include <string>
#include <vector>

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

}  // namespace saltus
