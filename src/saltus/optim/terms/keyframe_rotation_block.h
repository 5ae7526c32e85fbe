#pragma once
/// @file
/// Paper eq. (3): ‖Q_k(t_i) − Q̄_k‖² <= ε2² for every keyframe i and joint k (sign-aligned), one
/// row each, in units of ε2² with the bound kKeyframeBoundMargin inside it (see motion_nlp.h).
/// Its Gauss–Newton curvature 2·JᵀJ joins the Hessian where the multiplier is positive.

#include "saltus/optim/keyframe_targets.h"
#include "saltus/optim/terms/constraint_block.h"

namespace saltus {

class KeyframeRotationBlock : public ConstraintBlock {
 public:
  /// @param tolerance  ε2
  /// @param bound      the rows' bound in units of ε2² (1 − margin)
  KeyframeRotationBlock(const TrajectoryLayout& layout, const KeyframeTargets& targets,
                        double tolerance, double bound);

  std::string name() const override { return "keyframe rotation"; }
  int rows() const override { return layout_.keyframe_count * layout_.segment_count; }
  void bounds(double* lower, double* upper) const override;
  std::vector<std::vector<int>> sparsity() const override;
  void values(NlpEvaluations& at, double* g) override;
  void jacobian(NlpEvaluations& at, double* values) override;
  void add_curvature(NlpEvaluations& at, const double* multipliers, const HessianBand& band,
                     double* values) override;

 private:
  TrajectoryLayout layout_;
  const KeyframeTargets& targets_;
  double scale_;  ///< 1/ε2²
  double bound_;
  std::vector<std::vector<int>> sparsity_;
};

}  // namespace saltus
