#pragma once
/// @file
/// The strict model's constraints (classic spacetime constraints): |F_i(t_s)| <= ε for every
/// component of the root wrench at every sample time, six rows per sample. Their curvature is not
/// available and is left out of the Hessian.

#include "saltus/optim/terms/constraint_block.h"

namespace saltus {

class ForceBoundBlock : public ConstraintBlock {
 public:
  /// @param earliest_knots, latest_knots  the knots with every keyframe time at its lower and at
  ///        its upper bound: a sample's row covers every span it can reach as the times move
  /// @param epsilon  the bound, N or N·m
  ForceBoundBlock(const TrajectoryLayout& layout, std::vector<double> times,
                  const std::vector<double>& earliest_knots,
                  const std::vector<double>& latest_knots, double epsilon);

  std::string name() const override { return "force bounds"; }
  int rows() const override { return 6 * samples_.size(); }
  void bounds(double* lower, double* upper) const override;
  std::vector<std::vector<int>> sparsity() const override { return sparsity_; }
  void values(NlpEvaluations& at, double* g) override;
  void jacobian(NlpEvaluations& at, double* values) override;

 private:
  WrenchSamples samples_;
  double epsilon_;
  std::vector<std::vector<int>> sparsity_;
};

}  // namespace saltus
