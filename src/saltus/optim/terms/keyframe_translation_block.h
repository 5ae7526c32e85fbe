#pragma once
/// @file
/// Paper eq. (2): |B_d(t_i) − B̄_d(t_i)| <= ε1 for every keyframe i and coordinate d, one row each,
/// stated in units of ε1 with bounds kKeyframeBoundMargin inside it (see motion_nlp.h).

#include "saltus/optim/keyframe_targets.h"
#include "saltus/optim/terms/constraint_block.h"

namespace saltus {

class KeyframeTranslationBlock : public ConstraintBlock {
 public:
  /// @param tolerance  ε1, m
  /// @param bound      the rows' bound in units of ε1 (1 − margin)
  KeyframeTranslationBlock(const TrajectoryLayout& layout, const KeyframeTargets& targets,
                           double tolerance, double bound);

  std::string name() const override { return "keyframe translation"; }
  int rows() const override { return 3 * layout_.keyframe_count; }
  void bounds(double* lower, double* upper) const override;
  std::vector<std::vector<int>> sparsity() const override;
  void values(NlpEvaluations& at, double* g) override;
  void jacobian(NlpEvaluations& at, double* values) override;

 private:
  TrajectoryLayout layout_;
  const KeyframeTargets& targets_;
  double scale_;  ///< 1/ε1
  double bound_;
  std::vector<std::vector<int>> sparsity_;
};

}  // namespace saltus
