#pragma once
// Small NLPs written out by hand for the solver's tests (unit/optim/solve_policy_test.cpp,
// ipopt_solver_test.cpp): problems with known answers and problems built so that a policy of
// the solve has to act. Each records every iterate and Hessian request the solver made.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "saltus/optim/nlp.h"

namespace saltus::test {

/// One iterate of a solve as the NLP saw it: step_taken() marks it, and its x is the last point
/// the objective was evaluated at (Ipopt evaluates a trial point, accepts it, then reports it; the
/// tests check this against the objective in the progress report of the same iteration).
struct Iterate {
  int run = 0;        ///< 0 for the first Ipopt run, 1 after the first restart, ...
  int iteration = 0;  ///< within its run (StepTaken::iteration)
  std::vector<double> x;
  double objective = 0.0;
  double violation = 0.0;  ///< largest constraint violation at x, computed here
};

/// A small NLP with dense derivatives. Subclasses state the problem; this class answers Ipopt's
/// sparse-triplet questions (every entry a nonzero, the Hessian's lower triangle) and records
/// what the solver did: every iterate and every Hessian request.
class DenseNlp : public Nlp {
 public:
  DenseNlp(std::vector<double> x_lower, std::vector<double> x_upper, std::vector<double> g_lower,
           std::vector<double> g_upper, std::vector<double> start)
      : x_lower_(std::move(x_lower)),
        x_upper_(std::move(x_upper)),
        g_lower_(std::move(g_lower)),
        g_upper_(std::move(g_upper)),
        start_(std::move(start)) {}

  /// The problem: f, ∇f, g, the m×n Jacobian of g (row-major) and the full n×n matrix
  /// σ∇²f + Σ λ_i ∇²g_i (only its lower triangle is passed on).
  virtual double f(const double* x) const = 0;
  virtual void grad_f(const double* x, double* out) const = 0;
  virtual void g(const double*, double*) const {}
  virtual void jac_g(const double*, double*) const {}
  virtual void hess_lagrangian(const double* x, double sigma, const double* lambda,
                               Eigen::MatrixXd& out) const = 0;

  int variable_count() const override { return static_cast<int>(start_.size()); }
  int constraint_count() const override { return static_cast<int>(g_lower_.size()); }
  void bounds(double* xl, double* xu, double* gl, double* gu) const override {
    std::copy(x_lower_.begin(), x_lower_.end(), xl);
    std::copy(x_upper_.begin(), x_upper_.end(), xu);
    std::copy(g_lower_.begin(), g_lower_.end(), gl);
    std::copy(g_upper_.begin(), g_upper_.end(), gu);
  }
  void initial_point(double* x) const override { std::copy(start_.begin(), start_.end(), x); }

  double objective(const double* x) override {
    last_x_.assign(x, x + variable_count());
    last_objective_ = f(x);
    return last_objective_;
  }
  void gradient(const double* x, double* out) override { grad_f(x, out); }
  void constraints(const double* x, double* out) override { g(x, out); }

  int jacobian_nonzeros() const override { return variable_count() * constraint_count(); }
  void jacobian_structure(int* rows, int* columns) const override {
    for (int i = 0, k = 0; i < constraint_count(); ++i)
      for (int j = 0; j < variable_count(); ++j, ++k)
        rows[k] = i, columns[k] = j;
  }
  void jacobian_values(const double* x, double* values) override { jac_g(x, values); }

  bool has_hessian() const override { return exact_hessian; }
  int hessian_nonzeros() const override { return variable_count() * (variable_count() + 1) / 2; }
  void hessian_structure(int* rows, int* columns) const override {
    ++hessian_structure_calls;
    for (int i = 0, k = 0; i < variable_count(); ++i)
      for (int j = 0; j <= i; ++j, ++k)
        rows[k] = i, columns[k] = j;
  }
  void hessian_values(const double* x, double sigma, const double* lambda,
                      double* values) override {
    hessian_points.emplace_back(x, x + variable_count());
    hessian_after_iterate.push_back(static_cast<int>(iterates.size()) - 1);
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(variable_count(), variable_count());
    hess_lagrangian(x, sigma, lambda, h);
    for (int i = 0, k = 0; i < variable_count(); ++i)
      for (int j = 0; j <= i; ++j, ++k)
        values[k] = h(i, j);
  }

  void step_taken(const StepTaken& step) override {
    if (step.iteration == 0) ++run_;
    Iterate it;
    it.run = run_;
    it.iteration = step.iteration;
    it.x = last_x_;
    it.objective = last_objective_;
    it.violation = violation(last_x_.data());
    iterates.push_back(it);
    steps.push_back(step);
  }

  /// Largest distance of g(x) from [g_lower, g_upper].
  double violation(const double* x) const {
    std::vector<double> values(g_lower_.size());
    g(x, values.data());
    double worst = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i)
      worst = std::max({worst, g_lower_[i] - values[i], values[i] - g_upper_[i]});
    return worst;
  }

  /// The iterates of one run, in order.
  std::vector<Iterate> run(int index) const {
    std::vector<Iterate> out;
    std::copy_if(iterates.begin(), iterates.end(), std::back_inserter(out),
                 [index](const Iterate& it) { return it.run == index; });
    return out;
  }

  bool exact_hessian = true;
  std::vector<Iterate> iterates;
  std::vector<StepTaken> steps;
  std::vector<std::vector<double>> hessian_points;
  std::vector<int> hessian_after_iterate;  ///< per Hessian request: the latest iterate's index
  mutable int hessian_structure_calls = 0;

 private:
  std::vector<double> x_lower_, x_upper_, g_lower_, g_upper_, start_;
  std::vector<double> last_x_;
  double last_objective_ = 0.0;
  int run_ = -1;
};

// ---------------------------------------------------------------------------------------------
// Problems with known answers.

/// Hock & Schittkowski (1981), problem 71: min x1·x4·(x1 + x2 + x3) + x3 subject to
/// x1·x2·x3·x4 >= 25, x1² + x2² + x3² + x4² = 40, 1 <= x <= 5, from (1, 5, 5, 1). Published
/// optimum x* = (1, 4.74299963, 3.82114998, 1.37940829), f* = 17.0140173.
class Hs71 : public DenseNlp {
 public:
  Hs71() : DenseNlp({1, 1, 1, 1}, {5, 5, 5, 5}, {25, 40}, {kUnbounded, 40}, {1, 5, 5, 1}) {}
  double f(const double* x) const override { return x[0] * x[3] * (x[0] + x[1] + x[2]) + x[2]; }
  void grad_f(const double* x, double* out) const override {
    out[0] = x[3] * (2 * x[0] + x[1] + x[2]);
    out[1] = x[0] * x[3];
    out[2] = x[0] * x[3] + 1;
    out[3] = x[0] * (x[0] + x[1] + x[2]);
  }
  void g(const double* x, double* out) const override {
    out[0] = x[0] * x[1] * x[2] * x[3];
    out[1] = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3];
  }
  void jac_g(const double* x, double* out) const override {
    out[0] = x[1] * x[2] * x[3];
    out[1] = x[0] * x[2] * x[3];
    out[2] = x[0] * x[1] * x[3];
    out[3] = x[0] * x[1] * x[2];
    for (int j = 0; j < 4; ++j)
      out[4 + j] = 2 * x[j];
  }
  void hess_lagrangian(const double* x, double s, const double* l,
                       Eigen::MatrixXd& h) const override {
    h(0, 0) = s * 2 * x[3] + l[1] * 2;
    h(1, 1) = h(2, 2) = h(3, 3) = l[1] * 2;
    h(1, 0) = s * x[3] + l[0] * x[2] * x[3];
    h(2, 0) = s * x[3] + l[0] * x[1] * x[3];
    h(2, 1) = l[0] * x[0] * x[3];
    h(3, 0) = s * (2 * x[0] + x[1] + x[2]) + l[0] * x[1] * x[2];
    h(3, 1) = s * x[0] + l[0] * x[0] * x[2];
    h(3, 2) = s * x[0] + l[0] * x[0] * x[1];
  }
  static constexpr double kOptimum[4] = {1.0, 4.74299963, 3.82114998, 1.37940829};
  static constexpr double kObjective = 17.0140173;
};

/// min ½‖x − c‖², c = (2, −1, 0.8, 3), subject to x1 + x2 + x3 + x4 <= 2.5 and 0 <= x <= 1.
/// KKT by hand: x_i = clamp(c_i − λ, 0, 1) with Σ x_i = 2.5 gives λ = 0.3 and
/// x* = (1, 0, 0.5, 1): x1 and x4 at their upper bounds (multipliers 0.7 and 1.7), x2 at its
/// lower bound (1.3), x3 free, the sum constraint active; f* = ½(1 + 1 + 0.09 + 4) = 3.045.
class BoundedQp : public DenseNlp {
 public:
  explicit BoundedQp(std::vector<double> start = {0.5, 0.5, 0.5, 0.5})
      : DenseNlp({0, 0, 0, 0}, {1, 1, 1, 1}, {-kUnbounded}, {2.5}, {std::move(start)}) {}
  double f(const double* x) const override {
    double sum = 0.0;
    for (int i = 0; i < 4; ++i)
      sum += 0.5 * (x[i] - kTarget[i]) * (x[i] - kTarget[i]);
    return sum;
  }
  void grad_f(const double* x, double* out) const override {
    for (int i = 0; i < 4; ++i)
      out[i] = x[i] - kTarget[i];
  }
  void g(const double* x, double* out) const override { out[0] = x[0] + x[1] + x[2] + x[3]; }
  void jac_g(const double*, double* out) const override { std::fill(out, out + 4, 1.0); }
  void hess_lagrangian(const double*, double s, const double*, Eigen::MatrixXd& h) const override {
    h.diagonal().setConstant(s);
  }
  static constexpr double kTarget[4] = {2.0, -1.0, 0.8, 3.0};
  static constexpr double kOptimum[4] = {1.0, 0.0, 0.5, 1.0};
  static constexpr double kObjective = 3.045;
};

/// Rosenbrock's valley, (1 − x1)² + 100·(x2 − x1²)², unconstrained, from (−1.2, 1): the minimum
/// is f(1, 1) = 0 at the end of a long curved valley that gradient steps crawl along.
class Rosenbrock : public DenseNlp {
 public:
  Rosenbrock()
      : DenseNlp({-kUnbounded, -kUnbounded}, {kUnbounded, kUnbounded}, {}, {}, {-1.2, 1}) {}
  double f(const double* x) const override {
    return (1 - x[0]) * (1 - x[0]) + 100 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]);
  }
  void grad_f(const double* x, double* out) const override {
    out[0] = -2 * (1 - x[0]) - 400 * x[0] * (x[1] - x[0] * x[0]);
    out[1] = 200 * (x[1] - x[0] * x[0]);
  }
  void hess_lagrangian(const double* x, double s, const double*,
                       Eigen::MatrixXd& h) const override {
    h(0, 0) = s * (2 - 400 * x[1] + 1200 * x[0] * x[0]);
    h(1, 0) = s * -400 * x[0];
    h(1, 1) = s * 200;
  }
};

/// min x1² + x2² subject to x1 + x2 >= 3 and 0 <= x <= 1: no point meets the constraint.
class Infeasible : public DenseNlp {
 public:
  Infeasible() : DenseNlp({0, 0}, {1, 1}, {3}, {kUnbounded}, {0.5, 0.5}) {}
  double f(const double* x) const override { return x[0] * x[0] + x[1] * x[1]; }
  void grad_f(const double* x, double* out) const override {
    out[0] = 2 * x[0];
    out[1] = 2 * x[1];
  }
  void g(const double* x, double* out) const override { out[0] = x[0] + x[1]; }
  void jac_g(const double*, double* out) const override { out[0] = out[1] = 1.0; }
  void hess_lagrangian(const double*, double s, const double*, Eigen::MatrixXd& h) const override {
    h.diagonal().setConstant(2 * s);
  }
};

// ---------------------------------------------------------------------------------------------
// Problems that make the adapter's policies act.

inline const std::vector<double> kFreeLower = {-kUnbounded, -kUnbounded};
inline const std::vector<double> kFreeUpper = {kUnbounded, kUnbounded};

/// 1 + (x1 − 1)⁴ + (x2 + 2)⁴, unconstrained, from (2, −1). Newton's method meets this degenerate
/// minimum only linearly (each step keeps 2/3 of the error), so the objective settles long before
/// the gradient reaches Ipopt's tolerance: the case the objective-change exit is for.
class FlatMinimum : public DenseNlp {
 public:
  FlatMinimum() : DenseNlp(kFreeLower, kFreeUpper, {}, {}, {2.0, -1.0}) {}
  double f(const double* x) const override {
    return 1 + std::pow(x[0] - 1, 4) + std::pow(x[1] + 2, 4);
  }
  void grad_f(const double* x, double* out) const override {
    out[0] = 4 * std::pow(x[0] - 1, 3);
    out[1] = 4 * std::pow(x[1] + 2, 3);
  }
  void hess_lagrangian(const double* x, double s, const double*,
                       Eigen::MatrixXd& h) const override {
    h(0, 0) = s * 12 * std::pow(x[0] - 1, 2);
    h(1, 1) = s * 12 * std::pow(x[1] + 2, 2);
  }
};

/// min −(3·x1 + 4·x2) subject to ε·(x1² + x2² − 1) = 0 with ε = 1e-4: the optimum is (0.6, 0.8)
/// on the unit circle, f* = −5. Started on the ray through the optimum at radius r0, every
/// iterate stays on that ray (the objective's gradient and the constraint's normal both lie on
/// it) and Newton's step on the constraint moves the radius as r ← (r² + 1) / 2r. From r0 = 0.1
/// the first step overshoots to r = 5.05, where f = −25.25 and the small ε leaves a violation of
/// only 2.45e-3, within the acceptable violation; every later iterate walks back to the circle
/// and is worse. A wander in miniature, with a path known in closed form.
class Overshoot : public DenseNlp {
 public:
  explicit Overshoot(double start_radius = 0.1)
      : DenseNlp(kFreeLower, kFreeUpper, {0.0}, {0.0}, {0.6 * start_radius, 0.8 * start_radius}) {}
  double f(const double* x) const override { return -(3 * x[0] + 4 * x[1]); }
  void grad_f(const double*, double* out) const override {
    out[0] = -3;
    out[1] = -4;
  }
  void g(const double* x, double* out) const override {
    out[0] = kScale * (x[0] * x[0] + x[1] * x[1] - 1);
  }
  void jac_g(const double* x, double* out) const override {
    out[0] = kScale * 2 * x[0];
    out[1] = kScale * 2 * x[1];
  }
  void hess_lagrangian(const double*, double, const double* l, Eigen::MatrixXd& h) const override {
    h.diagonal().setConstant(l[0] * kScale * 2);
  }
  static constexpr double kScale = 1e-4;
};

inline double radius(const std::vector<double>& x) {
  return std::hypot(x[0], x[1]);
}

}  // namespace saltus::test
