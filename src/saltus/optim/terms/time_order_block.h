#pragma once
/// @file
/// Paper eq. (4): t_{i+1} − t_i >= gap for every pair of consecutive keyframes, one row each
/// (only when the keyframe times are variables).

#include "saltus/optim/terms/constraint_block.h"

namespace saltus {

class TimeOrderBlock : public ConstraintBlock {
 public:
  /// @param gap  the smallest interval between two keyframes, s
  TimeOrderBlock(const TrajectoryLayout& layout, double gap) : layout_(layout), gap_(gap) {}

  std::string name() const override { return "time order"; }
  int rows() const override { return layout_.keyframe_count - 1; }
  void bounds(double* lower, double* upper) const override;
  std::vector<std::vector<int>> sparsity() const override;
  void values(NlpEvaluations& at, double* g) override;
  void jacobian(NlpEvaluations& at, double* values) override;

 private:
  TrajectoryLayout layout_;
  double gap_;
};

}  // namespace saltus
