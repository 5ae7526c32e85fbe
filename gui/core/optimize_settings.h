#pragma once
/// @file
/// The optimisation panel's choices, their translation into the library's OptimizeOptions (with
/// the same defaults as `saltus optimize`), the rows of the result table and the progress line.

#include <string>
#include <vector>

#include "saltus/optim/optimize.h"

namespace saltus::gui {

struct OptimizeSettings {
  bool strict = false;          ///< strict spacetime constraints instead of the relaxed model
  double epsilon = 100.0;       ///< strict bound on each |F_i|, N or N·m
  bool optimize_timing = true;  ///< interior keyframe times are variables
  int knots_per_interval = 0;   ///< 0: automatic resolution (`--knots-per-interval auto`)
  int max_iterations = SolverOptions{}.max_iterations;  ///< the library's (and CLI's) default
  int samples = kDefaultSamples;
  /// Soft limit on a joint's turn between two control points (`--max-joint-turn`), 0 = none.
  double max_joint_turn_deg = 180.0;
};

/// `saltus optimize --tol`'s default: the library's.
inline const double kCliTolerance = SolverOptions{}.tolerance;

/// Ranges the panel enforces (the CLI's).
constexpr int kMaxKnotsPerInterval = 50;
constexpr int kMaxIterations = 100000;
constexpr int kMinSamples = 2;
constexpr int kMaxSamples = 100000;

/// Throws std::invalid_argument naming the field for a value out of range.
OptimizeOptions to_optimize_options(const OptimizeSettings& settings);

struct ResultRow {
  std::string quantity;
  std::string before;
  std::string after;
};

/// Keyframes, knot refinement (asked/used), variables, constraints, objective and average root
/// force before/after, iterations (and restarts), seconds, status, RMS/peak force and moment,
/// keyframe times and errors.
std::vector<ResultRow> result_table(const OptimizationResult& result,
                                    const OptimizeOptions& options);

/// One line of live progress, e.g. "iteration 12   objective 3.41e+01   violation 2.0e-05   3.2 s".
std::string progress_text(const ProgressInfo& progress);

}  // namespace saltus::gui
