#pragma once
/// @file
/// w·Σ‖δ‖² over the joints' control-point tangents δ (rad), relative to the interpolation the
/// optimiser starts from: smooth and convex, it makes the directions the root force hardly sees
/// (light limbs) well posed without bounds. w is in the objective's units per rad².

#include "saltus/optim/terms/objective_term.h"

namespace saltus {

class ProximityTerm : public ObjectiveTerm {
 public:
  ProximityTerm(const TrajectoryLayout& layout, double weight);

  std::string name() const override { return "proximity"; }
  double value(NlpEvaluations& at) override;
  void add_gradient(NlpEvaluations& at, double* gradient) override;
  void add_curvature(NlpEvaluations& at, double factor, const HessianBand& band,
                     double* values) override;
  std::vector<double> residuals(NlpEvaluations& at) override;

 private:
  /// The joints' tangent coordinates (every control variable but the root translation's).
  bool is_joint(int variable) const { return variable % layout_.curve_block() >= 3; }
  TrajectoryLayout layout_;
  double weight_;
};

}  // namespace saltus
