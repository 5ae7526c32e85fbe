#pragma once
/// @file
/// One Ipopt run of an Nlp. The adapter only translates (Drake's style): Ipopt's TNLP calls map
/// onto Nlp, Ipopt's options come from IpoptSettings one to one, and every iteration is shown
/// to an observer that may stop the run. When to stop, restart or accept a point is the solve
/// policy's (solve_policy.h). Ipopt's headers stay inside ipopt_solver.cpp.

#include <functional>
#include <string>
#include <vector>

#include "saltus/optim/nlp.h"

namespace saltus {

/// Ipopt's options as the solve policy sets them.
struct IpoptSettings {
  int max_iterations = 300;
  double tolerance = 1e-8;  ///< tol: the NLP error of an "optimal" exit
  /// Ipopt's "acceptable" exit on the objective's relative change alone (acceptable_obj_change_tol
  /// for acceptable_iterations iterations, constraints within acceptable_constraint_violation);
  /// 0: no acceptable exit.
  double objective_change_tolerance = 0.0;
  int acceptable_iterations = 3;
  double acceptable_constraint_violation = 0.01;
  bool warm_start = false;           ///< a small initial barrier parameter and bound push
  bool verbose = false;              ///< Ipopt's own iteration log on stdout
  std::string derivative_test_file;  ///< Ipopt's first-order derivative check written here
};

/// What one iteration shows the observer.
struct IpoptIteration {
  int iteration = 0;  ///< of this run
  double objective = 0.0;
  double constraint_violation = 0.0;  ///< Ipopt's inf_pr
  bool restoration = false;           ///< Ipopt's restoration phase
  int line_search_trials = 0;
  /// Copies the iterate into `x`; false when Ipopt does not expose it.
  std::function<bool(std::vector<double>& x)> current_point;
};

/// How a run ended.
struct IpoptRun {
  /// "solved" (optimal or acceptable), "max_iterations", "infeasible", "stopped" (the observer
  /// stopped it), "diverging", "restoration_failed", "tiny_step" or "error".
  std::string status = "error";
  std::string ipopt_status;  ///< Ipopt's own name of its return status
  int iterations = 0;
  std::vector<double> x;  ///< the final point; empty if Ipopt gave up before one
  double objective = 0.0;
};

/// Runs Ipopt on `nlp` from `start` (or the Nlp's initial point when null). `observe` is called
/// after every iteration; returning false stops the run. Never throws for solver failures.
IpoptRun run_ipopt(Nlp& nlp, const IpoptSettings& settings, const std::vector<double>* start,
                   const std::function<bool(const IpoptIteration&)>& observe);

}  // namespace saltus
