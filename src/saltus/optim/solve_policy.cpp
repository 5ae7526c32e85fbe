#include "saltus/optim/solve_policy.h"

#include <algorithm>
#include <chrono>
#include <limits>

#include "saltus/base/text_format.h"
#include "saltus/optim/ipopt_solver.h"

namespace saltus {

namespace {

using Clock = std::chrono::steady_clock;

/// The lowest-objective iterate whose constraints were met (to the acceptable violation), over
/// every run of one solve, and the smallest violation of any iterate.
struct BestIterate {
  std::vector<double> x;
  double objective = std::numeric_limits<double>::infinity();
  double smallest_violation = std::numeric_limits<double>::infinity();
  bool found() const { return !x.empty(); }
};

/// One run's watch over its iterations: the best iterate, progress, cancel, checkpoints, stall.
class RunWatch {
 public:
  RunWatch(const SolverOptions& options, const ProgressCallback& progress,
           const std::atomic<bool>* cancel, int first_iteration, Clock::time_point start,
           BestIterate& best)
      : options_(options),
        progress_(progress),
        cancel_(cancel),
        first_iteration_(first_iteration),
        start_(start),
        best_(best) {}

  bool operator()(const IpoptIteration& it) {
    const int iterations = first_iteration_ + it.iteration;
    if (!it.restoration && it.objective < best_.objective) {
      // Progress: a feasible iterate better than the best one, or an infeasible one below it
      // (the usual way to approach a constrained optimum), but only the former is kept.
      if (it.constraint_violation <= options_.acceptable_constraint_violation &&
          it.current_point(best_.x)) {
        best_.objective = it.objective;
        best_iteration_ = it.iteration;
      }
      if (best_.found()) last_improvement_ = it.iteration;
    }
    if (progress_) {
      ProgressInfo info;
      info.iteration = iterations;
      info.objective = it.objective;
      info.constraint_violation = it.constraint_violation;
      info.elapsed_seconds = std::chrono::duration<double>(Clock::now() - start_).count();
      info.stage_iteration = iterations;
      info.objective_change_tolerance = options_.objective_change_tolerance;
      info.acceptable_iterations = options_.acceptable_iterations;
      progress_(info);
    }
    if (cancel_ && cancel_->load()) return false;
    best_.smallest_violation = std::min(best_.smallest_violation, it.constraint_violation);
    for (const FeasibilityCheckpoint& checkpoint : options_.feasibility_checkpoints)
      if (iterations >= checkpoint.iterations &&
          !(best_.smallest_violation < checkpoint.violation)) {
        missed_ = &checkpoint;
        return false;
      }
    // A restart from this run's own starting point would retrace the same path: only a best
    // iterate found during the run (iteration > 0) is worth restarting from.
    if (options_.stall_iterations > 0 && best_iteration_ > 0 &&
        it.iteration - last_improvement_ >= options_.stall_iterations) {
      stalled_ = true;
      return false;
    }
    return true;
  }

  bool stalled() const { return stalled_; }
  const FeasibilityCheckpoint* missed_checkpoint() const { return missed_; }

 private:
  const SolverOptions& options_;
  const ProgressCallback& progress_;
  const std::atomic<bool>* cancel_;
  int first_iteration_ = 0;
  Clock::time_point start_;
  BestIterate& best_;
  int last_improvement_ = -1;  ///< last iteration below the best feasible objective
  int best_iteration_ = -1;    ///< this run's iteration that set best_, −1 if none did
  bool stalled_ = false;
  const FeasibilityCheckpoint* missed_ = nullptr;
};

IpoptSettings ipopt_settings(const SolverOptions& o) {
  IpoptSettings s;
  s.max_iterations = o.max_iterations;
  s.tolerance = o.tolerance;
  s.objective_change_tolerance = o.objective_change_tolerance;
  s.acceptable_iterations = o.acceptable_iterations;
  s.acceptable_constraint_violation = o.acceptable_constraint_violation;
  s.warm_start = o.warm_start;
  s.verbose = o.verbose;
  s.derivative_test_file = o.derivative_test_file;
  return s;
}

}  // namespace

std::string solve_stage_words(const SolveStage& stage) {
  if (stage.kind == SolveStage::Kind::kSolve) return "solving";
  std::string out = stage.landing_pass ? "second pass for the landing, " : "";
  const std::string of =
      std::to_string(stage.step) + " of at most " + std::to_string(stage.max_steps);
  if (stage.kind == SolveStage::Kind::kLevel) {
    if (stage.max_steps <= 1) return out + "the least root force on the knots asked for";
    return out + "level " + of +
           (stage.step == 1 ? ": the least root force on knots chosen from how far the body turns"
                            : ": the least root force on knots refined where it lives");
  }
  return out + "joints, try " + of +
         ": least joint effort at the keyframe times found, the root force held";
}

std::string objective_meaning_words(const SolveStage& stage) {
  if (stage.kind == SolveStage::Kind::kJoints)
    return "The objective now adds least joint effort (the joints' moments squared) to the root "
           "force and moment: a new problem, so it starts higher and falls as the joints work "
           "less.";
  return "The objective: the root force and moment squared over the flight, plus small terms "
         "for the keyframes and joints. Each stage is a new problem and starts again: a jump "
         "between stages is no failure.";
}

SolveReport solve_nlp(Nlp& nlp, const SolverOptions& options, const ProgressCallback& progress,
                      const std::atomic<bool>* cancel) {
  SolveReport report;
  report.status = "error";
  const Clock::time_point start = Clock::now();
  IpoptSettings settings = ipopt_settings(options);
  BestIterate best;
  std::vector<double> restart_point;
  for (int run = 0;; ++run) {
    const int used = report.iterations;
    settings.max_iterations = std::max(0, options.max_iterations - used);
    RunWatch watch(options, progress, cancel, used, start, best);
    const IpoptRun result = run_ipopt(nlp, settings, run == 0 ? nullptr : &restart_point,
                                      [&watch](const IpoptIteration& it) { return watch(it); });
    report.iterations = used + result.iterations;
    if (!result.x.empty()) {
      report.x = result.x;
      report.objective = result.objective;
    }
    report.status = result.status == "stopped" ? "cancelled" : result.status;
    report.ipopt_status = result.ipopt_status;
    report.solved = report.status == "solved";
    const bool budget_left = report.iterations < options.max_iterations;
    if (const FeasibilityCheckpoint* missed = watch.missed_checkpoint()) {
      report.status = "stopped_infeasible";
      report.ipopt_status = "stopped early: constraint violation never below " +
                            format_number("%g", missed->violation) + " in " +
                            std::to_string(missed->iterations) + " iterations";
      report.solved = false;
      break;
    }
    if (!watch.stalled() || !best.found() || run >= options.max_restarts || !budget_left) {
      if (watch.stalled()) {
        report.status = "stalled";
        report.ipopt_status = "no progress on the best feasible iterate";
        report.solved = false;
      }
      break;
    }
    restart_point = best.x;
    ++report.restarts;
  }
  report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (report.x.empty()) {  // Ipopt gave up before a final point (e.g. an exception inside)
    report.x.resize(nlp.variable_count());
    nlp.initial_point(report.x.data());
  }
  // A failed run returns its best feasible iterate when it stopped somewhere worse (a wander);
  // a run stopped early while still improving keeps its last, lower-objective iterate, whose
  // keyframe errors the caller checks and reports.
  if (!report.solved && best.found() && best.objective < report.objective) {
    report.x = best.x;
    report.objective = best.objective;
  }
  return report;
}

}  // namespace saltus
