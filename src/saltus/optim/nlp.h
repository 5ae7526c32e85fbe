#pragma once
/// @file
/// A nonlinear program in the shape Ipopt wants, but with no Ipopt in it, so that every NLP can
/// be tested (values, derivatives, sparsity) on its own. Derivative arrays are sparse triplets;
/// the Hessian is the lower triangle of ∇²L = σ∇²f + Σ λ_i ∇²g_i.

namespace saltus {

/// How the solver reached its current iterate. Told before that iterate's Hessian is asked for.
struct StepTaken {
  int iteration = 0;           ///< of the current solver run; 0: the starting point
  int line_search_trials = 0;  ///< 1: the first trial step was accepted; more: it was cut back
  bool restoration = false;    ///< the step came from the feasibility restoration phase
};

class Nlp {
 public:
  virtual ~Nlp() = default;

  virtual int variable_count() const = 0;
  virtual int constraint_count() const = 0;
  /// Bounds; ±1e19 means unbounded (Ipopt's convention).
  virtual void bounds(double* x_lower, double* x_upper, double* g_lower, double* g_upper) const = 0;
  virtual void initial_point(double* x) const = 0;

  virtual double objective(const double* x) = 0;
  virtual void gradient(const double* x, double* gradient) = 0;
  virtual void constraints(const double* x, double* g) = 0;

  virtual int jacobian_nonzeros() const = 0;
  virtual void jacobian_structure(int* rows, int* columns) const = 0;
  virtual void jacobian_values(const double* x, double* values) = 0;

  /// False: the solver must approximate the Hessian (limited-memory quasi-Newton).
  virtual bool has_hessian() const = 0;
  virtual int hessian_nonzeros() const = 0;
  virtual void hessian_structure(int* rows, int* columns) const = 0;
  virtual void hessian_values(const double* x, double objective_factor, const double* multipliers,
                              double* values) = 0;

  /// Called once per solver iteration, before its Hessian; default: ignored. An NLP whose
  /// Hessian adapts to the solver's progress (MotionNlp's damping) listens here.
  virtual void step_taken(const StepTaken&) {}
};

inline constexpr double kUnbounded = 1e19;

}  // namespace saltus
