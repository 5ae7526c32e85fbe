#pragma once
/// @file
/// How an Nlp is solved: Ipopt runs (ipopt_solver.h) under a policy of our own: an acceptable
/// exit on the objective's relative change, a restart from the best feasible iterate when a run
/// stalls, an early stop at feasibility checkpoints, the best feasible iterate returned when a
/// run ends somewhere worse, progress once per iteration and a cancel flag that stops cleanly.

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "saltus/optim/nlp.h"

namespace saltus {

/// A point by which a run must have come near feasibility (SolverOptions::feasibility_checkpoints).
struct FeasibilityCheckpoint {
  int iterations = 0;      ///< checked once this many iterations have run (restarts included)
  double violation = 0.0;  ///< the smallest constraint violation so far must be below this
};

struct SolverOptions {
  /// Iterations over every run of one solve (docs/optimizer.md says what the motions need).
  int max_iterations = 300;
  double tolerance =
      1e-8;  ///< Ipopt's tol: the NLP error for an "optimal" exit (CLI and GUI default)
  /// "Acceptable" exit (reported as solved): for `acceptable_iterations` consecutive iterations the
  /// objective changes by less than this fraction of max(1, |f|) while the constraints are
  /// violated by at most `acceptable_constraint_violation`. A sum of squared residuals that
  /// stays non-zero at the optimum converges linearly under Gauss–Newton: the last digits of J
  /// cost most of the iterations and move the average root force by < 0.1 %. 0 disables.
  double objective_change_tolerance = 1e-3;
  int acceptable_iterations = 3;
  /// In the constraints' units: a fraction of the keyframe tolerances (MotionNlp states them
  /// in units of the tolerance and keeps its bounds 2× this inside, see kKeyframeBoundMargin),
  /// s for keyframe-time gaps, N or N·m for the strict model's force bounds.
  double acceptable_constraint_violation = 0.01;
  /// Recovery from a wander. Interior-point iterates sometimes leave a good feasible region and
  /// drift (large timing errors, keyframes far from the interpolation): the objective climbs and
  /// the keyframe constraints break for hundreds of iterations. When no iterate has improved on
  /// the best feasible one (objective, constraints met to acceptable_constraint_violation) for
  /// this many iterations, the run is stopped and Ipopt restarts from that best iterate with a
  /// fresh barrier parameter and multipliers. 0 disables.
  int stall_iterations = 40;
  int max_restarts = 2;
  /// Early stop of a run that is nowhere near feasible (the strict model at a small ε): once a
  /// checkpoint's iterations have run, a run whose constraint violation (Ipopt's inf_pr, in the
  /// constraints' units: N and N·m for force bounds, tolerances for keyframes) has not once been
  /// below the checkpoint's violation stops with status "stopped_infeasible". This is evidence,
  /// not proof: no certificate of infeasibility exists for this nonconvex problem, so the
  /// checkpoints are set from measured runs (studies/convergence_study.h,
  /// kStrictStudyCheckpoints). Empty (the default): runs go on to max_iterations.
  std::vector<FeasibilityCheckpoint> feasibility_checkpoints;
  /// Start near an optimum (a finer resolution of a solved motion): a small initial barrier
  /// parameter and bound push, so the interior-point method does not first walk away from it.
  bool warm_start = false;
  bool verbose = false;  ///< Ipopt's own iteration log on stdout
  /// Run Ipopt's first-order derivative checker at the starting point and write its report
  /// (and the iteration log) to this file; empty: off.
  std::string derivative_test_file;
};

/// Which solve of a run an iteration belongs to: optimize_motion's levels (the root force on
/// knots refined level by level) and least joint effort's tries; solve_nlp on its own reports
/// kSolve. Each is a problem of its own, with an objective of its own (solve_stage_words).
struct SolveStage {
  enum class Kind { kSolve, kLevel, kJoints };
  Kind kind = Kind::kSolve;
  int step = 1;       ///< 1-based: the level, or the joints' try (kPolishTries)
  int max_steps = 1;  ///< the most a run can have of this kind
  /// The run's second pass: the levels and the joints again with the root moment weighed for
  /// the landing (kLandingRootMomentWeight in optimize.h).
  bool landing_pass = false;
  bool operator==(const SolveStage& o) const {
    return kind == o.kind && step == o.step && max_steps == o.max_steps &&
           landing_pass == o.landing_pass;
  }
  bool operator!=(const SolveStage& o) const { return !(*this == o); }
};

/// The stage in words: "level 2 of at most 3: the root force on knots refined where it lives",
/// "joints, try 2 of at most 5: least joint effort at the keyframe times found", prefixed with
/// "second pass for the landing, " in the landing pass; "solving" for kSolve.
std::string solve_stage_words(const SolveStage& stage);

/// What the objective of a stage's problem is, for a reader watching it: its terms and that it
/// starts again with each stage (a new problem), so that a jump between stages is not a failure.
std::string objective_meaning_words(const SolveStage& stage);

struct ProgressInfo {
  int iteration = 0;                  ///< over the run (optimize_motion counts across solves)
  double objective = 0.0;             ///< of the NLP being solved
  double constraint_violation = 0.0;  ///< Ipopt's inf_pr
  double elapsed_seconds = 0.0;       ///< over the run
  SolveStage stage;
  int stage_iteration = 0;  ///< this solve's own count (restarts included)
  /// The solve's acceptable exit (SolverOptions::objective_change_tolerance): it stops once the
  /// objective changes by less than this fraction for SolverOptions::acceptable_iterations.
  double objective_change_tolerance = 0.0;
  int acceptable_iterations = 0;
};

using ProgressCallback = std::function<void(const ProgressInfo&)>;

struct SolveReport {
  /// "solved" (Ipopt optimal or acceptable), else why not: "max_iterations", "infeasible",
  /// "cancelled", "diverging", "restoration_failed", "tiny_step", "stalled" (no progress after
  /// SolverOptions::max_restarts restarts), "stopped_infeasible" (a feasibility checkpoint was
  /// missed, SolverOptions::feasibility_checkpoints), "error".
  std::string status;
  std::string ipopt_status;  ///< Ipopt's own name of its return status
  bool solved = false;
  int iterations = 0;  ///< over every run
  int restarts = 0;  ///< restarts from the best feasible iterate (SolverOptions::stall_iterations)
  double seconds = 0.0;
  double objective = 0.0;
  /// The final point. If Ipopt does not converge: its best feasible iterate when that has a
  /// lower objective than the last iterate (the run wandered off), otherwise the last iterate.
  std::vector<double> x;
};

/// Solves `nlp` from its initial point. Never throws for solver failures: they are reported.
SolveReport solve_nlp(Nlp& nlp, const SolverOptions& options, const ProgressCallback& progress = {},
                      const std::atomic<bool>* cancel = nullptr);

}  // namespace saltus
