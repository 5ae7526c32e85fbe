#include "saltus/optim/terms/force_bound_block.h"

#include "saltus/math/bspline_basis.h"

namespace saltus {

ForceBoundBlock::ForceBoundBlock(const TrajectoryLayout& layout, std::vector<double> times,
                                 const std::vector<double>& earliest_knots,
                                 const std::vector<double>& latest_knots, double epsilon)
    : samples_(std::move(times)), epsilon_(epsilon) {
  std::vector<int> time_variables;
  for (int i = 0; i < layout.keyframe_count; ++i)
    if (layout.time_variable(i) >= 0) time_variables.push_back(layout.time_variable(i));
  for (double t : samples_.times()) {
    const int first_span = find_span(latest_knots, t), last_span = find_span(earliest_knots, t);
    std::vector<int> columns;
    for (int v = layout.control_variable(0, first_span - 3, 0);
         v < layout.control_variable(0, last_span + 1, 0); ++v)
      columns.push_back(v);
    columns.insert(columns.end(), time_variables.begin(), time_variables.end());
    for (int component = 0; component < 6; ++component)
      sparsity_.push_back(columns);
  }
}

void ForceBoundBlock::bounds(double* lower, double* upper) const {
  for (int r = 0; r < rows(); ++r) {
    lower[r] = -epsilon_;
    upper[r] = epsilon_;
  }
}

void ForceBoundBlock::values(NlpEvaluations& at, double* g) {
  const std::vector<Vector6d>& wrench = samples_.values(at);
  int row = 0;
  for (const Vector6d& w : wrench)
    for (int c = 0; c < 6; ++c)
      g[row++] = w[c];
}

void ForceBoundBlock::jacobian(NlpEvaluations& at, double* values) {
  const std::vector<LocalJacobian<6>>& jacobians = samples_.jacobians(at);
  int entry = 0, row = 0;
  for (const LocalJacobian<6>& jac : jacobians)
    for (int c = 0; c < 6; ++c, ++row) {
      Eigen::Matrix<double, 1, 6> pick = Eigen::Matrix<double, 1, 6>::Zero();
      pick[c] = 1.0;
      for (int column : sparsity_[row])
        values[entry++] = local_derivative<6>(jac, pick, column);
    }
}

}  // namespace saltus
