#include "saltus/optim/terms/joint_load_term.h"

#include <cmath>
#include <utility>

#include "saltus/math/gauss_legendre.h"

namespace saltus {

namespace {
constexpr int kNodesPerSpan = 3;
}

JointLoadTerm::JointLoadTerm(const TrajectoryLayout& layout, const std::vector<double>& knots,
                             double duration, double weight, std::vector<double> scales)
    : scales_(std::move(scales)) {
  const QuadratureRule rule = gauss_lobatto(kNodesPerSpan);
  for (int span = 3; span < layout.control_count(); ++span) {
    const double length = knots.at(span + 1) - knots.at(span);
    const int first = static_cast<int>(nodes_.size());
    for (int q = 0; q < kNodesPerSpan; ++q)
      nodes_.push_back({span, rule.nodes[q], weight * rule.weights[q] * length / duration});
    spans_.emplace_back(first, static_cast<int>(nodes_.size()));
  }
  values_.resize(nodes_.size());
  jacobians_.resize(nodes_.size());
}

template <typename Rows>
void JointLoadTerm::scale_rows(Rows& rows) const {
  for (std::size_t j = 0; j < scales_.size(); ++j)
    rows.middleRows(3 * static_cast<Eigen::Index>(j), 3) *= scales_[j];
}

const std::vector<Eigen::VectorXd>& JointLoadTerm::values(NlpEvaluations& at) {
  if (values_generation_ == at.generation()) return values_;
  at.for_each_range(static_cast<int>(nodes_.size()),
                    [this](int, RootWrenchDerivatives& evaluator, int begin, int end) {
                      for (int n = begin; n < end; ++n) {
                        values_[n] = evaluator.joint_moments_on_span(nodes_[n].span, nodes_[n].xi);
                        scale_rows(values_[n]);
                      }
                    });
  values_generation_ = at.generation();
  return values_;
}

const std::vector<LocalJacobian<Eigen::Dynamic>>& JointLoadTerm::jacobians(NlpEvaluations& at) {
  if (jacobians_generation_ == at.generation()) return jacobians_;
  at.for_each_range(static_cast<int>(nodes_.size()),
                    [this](int, RootWrenchDerivatives& evaluator, int begin, int end) {
                      for (int n = begin; n < end; ++n) {
                        LocalJacobian<Eigen::Dynamic>& jac = jacobians_[n];
                        evaluator.joint_moments_jacobian_on_span(nodes_[n].span, nodes_[n].xi, jac);
                        scale_rows(jac.value);
                        scale_rows(jac.control);
                        scale_rows(jac.time);
                        values_[n] = jac.value;
                      }
                    });
  values_generation_ = jacobians_generation_ = at.generation();
  return jacobians_;
}

double JointLoadTerm::value(NlpEvaluations& at) {
  const std::vector<Eigen::VectorXd>& moments = values(at);
  double sum = 0.0;
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    sum += nodes_[n].weight * moments[n].squaredNorm();
  return sum;
}

void JointLoadTerm::add_gradient(NlpEvaluations& at, double* gradient) {
  const std::vector<LocalJacobian<Eigen::Dynamic>>& jac = jacobians(at);
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    const Eigen::RowVectorXd w = 2.0 * nodes_[n].weight * jac[n].value.transpose();
    Eigen::Map<Eigen::RowVectorXd>(gradient + jac[n].first_control_variable,
                                   jac[n].control.cols()) += w * jac[n].control;
    for (int p = 0; p < jac[n].time_count; ++p)
      gradient[jac[n].time_variable[p]] += w.dot(jac[n].time.col(p));
  }
}

std::vector<double> JointLoadTerm::residuals(NlpEvaluations& at) {
  const std::vector<Eigen::VectorXd>& moments = values(at);
  std::vector<double> r;
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    for (int c = 0; c < moments[n].size(); ++c)
      r.push_back(std::sqrt(nodes_[n].weight) * moments[n][c]);
  return r;
}

void JointLoadTerm::add_curvature(NlpEvaluations& at, double factor, const HessianBand& band,
                                  double* values) {
  // 2·factor·Σ_n w_n·∇n_nᵀ∇n_n, the nodes of one span stacked into one rank-k update (they
  // share the span's columns); spans in parallel, scattered in span order.
  const std::vector<LocalJacobian<Eigen::Dynamic>>& jac = jacobians(at);
  const int span_count = static_cast<int>(spans_.size());
  span_blocks_.resize(spans_.size());
  stacked_rows_.resize(at.parts());
  at.for_each_range(span_count, [&](int part, RootWrenchDerivatives&, int first, int end) {
    Eigen::MatrixXd& stacked = stacked_rows_[part];
    for (int index = first; index < end; ++index) {
      const auto [begin, stop] = spans_[index];
      const int rows = static_cast<int>(jac[begin].value.size());
      const int width = static_cast<int>(jac[begin].control.cols());
      const int times = jac[begin].time_count;
      stacked.resize(rows * (stop - begin), width + times);
      for (int n = begin; n < stop; ++n) {
        const double root_weight = std::sqrt(2.0 * factor * nodes_[n].weight);
        stacked.block(rows * (n - begin), 0, rows, width) = root_weight * jac[n].control;
        stacked.block(rows * (n - begin), width, rows, times) =
            root_weight * jac[n].time.leftCols(times);
      }
      Eigen::MatrixXd& block = span_blocks_[index];
      block.setZero(width + times, width + times);
      block.selfadjointView<Eigen::Lower>().rankUpdate(stacked.transpose());
    }
  });
  for (int index = 0; index < span_count; ++index) {
    const LocalJacobian<Eigen::Dynamic>& first = jac[spans_[index].first];
    band.add_span_block(span_blocks_[index], first.first_control_variable,
                        static_cast<int>(first.control.cols()), first.time_count,
                        first.time_variable, values);
  }
}

}  // namespace saltus
