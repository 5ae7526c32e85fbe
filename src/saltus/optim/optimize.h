#pragma once
/// @file
/// `optimize_motion`: interpolation ("before"), the NLP, Ipopt, and the optimised motion
/// ("after") evaluated on the same grid — the one call behind `saltus optimize` and the GUI.

#include <atomic>

#include "saltus/analysis/motion_analysis.h"
#include "saltus/optim/ipopt_solver.h"
#include "saltus/optim/motion_nlp.h"

namespace saltus {

struct OptimizeOptions {
  MotionNlpOptions nlp;
  SolverOptions solver;
};

struct OptimizationResult {
  SolveReport solve;
  int variables = 0;
  int constraints = 0;
  MotionEvaluation before;  ///< the interpolated motion (the starting point)
  MotionEvaluation after;   ///< the optimised motion, on the same sample grid
  /// The input motion with the optimised keyframe times and the optimised spline stored, so that
  /// loading it reproduces `after` exactly.
  Motion optimized_motion;
};

/// Throws std::invalid_argument for options out of range; solver failures are reported in
/// result.solve (the result is still complete, from the last iterate).
OptimizationResult optimize_motion(const Motion& motion, const BodyModel& model,
                                   const OptimizeOptions& options,
                                   const ProgressCallback& progress = {},
                                   const std::atomic<bool>* cancel = nullptr);

}  // namespace saltus
