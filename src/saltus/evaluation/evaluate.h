#pragma once
/// @file
/// `evaluate_motion`: a motion as interpolated (or as stored) and its dynamics, the one call
/// behind `saltus evaluate` and the app's views of a motion.

#include <vector>

#include "saltus/evaluation/force_metrics.h"
#include "saltus/evaluation/keyframe_errors.h"
#include "saltus/evaluation/sampling.h"
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
  std::vector<SampleRecord> samples;  ///< at `samples` uniform times (the written trajectory)
  /// The true residual: the dense check (force_metrics.h), at least `samples` points and
  /// kCheckPointsPerSpan per knot span. `metrics` is check.metrics.
  DenseCheck check;
  ForceMetrics metrics;
  KeyframeErrors keyframe_errors;
};

/// Throws std::invalid_argument for options out of range (samples < 2, knots per interval < 1).
MotionEvaluation evaluate_motion(const Motion& motion, const BodyModel& model,
                                 const EvaluateOptions& options = {});

/// Throws std::invalid_argument for options out of range (samples < 2, knots per interval < 1).
void check_evaluate_options(const EvaluateOptions& options);

}  // namespace saltus
