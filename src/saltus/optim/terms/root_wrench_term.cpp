#include "saltus/optim/terms/root_wrench_term.h"

#include <cmath>

namespace saltus {

RootWrenchTerm::RootWrenchTerm(std::vector<double> times, std::vector<double> weights,
                               const AdaptiveDamping* damping)
    : samples_(std::move(times)), weights_(std::move(weights)), damping_(damping) {}

double RootWrenchTerm::value(NlpEvaluations& at) {
  const std::vector<Vector6d>& wrench = samples_.values(at);
  double j = 0.0;
  for (std::size_t s = 0; s < wrench.size(); ++s)
    j += weights_[s] * wrench[s].squaredNorm();
  return j;
}

void RootWrenchTerm::add_gradient(NlpEvaluations& at, double* gradient) {
  const std::vector<LocalJacobian<6>>& jacobians = samples_.jacobians(at);
  const std::vector<Vector6d>& wrench = samples_.values(at);
  for (std::size_t s = 0; s < jacobians.size(); ++s) {
    const LocalJacobian<6>& jac = jacobians[s];
    const Eigen::Matrix<double, 1, 6> w = 2.0 * weights_[s] * wrench[s].transpose();
    Eigen::Map<Eigen::RowVectorXd>(gradient + jac.first_control_variable, jac.control.cols()) +=
        w * jac.control;
    for (int p = 0; p < jac.time_count; ++p)
      gradient[jac.time_variable[p]] += w * jac.time.col(p);
  }
}

std::vector<double> RootWrenchTerm::residuals(NlpEvaluations& at) {
  const std::vector<Vector6d>& wrench = samples_.values(at);
  std::vector<double> r;
  for (std::size_t s = 0; s < wrench.size(); ++s)
    for (int c = 0; c < 6; ++c)
      r.push_back(std::sqrt(weights_[s]) * wrench[s][c]);
  return r;
}

void RootWrenchTerm::add_curvature(NlpEvaluations& at, double factor, const HessianBand& band,
                                   double* values) {
  // 2·factor·Σ w_s J_sᵀJ_s. Samples on one knot span share their columns (the span's control
  // block and time slots), so their sum is one symmetric rank-k update of the stacked, weighted
  // rows and one scatter into the band, instead of a dense product and a scatter per sample.
  // The spans' blocks are computed in parallel and scattered in span order, so the sums do not
  // depend on the thread count.
  const std::vector<LocalJacobian<6>>& jacobians = samples_.jacobians(at);
  const double scale = 2.0 * factor;
  const std::size_t n = jacobians.size();
  spans_.clear();
  for (std::size_t begin = 0; begin < n;) {
    const LocalJacobian<6>& first = jacobians[begin];
    std::size_t end = begin + 1;
    while (end < n && jacobians[end].first_control_variable == first.first_control_variable &&
           jacobians[end].time_count == first.time_count &&
           jacobians[end].time_variable == first.time_variable)
      ++end;
    spans_.emplace_back(static_cast<int>(begin), static_cast<int>(end));
    begin = end;
  }
  span_blocks_.resize(spans_.size());
  stacked_rows_.resize(at.parts());
  const int span_count = static_cast<int>(spans_.size());
  at.for_each_range(
      span_count, [&](int part, RootWrenchDerivatives&, int first_span, int end_span) {
        Eigen::MatrixXd& stacked = stacked_rows_[part];
        for (int index = first_span; index < end_span; ++index) {
          const auto [begin, end] = spans_[index];
          const LocalJacobian<6>& first = jacobians[begin];
          const int width = static_cast<int>(first.control.cols());
          const int times = first.time_count;
          stacked.resize(6 * (end - begin), width + times);
          for (int s = begin; s < end; ++s) {
            const double root_weight = std::sqrt(scale * weights_[s]);
            const int row = 6 * (s - begin);
            stacked.block(row, 0, 6, width) = root_weight * jacobians[s].control;
            stacked.block(row, width, 6, times) = root_weight * jacobians[s].time.leftCols(times);
          }
          Eigen::MatrixXd& block = span_blocks_[index];
          block.setZero(width + times, width + times);
          block.selfadjointView<Eigen::Lower>().rankUpdate(stacked.transpose());
        }
      });
  for (int index = 0; index < span_count; ++index) {
    const LocalJacobian<6>& first = jacobians[spans_[index].first];
    const Eigen::MatrixXd& block = span_blocks_[index];
    const int width = static_cast<int>(first.control.cols());
    const int times = first.time_count;
    // Scatter the lower triangle: controls are contiguous from `first_control_variable`, time
    // slot p is variable time_variable[p] (beyond every control).
    const int base = first.first_control_variable;
    for (int a = 0; a < width; ++a)
      Eigen::Map<Eigen::RowVectorXd>(values + band.index(base + a, base), a + 1) +=
          block.row(a).head(a + 1);
    for (int p = 0; p < times; ++p) {
      const int tv = first.time_variable[p];
      Eigen::Map<Eigen::RowVectorXd>(values + band.index(tv, base), width) +=
          block.row(width + p).head(width);
      for (int q = 0; q < times; ++q) {
        const int other = first.time_variable[q];
        // Row width + max(p, q) holds the pair in the lower triangle.
        if (other <= tv)
          values[band.index(tv, other)] += block(width + std::max(p, q), width + std::min(p, q));
      }
    }
  }
  if (damping_) {
    const double damping = factor * damping_->factor() * value(at);
    for (int v = 0; v < band.size(); ++v)
      values[band.index(v, v)] += damping;
  }
}

}  // namespace saltus
