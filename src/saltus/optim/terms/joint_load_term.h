#pragma once
/// @file
/// Least joint effort: w·(1/T)∫ Σ_j |n_j(t)|² dt over every non-root joint j, where n_j is the
/// moment the joint carries (inverse dynamics, child frame, N·m) and w is in N² of root wrench
/// per (N·m)² of joint moment. The root wrench alone leaves the optimiser free to buy its last
/// newtons with internal kicks — a foot or forearm whipped within the first or last few
/// hundredths of a second, the root untouched and the joint at 10-40 times the input's load
/// (docs/optimizer.md, "Joint loads"). Among motions with the same root residual this term
/// prefers the one whose joints work least: the criterion of classic spacetime constraints,
/// and what a body does in flight.
///
/// Integrated by 3-point Gauss–Lobatto on every knot span of the starting knots (ends included:
/// the kicks peak at the flight's ends) with fixed weights, the nodes moving with the knots.
/// Exact derivatives from the joint moments' (root_wrench_derivatives.h); Gauss–Newton curvature
/// stacked per span, inside the Hessian's band like the root wrench's.

#include <Eigen/Core>
#include <vector>

#include "saltus/optim/terms/objective_term.h"

namespace saltus {

class JointLoadTerm : public ObjectiveTerm {
 public:
  /// @param knots     the starting knot vector (the nodes' spans and fixed weights)
  /// @param duration  T, s
  /// @param weight    w, N² per (N·m)²
  /// @param scales    s_j, each non-root joint's moment counted as s_j·n_j (empty: all 1)
  JointLoadTerm(const TrajectoryLayout& layout, const std::vector<double>& knots, double duration,
                double weight, std::vector<double> scales = {});

  std::string name() const override { return "joint loads"; }
  double value(NlpEvaluations& at) override;
  void add_gradient(NlpEvaluations& at, double* gradient) override;
  void add_curvature(NlpEvaluations& at, double factor, const HessianBand& band,
                     double* values) override;
  std::vector<double> residuals(NlpEvaluations& at) override;

 private:
  struct Node {
    int span = 3;
    double xi = 0.0;
    double weight = 0.0;  ///< w·ω·h/T on the starting knots
  };
  const std::vector<Eigen::VectorXd>& values(NlpEvaluations& at);
  const std::vector<LocalJacobian<Eigen::Dynamic>>& jacobians(NlpEvaluations& at);
  /// Multiplies joint j's three rows of `rows` (values or a Jacobian) by s_j.
  template <typename Rows>
  void scale_rows(Rows& rows) const;

  std::vector<Node> nodes_;
  std::vector<double> scales_;
  std::vector<std::pair<int, int>> spans_;  ///< [first, end) nodes of each knot span
  std::vector<Eigen::VectorXd> values_;
  std::vector<LocalJacobian<Eigen::Dynamic>> jacobians_;
  long values_generation_ = -1, jacobians_generation_ = -1;
  std::vector<Eigen::MatrixXd> stacked_rows_, span_blocks_;
};

}  // namespace saltus
