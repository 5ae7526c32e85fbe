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
  /// The translation part is multiplied by `translation_weight`, the rotation part by
  /// `rotation_weight` (1 and 1 in the strict model; the relaxed model's keyframe prior uses
  /// w/ε1² and w/ε2², a distance in units of the tolerances).
  explicit KeyframeDistanceTerm(const KeyframeTargets& targets, double translation_weight = 1.0,
                                double rotation_weight = 1.0)
      : targets_(targets),
        translation_weight_(translation_weight),
        rotation_weight_(rotation_weight) {}

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
  double translation_weight_;
  double rotation_weight_;
};

}  // namespace saltus
