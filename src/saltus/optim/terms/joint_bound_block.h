#pragma once
/// @file
/// Human joints as constraints: |n_j(t)| <= b_j and, when force bounds are given,
/// |f_j(t)| <= c_j for every non-root joint j at nodes on every knot span (n_j, f_j the moment
/// and force the joint carries, inverse dynamics). optimize_motion's polish sets them to a
/// multiple of the interpolated input's peaks at that joint, so the optimised motion cannot buy
/// its root residual with a joint working harder than the input asked of it. Least joint effort
/// (joint_load_term.h) only prefers small loads on average; without the bounds one joint's peak
/// still rose to 2-3 times the input's (docs/optimizer.md, "Joint bounds").
///
/// A row is |n_j|²/b_j² <= 1 (smooth, unlike |n_j|), then |f_j|²/c_j² <= 1; nodes at
/// kNodeFractions of every span (kEndSpanNodes evenly on the first and the last) and the last
/// span's end, moving with the knots. A row's columns are the root translation's and those of the
/// segments that move that joint's load (joint_wrench_depends_on: the joint's ancestors and its
/// subtree), not the whole body's: a wrist's row leaves the legs out, which keeps the KKT system
/// the solver factors sparse. Their Gauss–Newton curvature joins the Hessian, as the keyframe
/// rows' does.

#include <array>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/optim/terms/constraint_block.h"

namespace saltus {

class JointBoundBlock : public ConstraintBlock {
 public:
  /// Where on each knot span (ξ) the loads are bounded.
  static constexpr std::array<double, 2> kNodeFractions = {0.0, 0.5};
  /// ... and on the first and last spans, where the clamped spline's ends let a joint's load
  /// rise between two nodes: on the exact flights the loads that passed the bound peaked
  /// 0.01-0.11 s after take-off, between the first span's nodes (docs/optimizer.md).
  static constexpr int kEndSpanNodes = 6;
  /// The nodes' ξ on one span: kNodeFractions, or kEndSpanNodes evenly from 0 on an end span.
  static std::vector<double> node_fractions(bool end_span);

  /// @param moment_bounds  b_j for each non-root joint in model order, N·m (each > 0)
  /// @param force_bounds   c_j likewise, N; empty: the forces are free
  JointBoundBlock(const BodyModel& model, const TrajectoryLayout& layout,
                  std::vector<double> moment_bounds, std::vector<double> force_bounds = {});

  std::string name() const override { return "joint bounds"; }
  int rows() const override { return static_cast<int>(nodes_.size() * limits_.size()); }
  void bounds(double* lower, double* upper) const override;
  std::vector<std::vector<int>> sparsity() const override { return sparsity_; }
  void values(NlpEvaluations& at, double* g) override;
  void jacobian(NlpEvaluations& at, double* values) override;
  void add_curvature(NlpEvaluations& at, const double* multipliers, const HessianBand& band,
                     double* values) override;

 private:
  struct Node {
    int span = 3;
    double xi = 0.0;
  };
  /// One row per node: the three rows of the joint's loads it bounds and by what.
  struct Limit {
    int first_row = 0;
    double bound = 1.0;
  };
  std::vector<Node> nodes_;
  std::vector<Limit> limits_;
  int rows_per_joint_ = 3;
  std::vector<std::vector<int>> sparsity_;
  std::vector<Eigen::VectorXd> loads_;
  std::vector<LocalJacobian<Eigen::Dynamic>> jacobians_;
  long jacobians_generation_ = -1;
  std::vector<Eigen::MatrixXd> stacked_rows_, node_blocks_;
  const std::vector<LocalJacobian<Eigen::Dynamic>>& jacobians(NlpEvaluations& at);
};

}  // namespace saltus
