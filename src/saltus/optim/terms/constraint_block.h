#pragma once
/// @file
/// A block of the optimiser's constraint rows (Drake's constraints as bindings): MotionNlp stacks
/// a list of them. Each declares its rows' bounds and Jacobian sparsity once, then gives values
/// and Jacobian entries at any point, and may add a positive semi-definite part of Σ λ·∇²g to
/// the Hessian.
///
/// Adding a block: a new file here, its registration in MotionNlp's constructor, and a
/// finite-difference test of its Jacobian (tests/unit/optim/terms).

#include <string>
#include <vector>

#include "saltus/optim/hessian_band.h"
#include "saltus/optim/nlp_evaluations.h"

namespace saltus {

class ConstraintBlock {
 public:
  virtual ~ConstraintBlock() = default;

  virtual std::string name() const = 0;
  virtual int rows() const = 0;
  /// Row bounds; ±kUnbounded (nlp.h) for none.
  virtual void bounds(double* lower, double* upper) const = 0;
  /// The variables each row depends on, row by row: the Jacobian's sparsity.
  virtual std::vector<std::vector<int>> sparsity() const = 0;
  /// g at the current point of `at`.
  virtual void values(NlpEvaluations& at, double* g) = 0;
  /// Jacobian entries in sparsity() order, row by row.
  virtual void jacobian(NlpEvaluations& at, double* values) = 0;
  /// values += a positive semi-definite part of Σ_r multipliers[r]·∇²g_r; default none.
  virtual void add_curvature(NlpEvaluations& /*at*/, const double* /*multipliers*/,
                             const HessianBand& /*band*/, double* /*values*/) {}
};

/// The entry of a local Jacobian (weighted over its rows) for variable `column`, 0 if the
/// quantity does not depend on it at this point.
template <int Rows>
double local_derivative(const LocalJacobian<Rows>& jac,
                        const Eigen::Matrix<double, 1, Rows>& weights, int column) {
  const int local = column - jac.first_control_variable;
  if (local >= 0 && local < jac.control.cols()) return weights * jac.control.col(local);
  for (int s = 0; s < jac.time_count; ++s)
    if (jac.time_variable[s] == column) return weights * jac.time.col(s);
  return 0.0;
}

}  // namespace saltus
