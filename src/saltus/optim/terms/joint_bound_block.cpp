#include "saltus/optim/terms/joint_bound_block.h"

#include <cmath>
#include <stdexcept>

#include "saltus/dynamics/joint_wrench_state_jacobian.h"
#include "saltus/optim/nlp.h"

namespace saltus {

JointBoundBlock::JointBoundBlock(const BodyModel& model, const TrajectoryLayout& layout,
                                 std::vector<double> moment_bounds,
                                 std::vector<double> force_bounds) {
  const std::size_t joints = static_cast<std::size_t>(layout.segment_count - 1);
  if (moment_bounds.size() != joints || (!force_bounds.empty() && force_bounds.size() != joints))
    throw std::invalid_argument("joint bounds: one per non-root joint");
  rows_per_joint_ = force_bounds.empty() ? 3 : 6;
  for (std::size_t j = 0; j < joints; ++j) {
    limits_.push_back({rows_per_joint_ * static_cast<int>(j), moment_bounds[j]});
    if (!force_bounds.empty())
      limits_.push_back({rows_per_joint_ * static_cast<int>(j) + 3, force_bounds[j]});
  }
  for (const Limit& limit : limits_)
    if (!(limit.bound > 0)) throw std::invalid_argument("joint bounds must be positive");

  const int last_span = layout.control_count() - 1;
  for (int span = 3; span <= last_span; ++span)
    for (const double xi : node_fractions(span == 3 || span == last_span))
      nodes_.push_back({span, xi});
  nodes_.push_back({last_span, 1.0});
  std::vector<int> time_variables;
  for (int i = 0; i < layout.keyframe_count; ++i)
    if (layout.time_variable(i) >= 0) time_variables.push_back(layout.time_variable(i));
  // Joint j's columns on four controls: the root translation (curve 0) and segment k's curve
  // (k + 1) where k moves j's load.
  std::vector<std::vector<int>> curves(joints);
  for (std::size_t j = 0; j < joints; ++j) {
    curves[j].push_back(0);
    for (int k = 0; k < layout.segment_count; ++k)
      if (joint_wrench_depends_on(model, static_cast<int>(j) + 1, k)) curves[j].push_back(k + 1);
  }
  for (const Node& node : nodes_)
    for (const Limit& limit : limits_) {
      std::vector<int> columns;
      for (int control = node.span - 3; control <= node.span; ++control)
        for (const int curve : curves[limit.first_row / rows_per_joint_])
          for (int dim = 0; dim < 3; ++dim)
            columns.push_back(layout.control_variable(curve, control, dim));
      columns.insert(columns.end(), time_variables.begin(), time_variables.end());
      sparsity_.push_back(columns);
    }
  loads_.resize(nodes_.size());
  jacobians_.resize(nodes_.size());
}

std::vector<double> JointBoundBlock::node_fractions(bool end_span) {
  if (!end_span) return {kNodeFractions.begin(), kNodeFractions.end()};
  std::vector<double> fractions;
  for (int k = 0; k < kEndSpanNodes; ++k)
    fractions.push_back(static_cast<double>(k) / kEndSpanNodes);
  return fractions;
}

void JointBoundBlock::bounds(double* lower, double* upper) const {
  for (int r = 0; r < rows(); ++r) {
    lower[r] = -kUnbounded;
    upper[r] = 1.0;
  }
}

void JointBoundBlock::values(NlpEvaluations& at, double* g) {
  at.for_each_range(static_cast<int>(nodes_.size()), [this](int, RootWrenchDerivatives& evaluator,
                                                            int begin, int end) {
    for (int n = begin; n < end; ++n)
      loads_[n] = rows_per_joint_ == 3
                      ? evaluator.joint_moments_on_span(nodes_[n].span, nodes_[n].xi)
                      : evaluator.joint_wrenches_on_span(nodes_[n].span, nodes_[n].xi);
  });
  int row = 0;
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    for (const Limit& limit : limits_)
      g[row++] = loads_[n].segment<3>(limit.first_row).squaredNorm() / (limit.bound * limit.bound);
}

const std::vector<LocalJacobian<Eigen::Dynamic>>& JointBoundBlock::jacobians(NlpEvaluations& at) {
  if (jacobians_generation_ == at.generation()) return jacobians_;
  at.for_each_range(static_cast<int>(nodes_.size()), [this](int, RootWrenchDerivatives& evaluator,
                                                            int begin, int end) {
    for (int n = begin; n < end; ++n) {
      if (rows_per_joint_ == 3)
        evaluator.joint_moments_jacobian_on_span(nodes_[n].span, nodes_[n].xi, jacobians_[n]);
      else
        evaluator.joint_wrenches_jacobian_on_span(nodes_[n].span, nodes_[n].xi, jacobians_[n]);
    }
  });
  jacobians_generation_ = at.generation();
  return jacobians_;
}

void JointBoundBlock::jacobian(NlpEvaluations& at, double* values) {
  const std::vector<LocalJacobian<Eigen::Dynamic>>& all = jacobians(at);
  int entry = 0, row = 0;
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    const LocalJacobian<Eigen::Dynamic>& jac = all[n];
    const int local_count = static_cast<int>(jac.control.cols());
    for (const Limit& limit : limits_) {
      // d(|v|²/b²) = 2·vᵀ·dv/b²: the node's three rows of this load weighted by that.
      const Eigen::RowVector3d weights =
          2.0 / (limit.bound * limit.bound) * jac.value.segment<3>(limit.first_row).transpose();
      for (int column : sparsity_[row++]) {
        const int local = column - jac.first_control_variable;
        double d = 0.0;
        if (local >= 0 && local < local_count) {
          d = weights * jac.control.block<3, 1>(limit.first_row, local);
        } else {
          for (int s = 0; s < jac.time_count; ++s)
            if (jac.time_variable[s] == column)
              d = weights * jac.time.block<3, 1>(limit.first_row, s);
        }
        values[entry++] = d;
      }
    }
  }
}

void JointBoundBlock::add_curvature(NlpEvaluations& at, const double* multipliers,
                                    const HessianBand& band, double* values) {
  // ∇²(|v|²/b²) ≈ 2·JᵀJ/b² (Gauss–Newton), counted where the multiplier makes it positive
  // semi-definite: without it the solver saw the bounds only through their gradients, and a start
  // far outside them (M1: a hip at 8.5 times its input) wandered for hundreds of iterations.
  const std::vector<LocalJacobian<Eigen::Dynamic>>& all = jacobians(at);
  const int count = static_cast<int>(nodes_.size());
  const int limits = static_cast<int>(limits_.size());
  node_blocks_.resize(nodes_.size());
  stacked_rows_.resize(at.parts());
  at.for_each_range(count, [&](int part, RootWrenchDerivatives&, int first, int end) {
    Eigen::MatrixXd& stacked = stacked_rows_[part];
    for (int n = first; n < end; ++n) {
      const LocalJacobian<Eigen::Dynamic>& jac = all[n];
      const int width = static_cast<int>(jac.control.cols());
      const int times = jac.time_count;
      stacked.setZero(3 * limits, width + times);
      for (int l = 0; l < limits; ++l) {
        const double lambda = multipliers[n * limits + l];
        if (!(lambda > 0)) continue;
        const Limit& limit = limits_[l];
        const double root_weight = std::sqrt(2.0 * lambda) / limit.bound;
        stacked.block(3 * l, 0, 3, width) =
            root_weight * jac.control.middleRows(limit.first_row, 3);
        stacked.block(3 * l, width, 3, times) =
            root_weight * jac.time.middleRows(limit.first_row, 3).leftCols(times);
      }
      Eigen::MatrixXd& block = node_blocks_[n];
      block.setZero(width + times, width + times);
      block.selfadjointView<Eigen::Lower>().rankUpdate(stacked.transpose());
    }
  });
  for (int n = 0; n < count; ++n) {
    const LocalJacobian<Eigen::Dynamic>& jac = all[n];
    band.add_span_block(node_blocks_[n], jac.first_control_variable,
                        static_cast<int>(jac.control.cols()), jac.time_count, jac.time_variable,
                        values);
  }
}

}  // namespace saltus
