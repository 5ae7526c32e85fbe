#pragma once
/// @file
/// The relaxed model's objective (paper eq. 1): J = (1/T) ∫ Σ F_i² dt, the mean squared root
/// wrench, integrated span by span with Gauss–Lobatto nodes that move with the knots. A fixed
/// grid let the optimum put force between its samples once the knots were denser than the grid,
/// and Gauss–Legendre nodes (which avoid a span's ends) let it put force at the knots, where the
/// wrench's slope jumps; nodes tied to the spans, ends included, integrate each piece as a piece.
/// Its Gauss–Newton curvature is damped by μ·J·I (Levenberg–Marquardt, μ from AdaptiveDamping:
/// light segments barely change the root force, so undamped Gauss–Newton steps would swing them
/// on a linear model that no longer holds).

#include <Eigen/Core>
#include <vector>

#include "saltus/optim/adaptive_damping.h"
#include "saltus/optim/terms/objective_term.h"

namespace saltus {

class RootWrenchTerm : public ObjectiveTerm {
 public:
  /// @param nodes     the quadrature (SpanQuadrature: nodes on every knot span)
  /// @param duration  T, s (fixed: the first and last keyframe times do not move)
  /// @param damping   μ's rule and state; null for no damping
  /// @param moment_weight  each moment component's square counts this many times (1: J itself)
  RootWrenchTerm(SpanQuadrature nodes, double duration, const AdaptiveDamping* damping,
                 double moment_weight = 1.0);

  std::string name() const override { return "root wrench"; }
  double value(NlpEvaluations& at) override;
  /// J itself, whatever the moment weight.
  double unweighted_value(NlpEvaluations& at);
  void add_gradient(NlpEvaluations& at, double* gradient) override;
  void add_curvature(NlpEvaluations& at, double factor, const HessianBand& band,
                     double* values) override;
  std::vector<double> residuals(NlpEvaluations& at) override;

  /// The quadrature nodes' times at the current point of `at`.
  std::vector<double> times(NlpEvaluations& at) const;
  /// Computes the derivatives at the current point now (before anything reads the values).
  void prepare_derivatives(NlpEvaluations& at) { nodes_.jacobians(at); }

 private:
  /// Node n's weight (k_{s+1} − k_s)·ω/T at the current point.
  double weight(NlpEvaluations& at, int node) const;
  SpanQuadrature nodes_;
  double duration_;
  const AdaptiveDamping* damping_;
  /// √ of each component's weight: ones for the force, √moment_weight for the moment.
  Vector6d root_weights_;
  /// add_curvature's workspace: the stacked rows per thread, the block per knot span.
  std::vector<Eigen::MatrixXd> stacked_rows_, span_blocks_;
  std::vector<std::pair<int, int>> spans_;  ///< [first, end) samples of each knot span
};

}  // namespace saltus
