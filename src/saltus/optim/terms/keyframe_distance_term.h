#pragma once
/// @file
/// The strict model's objective: Σ_i ‖B(t_i) − B̄_i‖² + Σ_i Σ_k ‖Q_k(t_i) − Q̄_k‖², how far the
/// motion is from its keyframes (classic spacetime constraints minimise such a distance while
/// the force bounds hold). Exact Gauss–Newton at zero distance.

#include "saltus/optim/keyframe_targets.h"
#include "saltus/optim/terms/objective_term.h"

namespace saltus {

class KeyframeDistanceTerm : public ObjectiveTerm {
 public:
  explicit KeyframeDistanceTerm(const KeyframeTargets& targets) : targets_(targets) {}

  std::string name() const override { return "keyframe distance"; }
  double value(NlpEvaluations& at) override;
  void add_gradient(NlpEvaluations& at, double* gradient) override;
  void add_curvature(NlpEvaluations& at, double factor, const HessianBand& band,
                     double* values) override;
  std::vector<double> residuals(NlpEvaluations& at) override;

 private:
  /// Jacobian of B(t_i) − B̄(t_i): the target moves along the parabola with the keyframe's time.
  LocalJacobian<3> translation_residual_jacobian(NlpEvaluations& at, int keyframe) const;
  const KeyframeTargets& targets_;
};

}  // namespace saltus
