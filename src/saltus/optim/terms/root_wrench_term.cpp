#include "saltus/optim/terms/root_wrench_term.h"

#include <cmath>

namespace saltus {

RootWrenchTerm::RootWrenchTerm(SpanQuadrature nodes, double duration,
                               const AdaptiveDamping* damping, double moment_weight)
    : nodes_(std::move(nodes)), duration_(duration), damping_(damping) {
  root_weights_ << 1.0, 1.0, 1.0, Eigen::Vector3d::Constant(std::sqrt(moment_weight));
}

double RootWrenchTerm::weight(NlpEvaluations& at, int node) const {
  return nodes_.span_length(at, node) * nodes_.nodes()[node].weight / duration_;
}

std::vector<double> RootWrenchTerm::times(NlpEvaluations& at) const {
  std::vector<double> t;
  for (int n = 0; n < nodes_.size(); ++n)
    t.push_back(nodes_.time(at, n));
  return t;
}

double RootWrenchTerm::value(NlpEvaluations& at) {
  const std::vector<Vector6d>& wrench = nodes_.values(at);
  double j = 0.0;
  for (int n = 0; n < nodes_.size(); ++n)
    j += weight(at, n) * root_weights_.cwiseProduct(wrench[n]).squaredNorm();
  return j;
}

double RootWrenchTerm::unweighted_value(NlpEvaluations& at) {
  const std::vector<Vector6d>& wrench = nodes_.values(at);
  double j = 0.0;
  for (int n = 0; n < nodes_.size(); ++n)
    j += weight(at, n) * wrench[n].squaredNorm();
  return j;
}

void RootWrenchTerm::add_gradient(NlpEvaluations& at, double* gradient) {
  // ∇(w‖F‖²) = 2w·Fᵀ∇F + ‖F‖²·∇w, the weight moving with its span's length.
  const std::vector<LocalJacobian<6>>& jacobians = nodes_.jacobians(at);
  const std::vector<Vector6d>& wrench = nodes_.values(at);
  for (int n = 0; n < nodes_.size(); ++n) {
    const LocalJacobian<6>& jac = jacobians[n];
    const Vector6d weighted = root_weights_.cwiseProduct(wrench[n]);
    const Eigen::Matrix<double, 1, 6> w =
        2.0 * weight(at, n) * root_weights_.cwiseProduct(weighted).transpose();
    Eigen::Map<Eigen::RowVectorXd>(gradient + jac.first_control_variable, jac.control.cols()) +=
        w * jac.control;
    const double weight_rate = nodes_.nodes()[n].weight / duration_ * weighted.squaredNorm();
    for (int p = 0; p < jac.time_count; ++p)
      gradient[jac.time_variable[p]] +=
          w * jac.time.col(p) + weight_rate * nodes_.span_length_rates()[n][p];
  }
}

std::vector<double> RootWrenchTerm::residuals(NlpEvaluations& at) {
  const std::vector<Vector6d>& wrench = nodes_.values(at);
  std::vector<double> r;
  for (int n = 0; n < nodes_.size(); ++n)
    for (int c = 0; c < 6; ++c)
      r.push_back(std::sqrt(weight(at, n)) * root_weights_[c] * wrench[n][c]);
  return r;
}

void RootWrenchTerm::add_curvature(NlpEvaluations& at, double factor, const HessianBand& band,
                                   double* values) {
  // 2·factor·Σ_n ∇r_nᵀ∇r_n with r_n = √w_n·F_n, ∇r_n = √w_n·(∇F_n + F_n·∇w_n/(2w_n)). Nodes on
  // one knot span share their columns (the span's control block and time slots), so their sum
  // is one symmetric rank-k update of the stacked rows and one scatter into the band. The
  // spans' blocks are computed in parallel and scattered in span order, so the sums do not
  // depend on the thread count.
  const std::vector<LocalJacobian<6>>& jacobians = nodes_.jacobians(at);
  const std::vector<Vector6d>& wrench = nodes_.values(at);
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
  at.for_each_range(span_count, [&](int part, RootWrenchDerivatives&, int first_span,
                                    int end_span) {
    Eigen::MatrixXd& stacked = stacked_rows_[part];
    for (int index = first_span; index < end_span; ++index) {
      const auto [begin, end] = spans_[index];
      const LocalJacobian<6>& first = jacobians[begin];
      const int width = static_cast<int>(first.control.cols());
      const int times = first.time_count;
      stacked.resize(6 * (end - begin), width + times);
      for (int s = begin; s < end; ++s) {
        const double w = weight(at, s);
        const double root_weight = std::sqrt(scale * w);
        const int row = 6 * (s - begin);
        const auto rows = root_weights_.asDiagonal();
        stacked.block(row, 0, 6, width) = root_weight * (rows * jacobians[s].control);
        const double relative_rate = nodes_.nodes()[s].weight / duration_ / (2.0 * w);
        stacked.block(row, width, 6, times) =
            root_weight *
            (rows * (jacobians[s].time.leftCols(times) +
                     relative_rate * wrench[s] * nodes_.span_length_rates()[s].leftCols(times)));
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
    band.add_span_block(block, first.first_control_variable, width, first.time_count,
                        first.time_variable, values);
  }
  if (damping_) {
    const double damping = factor * damping_->factor() * value(at);
    for (int v = 0; v < band.size(); ++v)
      values[band.index(v, v)] += damping;
  }
}

}  // namespace saltus
