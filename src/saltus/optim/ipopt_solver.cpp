#include "saltus/optim/ipopt_solver.h"

#include <dlfcn.h>
#include <IpDenseVector.hpp>
#include <IpIpoptApplication.hpp>
#include <IpIpoptData.hpp>
#include <IpIteratesVector.hpp>
#include <IpTNLP.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>

// One MUMPS call at a time in a process. Ipopt's linear solver, MUMPS (Debian's 5.5, sequential),
// keeps the factorisation's load-balancing data in Fortran module variables shared by every
// instance: two optimisations at once in one process (two threads of the Python module) crashed
// in dmumps_load_update. Ipopt calls MUMPS only through dmumps_c, so this definition, found
// before MUMPS's own (the program's or the module's symbols come first), takes a lock and
// calls MUMPS's; everything else of two solves (the NLP's callbacks, Ipopt's own steps) still
// runs at once.
extern "C" void dmumps_c(void* mumps_data) {
  using Mumps = void (*)(void*);
  static const Mumps mumps = reinterpret_cast<Mumps>(dlsym(RTLD_NEXT, "dmumps_c"));
  static std::mutex one_at_a_time;
  if (!mumps) {
    std::fputs("saltus: MUMPS's dmumps_c not found beside Ipopt\n", stderr);
    std::abort();
  }
  const std::lock_guard<std::mutex> lock(one_at_a_time);
  mumps(mumps_data);
}

namespace saltus {

namespace {

using Ipopt::Index;
using Ipopt::Number;

/// Ipopt's calls onto the Nlp, and each iteration onto the observer.
class NlpAdapter : public Ipopt::TNLP {
 public:
  NlpAdapter(Nlp& nlp, const std::vector<double>* start,
             const std::function<bool(const IpoptIteration&)>& observe, IpoptRun& run)
      : nlp_(nlp), start_(start), observe_(observe), run_(run) {}

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
    run_.iterations = iter;
    StepTaken step;
    step.iteration = iter;
    step.line_search_trials = ls_trials;
    step.restoration = mode == Ipopt::RestorationPhaseMode;
    nlp_.step_taken(step);
    if (!observe_) return true;
    IpoptIteration it;
    it.iteration = iter;
    it.objective = obj_value;
    it.constraint_violation = inf_pr;
    it.restoration = step.restoration;
    it.line_search_trials = ls_trials;
    it.current_point = [this, ip_data](std::vector<double>& x) { return current(ip_data, x); };
    return observe_(it);
  }

  void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* x, const Number*,
                         const Number*, Index, const Number*, const Number*, Number obj_value,
                         const Ipopt::IpoptData* ip_data,
                         Ipopt::IpoptCalculatedQuantities*) override {
    run_.x.assign(x, x + n);
    run_.objective = obj_value;
    if (ip_data) run_.iterations = ip_data->iter_count();
    switch (status) {
      case Ipopt::SUCCESS:
        run_.status = "solved", run_.ipopt_status = "optimal";
        break;
      case Ipopt::STOP_AT_ACCEPTABLE_POINT:
        run_.status = "solved", run_.ipopt_status = "acceptable";
        break;
      case Ipopt::MAXITER_EXCEEDED:
      case Ipopt::CPUTIME_EXCEEDED:
        run_.status = "max_iterations", run_.ipopt_status = "maximum iterations exceeded";
        break;
      case Ipopt::LOCAL_INFEASIBILITY:
        run_.status = "infeasible", run_.ipopt_status = "converged to an infeasible point";
        break;
      case Ipopt::USER_REQUESTED_STOP:
        run_.status = "stopped", run_.ipopt_status = "user requested stop";
        break;
      case Ipopt::DIVERGING_ITERATES:
        run_.status = "diverging", run_.ipopt_status = "diverging iterates";
        break;
      case Ipopt::RESTORATION_FAILURE:
        run_.status = "restoration_failed", run_.ipopt_status = "restoration failed";
        break;
      case Ipopt::STOP_AT_TINY_STEP:
        run_.status = "tiny_step", run_.ipopt_status = "search direction too small";
        break;
      default:
        run_.status = "error", run_.ipopt_status = "solver error";
        break;
    }
  }

 private:
  /// Ipopt's current x, which is the TNLP's x here: no scaling (nlp_scaling_method none) and no
  /// fixed variables (no variable has equal bounds); the dimension check guards that.
  bool current(const Ipopt::IpoptData* ip_data, std::vector<double>& out) const {
    if (!ip_data || !IsValid(ip_data->curr())) return false;
    const auto* x = dynamic_cast<const Ipopt::DenseVector*>(Ipopt::GetRawPtr(ip_data->curr()->x()));
    if (!x || x->Dim() != nlp_.variable_count()) return false;
    const double* values = x->ExpandedValues();
    out.assign(values, values + x->Dim());
    return true;
  }

  Nlp& nlp_;
  const std::vector<double>* start_;
  const std::function<bool(const IpoptIteration&)>& observe_;
  IpoptRun& run_;
};

/// Ipopt's options for our NLPs: the settings, and the fixed choices that suit a sum of squared
/// wrenches under keyframe bounds (why each, and what was measured: docs/optimizer.md,
/// "Ipopt's settings").
void set_options(Ipopt::OptionsList& o, const IpoptSettings& s, bool has_hessian) {
  o.SetIntegerValue("print_level", s.verbose ? 5 : 0);
  o.SetStringValue("sb", "yes");  // no banner
  o.SetIntegerValue("max_iter", std::max(0, s.max_iterations));
  o.SetNumericValue("tol", s.tolerance);
  o.SetStringValue("mu_strategy", "adaptive");
  // Keyframe rows are in units of their tolerance with bounds 2 % inside it: an "optimal" exit
  // may violate them by 1e-6 of a tolerance.
  o.SetNumericValue("constr_viol_tol", 1e-6);
  // The objective keeps its units (N²), so that its relative change means what it says.
  o.SetStringValue("nlp_scaling_method", "none");
  // A descent step on J is accepted while the keyframes are violated by less than 0.3 of a
  // tolerance, instead of trading the root force for tiny keyframe violations.
  o.SetNumericValue("delta", 1e-8);
  o.SetNumericValue("theta_min_fact", 0.3);
  if (s.objective_change_tolerance > 0) {
    o.SetNumericValue("acceptable_obj_change_tol", s.objective_change_tolerance);
    o.SetIntegerValue("acceptable_iter", s.acceptable_iterations);
    o.SetNumericValue("acceptable_constr_viol_tol", s.acceptable_constraint_violation);
    // The objective-change and feasibility tests decide; the NLP error (a gradient norm in N²
    // per radian, unscaled) does not.
    o.SetNumericValue("acceptable_tol", 1e20);
  } else {
    o.SetIntegerValue("acceptable_iter", 0);
  }
  if (!s.derivative_test_file.empty()) {
    o.SetStringValue("derivative_test", "first-order");
    // A coarse check of the plumbing: one-sided differences cannot resolve J's derivatives
    // (the exact ones are checked by central differences in the tests).
    o.SetNumericValue("derivative_test_perturbation", 1e-7);
    o.SetNumericValue("point_perturbation_radius", 0.0);  // at the given point
    o.SetNumericValue("derivative_test_tol", 2e-2);
    o.SetStringValue("output_file", s.derivative_test_file);
    o.SetIntegerValue("file_print_level", 5);
  }
  // MUMPS on a banded Hessian bordered by a few time columns and keyframe rows: approximate
  // minimum degree finds the band's order; no scaling passes; refinement only when needed.
  o.SetIntegerValue("mumps_pivot_order", 0);
  o.SetIntegerValue("mumps_scaling", 0);
  o.SetIntegerValue("mumps_permuting_scaling", 0);
  o.SetIntegerValue("min_refinement_steps", 0);
  if (!has_hessian) o.SetStringValue("hessian_approximation", "limited-memory");
  if (s.warm_start) {
    o.SetNumericValue("mu_init", 1e-4);
    o.SetNumericValue("bound_push", 1e-6);
    o.SetNumericValue("bound_frac", 1e-6);
  }
}

}  // namespace

IpoptRun run_ipopt(Nlp& nlp, const IpoptSettings& settings, const std::vector<double>* start,
                   const std::function<bool(const IpoptIteration&)>& observe) {
  IpoptRun run;
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  set_options(*app->Options(), settings, nlp.has_hessian());
  // "": no options file. Ipopt would otherwise read ./ipopt.opt, and a stray file in the user's
  // folder would silently change the solver (the same input must give the same output).
  if (app->Initialize("") != Ipopt::Solve_Succeeded) {
    run.ipopt_status = "initialisation failed";
    return run;
  }
  Ipopt::SmartPtr<NlpAdapter> adapter = new NlpAdapter(nlp, start, observe, run);
  app->OptimizeTNLP(adapter);
  return run;
}

}  // namespace saltus
