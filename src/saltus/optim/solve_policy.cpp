#include "saltus/optim/ipopt_solver.h"

#include <IpDenseVector.hpp>
#include <IpIpoptApplication.hpp>
#include <IpIpoptData.hpp>
#include <IpIteratesVector.hpp>
#include <IpTNLP.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "saltus/base/text_format.h"

namespace saltus {

namespace {

using Ipopt::Index;
using Ipopt::Number;

/// The lowest-objective iterate whose constraints were met (to the acceptable violation), over
/// every run of one solve, and the smallest violation of any iterate.
struct BestIterate {
  std::vector<double> x;
  double objective = std::numeric_limits<double>::infinity();
  double smallest_violation = std::numeric_limits<double>::infinity();
  bool found() const { return !x.empty(); }
};

/// MUMPS allocates its frontal matrices (tens of MB) afresh for every factorization. With
/// glibc's defaults those blocks are mmap'ed and returned to the kernel on free, so every
/// iteration page-faulted them in again: 8 % of M7's run time was in the kernel. Serving them
/// from the heap and keeping the heap's top makes the next factorization reuse the same pages
/// (M7: 1.66 -> 1.47 s). Process-wide, set once; memory peaks stay mapped, which for a
/// process that optimises again is what is wanted.
void keep_solver_memory_mapped() {
#if defined(__GLIBC__)
  static std::once_flag once;
  std::call_once(once, [] {
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
  });
#endif
}

/// One Ipopt run. Iterations are numbered on from `first_iteration` (earlier runs of the same
/// solve) in progress reports.
class NlpAdapter : public Ipopt::TNLP {
 public:
  NlpAdapter(Nlp& nlp, const SolverOptions& options, const ProgressCallback& progress,
             const std::atomic<bool>* cancel, const std::vector<double>* start, int first_iteration,
             SolveReport& report, BestIterate& best)
      : nlp_(nlp),
        options_(options),
        progress_(progress),
        cancel_(cancel),
        start_(start),
        first_iteration_(first_iteration),
        report_(report),
        best_(best),
        start_time_(std::chrono::steady_clock::now()) {}

  /// True when the run was stopped because it stalled (see SolverOptions::stall_iterations).
  bool stalled() const { return stalled_; }
  /// The feasibility checkpoint the run missed (SolverOptions::feasibility_checkpoints), if any.
  const FeasibilityCheckpoint* missed_checkpoint() const { return missed_; }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = nlp_.variable_count();
    m = nlp_.constraint_count();
    nnz_jac_g = nlp_.jacobian_nonzeros();
    nnz_h_lag = nlp_.has_hessian() ? nlp_.hessian_nonzeros() : 0;
    index_style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index, Number* x_l, Number* x_u, Index, Number* g_l, Number* g_u) override {
    nlp_.bounds(x_l, x_u, g_l, g_u);
    return true;
  }

  bool get_starting_point(Index, bool init_x, Number* x, bool init_z, Number*, Number*, Index,
                          bool init_lambda, Number*) override {
    if (init_z || init_lambda) return false;  // no warm start of multipliers
    if (init_x) {
      if (start_)
        std::copy(start_->begin(), start_->end(), x);
      else
        nlp_.initial_point(x);
    }
    return true;
  }

  bool eval_f(Index, const Number* x, bool, Number& obj_value) override {
    obj_value = nlp_.objective(x);
    return std::isfinite(obj_value);
  }
  bool eval_grad_f(Index, const Number* x, bool, Number* grad_f) override {
    nlp_.gradient(x, grad_f);
    return true;
  }
  bool eval_g(Index, const Number* x, bool, Index, Number* g) override {
    nlp_.constraints(x, g);
    return true;
  }
  bool eval_jac_g(Index, const Number* x, bool, Index, Index, Index* i_row, Index* j_col,
                  Number* values) override {
    if (values == nullptr)
      nlp_.jacobian_structure(i_row, j_col);
    else
      nlp_.jacobian_values(x, values);
    return true;
  }
  bool eval_h(Index, const Number* x, bool, Number obj_factor, Index, const Number* lambda, bool,
              Index, Index* i_row, Index* j_col, Number* values) override {
    if (values == nullptr)
      nlp_.hessian_structure(i_row, j_col);
    else
      nlp_.hessian_values(x, obj_factor, lambda, values);
    return true;
  }

  bool intermediate_callback(Ipopt::AlgorithmMode mode, Index iter, Number obj_value, Number inf_pr,
                             Number, Number, Number, Number, Number, Number, Index ls_trials,
                             const Ipopt::IpoptData* ip_data,
                             Ipopt::IpoptCalculatedQuantities*) override {
    report_.iterations = first_iteration_ + iter;
    StepTaken step;
    step.iteration = iter;
    step.line_search_trials = ls_trials;
    step.restoration = mode == Ipopt::RestorationPhaseMode;
    nlp_.step_taken(step);
    if (mode == Ipopt::RegularMode && obj_value < best_.objective) {
      // Progress: a feasible iterate better than the best one, or an infeasible one below it
      // (the usual way to approach a constrained optimum), but only the former is kept.
      if (inf_pr <= options_.acceptable_constraint_violation && remember(ip_data)) {
        best_.objective = obj_value;
        best_iteration_ = iter;
      }
      if (best_.found()) last_improvement_ = iter;
    }
    if (progress_) {
      ProgressInfo info;
      info.iteration = report_.iterations;
      info.objective = obj_value;
      info.constraint_violation = inf_pr;
      info.elapsed_seconds = elapsed();
      progress_(info);
    }
    if (cancel_ && cancel_->load()) return false;
    best_.smallest_violation = std::min(best_.smallest_violation, static_cast<double>(inf_pr));
    for (const FeasibilityCheckpoint& checkpoint : options_.feasibility_checkpoints)
      if (report_.iterations >= checkpoint.iterations &&
          !(best_.smallest_violation < checkpoint.violation)) {
        missed_ = &checkpoint;
        return false;
      }
    // A restart from this run's own starting point would retrace the same path: only a best
    // iterate found during the run (iteration > 0) is worth restarting from.
    if (options_.stall_iterations > 0 && best_iteration_ > 0 &&
        iter - last_improvement_ >= options_.stall_iterations) {
      stalled_ = true;
      return false;
    }
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* x, const Number*,
                         const Number*, Index, const Number*, const Number*, Number obj_value,
                         const Ipopt::IpoptData* ip_data,
                         Ipopt::IpoptCalculatedQuantities*) override {
    report_.x.assign(x, x + n);
    report_.objective = obj_value;
    if (ip_data) report_.iterations = first_iteration_ + ip_data->iter_count();
    using Ipopt::SolverReturn;
    switch (status) {
      case Ipopt::SUCCESS:
        report_.status = "solved", report_.ipopt_status = "optimal";
        break;
      case Ipopt::STOP_AT_ACCEPTABLE_POINT:
        report_.status = "solved", report_.ipopt_status = "acceptable";
        break;
      case Ipopt::MAXITER_EXCEEDED:
      case Ipopt::CPUTIME_EXCEEDED:
        report_.status = "max_iterations", report_.ipopt_status = "maximum iterations exceeded";
        break;
      case Ipopt::LOCAL_INFEASIBILITY:
        report_.status = "infeasible", report_.ipopt_status = "converged to an infeasible point";
        break;
      case Ipopt::USER_REQUESTED_STOP:
        report_.status = "cancelled", report_.ipopt_status = "user requested stop";
        break;
      case Ipopt::DIVERGING_ITERATES:
        report_.status = "diverging", report_.ipopt_status = "diverging iterates";
        break;
      case Ipopt::RESTORATION_FAILURE:
        report_.status = "restoration_failed", report_.ipopt_status = "restoration failed";
        break;
      case Ipopt::STOP_AT_TINY_STEP:
        report_.status = "tiny_step", report_.ipopt_status = "search direction too small";
        break;
      default:
        report_.status = "error", report_.ipopt_status = "solver error";
        break;
    }
    report_.solved = report_.status == "solved";
  }

  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time_).count();
  }

 private:
  /// Copies Ipopt's current x into best_. Ipopt's internal x is the TNLP's x here: no scaling
  /// (nlp_scaling_method none) and no fixed variables (no variable has equal bounds); the
  /// dimension check guards that assumption.
  bool remember(const Ipopt::IpoptData* ip_data) {
    if (!ip_data || !IsValid(ip_data->curr())) return false;
    const auto* x = dynamic_cast<const Ipopt::DenseVector*>(Ipopt::GetRawPtr(ip_data->curr()->x()));
    if (!x || x->Dim() != nlp_.variable_count()) return false;
    const double* values = x->ExpandedValues();
    best_.x.assign(values, values + x->Dim());
    return true;
  }

  Nlp& nlp_;
  const SolverOptions& options_;
  const ProgressCallback& progress_;
  const std::atomic<bool>* cancel_;
  const std::vector<double>* start_;
  int first_iteration_ = 0;
  SolveReport& report_;
  BestIterate& best_;
  int last_improvement_ = -1;  ///< last iteration below the best feasible objective
  int best_iteration_ = -1;    ///< this run's iteration that set best_, −1 if none did
  bool stalled_ = false;
  const FeasibilityCheckpoint* missed_ = nullptr;
  std::chrono::steady_clock::time_point start_time_;
};

}  // namespace

SolveReport solve_with_ipopt(Nlp& nlp, const SolverOptions& options,
                             const ProgressCallback& progress, const std::atomic<bool>* cancel) {
  SolveReport report;
  report.status = "error";
  keep_solver_memory_mapped();
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetIntegerValue("print_level", options.verbose ? 5 : 0);
  app->Options()->SetStringValue("sb", "yes");  // no banner
  app->Options()->SetNumericValue("tol", options.tolerance);
  app->Options()->SetStringValue("mu_strategy", "adaptive");
  // Keyframe rows are in units of their tolerance, with bounds 2 % inside it: an "optimal" exit
  // may violate them by 1e-6 of a tolerance.
  app->Options()->SetNumericValue("constr_viol_tol", 1e-6);
  // The objective keeps its own units (N²): Ipopt's gradient-based scaling divides J by its
  // largest initial gradient entry (~1e4 on a keyframed motion), after which the relative
  // objective-change test below would compare changes with max(1, 1e-3) and stop far too early.
  app->Options()->SetStringValue("nlp_scaling_method", "none");
  // Filter line search: every Gauss–Newton step bends off the curved keyframe constraints (by
  // 1e-2..1e-1 of a tolerance). With Ipopt's default switching rule (δ = 1, θ_min = 1e-4) such
  // a violation outweighs the objective, and steps that cut it are accepted even when they
  // multiply the root force (measured on M1: J 0.5 -> 5 N² and back, for 60 iterations). A
  // small δ and θ_min = 0.3 (of a tolerance) make a descent step satisfy Armijo on J whenever
  // the violation is below that, which is almost always the case here; feasibility is still
  // enforced by the Newton step and by the termination tests. Measured over the convergence
  // study's 105 relaxed cases (M1-M7 × 5 mass × 3 timing errors): θ_min = 0.01 left cases
  // cycling between h-type steps that restore the keyframes and f-type steps that break them
  // again (M6 at K = 3: 262 iterations; M1 with −20 % mass and 0.05 s timing error: never
  // accepted); 0.1 solved 100/105 in 11165 iterations, 0.3 all 105 in 9296.
  app->Options()->SetNumericValue("delta", 1e-8);
  app->Options()->SetNumericValue("theta_min_fact", 0.3);
  if (options.objective_change_tolerance > 0) {
    app->Options()->SetNumericValue("acceptable_obj_change_tol",
                                    options.objective_change_tolerance);
    app->Options()->SetIntegerValue("acceptable_iter", options.acceptable_iterations);
    app->Options()->SetNumericValue("acceptable_constr_viol_tol",
                                    options.acceptable_constraint_violation);
    // The objective-change and feasibility tests decide; the NLP error (a gradient norm in N²
    // per radian, unscaled) does not.
    app->Options()->SetNumericValue("acceptable_tol", 1e20);
  } else {
    app->Options()->SetIntegerValue("acceptable_iter", 0);
  }
  if (!options.derivative_test_file.empty()) {
    app->Options()->SetStringValue("derivative_test", "first-order");
    // Ipopt's checker uses one-sided differences: truncation h·f''/2 against rounding
    // ~1e-16·Σ|F_i²|/h (J sums squared forces of up to 1e4 N²). No step makes both small, so
    // this is a coarse check of the adapter's plumbing; the exact derivatives are checked by
    // central differences in tests/unit/motion_nlp_test.cpp.
    app->Options()->SetNumericValue("derivative_test_perturbation", 1e-7);
    // Check at the given point, not at Ipopt's default random perturbation of it (radius 10
    // within the bounds lands on wild poses where J is enormous and differences meaningless).
    app->Options()->SetNumericValue("point_perturbation_radius", 0.0);
    app->Options()->SetNumericValue("derivative_test_tol", 2e-2);
    app->Options()->SetStringValue("output_file", options.derivative_test_file);
    app->Options()->SetIntegerValue("file_print_level", 5);
  }
  // MUMPS on our KKT systems: a banded Hessian (a sample couples 4 consecutive control points
  // of every curve) bordered by a few keyframe-time columns and keyframe rows. Approximate
  // minimum degree finds the band's natural order; with Ipopt's automatic ordering, MUMPS's
  // scaling passes and a refinement step on every solve M7 took 2.1 s instead of 1.53 s, for
  // the same iterates (docs/performance.md). The residual of each solve is still checked, and
  // refined when it needs it.
  app->Options()->SetIntegerValue("mumps_pivot_order", 0);
  app->Options()->SetIntegerValue("mumps_scaling", 0);
  app->Options()->SetIntegerValue("mumps_permuting_scaling", 0);
  app->Options()->SetIntegerValue("min_refinement_steps", 0);
  if (!nlp.has_hessian()) app->Options()->SetStringValue("hessian_approximation", "limited-memory");
  if (options.warm_start) {
    app->Options()->SetNumericValue("mu_init", 1e-4);
    app->Options()->SetNumericValue("bound_push", 1e-6);
    app->Options()->SetNumericValue("bound_frac", 1e-6);
  }
  // "": no options file. Ipopt would otherwise read ./ipopt.opt, and a stray file in the user's
  // folder would silently change the solver (the same input must give the same output).
  if (app->Initialize("") != Ipopt::Solve_Succeeded) {
    report.ipopt_status = "initialisation failed";
    return report;
  }
  const auto start = std::chrono::steady_clock::now();
  BestIterate best;
  std::vector<double> restart_point;
  for (int run = 0;; ++run) {
    const int used = report.iterations;
    app->Options()->SetIntegerValue("max_iter", std::max(0, options.max_iterations - used));
    Ipopt::SmartPtr<NlpAdapter> adapter = new NlpAdapter(
        nlp, options, progress, cancel, run == 0 ? nullptr : &restart_point, used, report, best);
    app->OptimizeTNLP(adapter);
    const bool budget_left = report.iterations < options.max_iterations;
    if (const FeasibilityCheckpoint* missed = adapter->missed_checkpoint()) {
      report.status = "stopped_infeasible";
      report.ipopt_status = "stopped early: constraint violation never below " +
                            format_number("%g", missed->violation) + " in " +
                            std::to_string(missed->iterations) + " iterations";
      report.solved = false;
      break;
    }
    if (!adapter->stalled() || !best.found() || run >= options.max_restarts || !budget_left) {
      // A stalled run ends as "user requested stop"; say what happened instead.
      if (adapter->stalled()) {
        report.status = "stalled";
        report.ipopt_status = "no progress on the best feasible iterate";
        report.solved = false;
      }
      break;
    }
    restart_point = best.x;
    ++report.restarts;
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (report.x.empty()) {  // Ipopt gave up before finalize (e.g. an exception inside)
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
