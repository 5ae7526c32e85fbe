#pragma once
/// @file
/// The relaxed model's objective (paper eq. 1): J = (1/T) ∫ Σ F_i² dt, the mean squared root
/// wrench, by quadrature over sample times; its Gauss–Newton curvature is damped by μ·J·I
/// (Levenberg–Marquardt, μ from AdaptiveDamping: light segments barely change the root force, so
/// undamped Gauss–Newton steps would swing them on a linear model that no longer holds).

#include <Eigen/Core>
#include <vector>

#include "saltus/optim/adaptive_damping.h"
#include "saltus/optim/terms/objective_term.h"

namespace saltus {

class RootWrenchTerm : public ObjectiveTerm {
 public:
  /// @param times    sample times on [0, T]
  /// @param weights  quadrature weights divided by T, one per time
  /// @param damping  μ's rule and state; null for no damping
  RootWrenchTerm(std::vector<double> times, std::vector<double> weights,
                 const AdaptiveDamping* damping);

  std::string name() const override { return "root wrench"; }
  double value(NlpEvaluations& at) override;
  void add_gradient(NlpEvaluations& at, double* gradient) override;
  void add_curvature(NlpEvaluations& at, double factor, const HessianBand& band,
                     double* values) override;
  std::vector<double> residuals(NlpEvaluations& at) override;

  const std::vector<double>& times() const { return samples_.times(); }
  /// Computes the derivatives at the current point now (before anything reads the values).
  void prepare_derivatives(NlpEvaluations& at) { samples_.jacobians(at); }

 private:
  WrenchSamples samples_;
  std::vector<double> weights_;
  const AdaptiveDamping* damping_;
  /// add_curvature's workspace: the stacked rows per thread, the block per knot span.
  std::vector<Eigen::MatrixXd> stacked_rows_, span_blocks_;
  std::vector<std::pair<int, int>> spans_;  ///< [first, end) samples of each knot span
};

}  // namespace saltus
