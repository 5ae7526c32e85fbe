#pragma once
/// @file
/// What a study keeps of one optimisation: the solve, the problem's size and the root force
/// before and after. One summary for every study (the convergence study's cases, the report's
/// runs), written into their case records and tables; the whole result goes to a result folder
/// when the study writes one.

#include <string>
#include <vector>

#include "saltus/motion/motion.h"
#include "saltus/optim/optimize.h"

namespace saltus {

struct RunSummary {
  std::string motion_name;  ///< Motion::name
  int keyframes = 0;
  /// SolveReport::status, or "crashed" / "timed_out" when the case's process did not finish.
  std::string status;
  bool solved = false;
  int iterations = 0;
  double seconds = 0.0;  ///< the solve's wall time
  int variables = 0;
  int constraints = 0;
  int knots_per_interval = 1;  ///< K used (raised when the interpolation missed the keyframes)
  int restarts = 0;            ///< solver restarts from its best feasible iterate
  double objective_before = 0.0, objective_after = 0.0;  ///< J, N²
  double avg_force_before = 0.0, avg_force_after = 0.0;  ///< sqrt(J/6), N
  double max_force_after = 0.0;                          ///< N
  double max_quaternion_error = 0.0;  ///< of the result, against the keyframes it was given
  std::vector<double> keyframe_times_before, keyframe_times_after;
  /// False when the case's process failed: only motion_name, keyframes and status are set.
  bool completed() const { return status != "crashed" && status != "timed_out"; }
};

/// The summary of `result`, an optimisation of `motion`.
RunSummary summarize_run(const Motion& motion, const OptimizationResult& result);

}  // namespace saltus
