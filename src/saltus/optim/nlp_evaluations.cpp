#include "saltus/optim/nlp_evaluations.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "saltus/math/gauss_legendre.h"

namespace saltus {

NlpEvaluations::NlpEvaluations(const BodyModel& model, const TrajectoryLayout& layout,
                               const TrajectoryReference& reference, int threads)
    : layout_(layout), reference_(reference) {
  for (int t = 0; t < threads; ++t)
    evaluators_.push_back(std::make_unique<RootWrenchDerivatives>(model, layout_, reference_));
  pool_ = std::make_unique<WorkerPool>(threads);
  translation_.resize(layout.keyframe_count);
  rotation_.resize(layout.keyframe_count * layout.segment_count);
}

NlpEvaluations::~NlpEvaluations() = default;

void NlpEvaluations::load(const double* x) {
  const std::size_t n = layout_.size();
  if (generation_ > 0 && std::memcmp(x, x_.data(), n * sizeof(double)) == 0) return;
  x_.assign(x, x + n);
  ++generation_;
  have_keyframe_values_ = have_keyframe_derivatives_ = false;
  keyframe_times_ = keyframe_times_from(layout_, reference_, x);
  for (auto& evaluator : evaluators_)
    evaluator->set_variables(x);
}

void NlpEvaluations::need_keyframe_values() {
  // Line-search trial points need only the constraint values: plain double evaluation, not the
  // AD of every keyframe quantity (the derivatives follow once Ipopt accepts the point).
  if (have_keyframe_values_ || have_keyframe_derivatives_) return;
  for (int i = 0; i < layout_.keyframe_count; ++i) {
    translation_[i].value = evaluators_[0]->keyframe_translation_value(i);
    for (int k = 0; k < layout_.segment_count; ++k)
      rotation_[i * layout_.segment_count + k].value =
          evaluators_[0]->keyframe_rotation_value(i, k);
  }
  have_keyframe_values_ = true;
}

void NlpEvaluations::need_keyframe_derivatives() {
  if (have_keyframe_derivatives_) return;
  for_each_range(layout_.keyframe_count,
                 [this](int, RootWrenchDerivatives& evaluator, int begin, int end) {
                   for (int i = begin; i < end; ++i) {
                     evaluator.keyframe_translation(i, translation_[i]);
                     for (int k = 0; k < layout_.segment_count; ++k)
                       evaluator.keyframe_rotation(i, k, rotation_[i * layout_.segment_count + k]);
                   }
                 });
  have_keyframe_derivatives_ = true;
}

const std::vector<Vector6d>& WrenchSamples::values(NlpEvaluations& at) {
  if (values_generation_ == at.generation()) return values_;
  at.for_each_range(size(), [this](int, RootWrenchDerivatives& evaluator, int begin, int end) {
    for (int s = begin; s < end; ++s)
      values_[s] = evaluator.wrench(times_[s]);
  });
  values_generation_ = at.generation();
  return values_;
}

const std::vector<LocalJacobian<6>>& WrenchSamples::jacobians(NlpEvaluations& at) {
  if (jacobians_generation_ == at.generation()) return jacobians_;
  at.for_each_range(size(), [this](int, RootWrenchDerivatives& evaluator, int begin, int end) {
    for (int s = begin; s < end; ++s) {
      evaluator.wrench_jacobian(times_[s], jacobians_[s]);
      values_[s] = jacobians_[s].value;
    }
  });
  values_generation_ = jacobians_generation_ = at.generation();
  return jacobians_;
}

SpanQuadrature::SpanQuadrature(const TrajectoryLayout& layout, const std::vector<double>& knots,
                               int min_nodes, double max_spacing) {
  // Spans 3 .. control_count − 1 are the clamped knot vector's spans of positive length.
  for (int span = 3; span < layout.control_count(); ++span) {
    const double length = knots.at(span + 1) - knots.at(span);
    const int count = std::max(min_nodes, static_cast<int>(std::ceil(length / max_spacing - 1e-9)));
    const QuadratureRule rule = gauss_lobatto(count);
    for (int q = 0; q < count; ++q)
      nodes_.push_back({span, rule.nodes[q], rule.weights[q]});
  }
  values_.resize(nodes_.size());
  jacobians_.resize(nodes_.size());
  span_length_rates_.resize(nodes_.size());
}

double SpanQuadrature::span_length(NlpEvaluations& at, int node) const {
  const std::vector<double>& knots = at.evaluator().knots();
  const int s = nodes_[node].span;
  return knots[s + 1] - knots[s];
}

double SpanQuadrature::time(NlpEvaluations& at, int node) const {
  const std::vector<double>& knots = at.evaluator().knots();
  const int s = nodes_[node].span;
  return knots[s] + nodes_[node].xi * (knots[s + 1] - knots[s]);
}

const std::vector<Vector6d>& SpanQuadrature::values(NlpEvaluations& at) {
  if (values_generation_ == at.generation()) return values_;
  at.for_each_range(size(), [this](int, RootWrenchDerivatives& evaluator, int begin, int end) {
    for (int n = begin; n < end; ++n)
      values_[n] = evaluator.wrench_on_span(nodes_[n].span, nodes_[n].xi);
  });
  values_generation_ = at.generation();
  return values_;
}

const std::vector<LocalJacobian<6>>& SpanQuadrature::jacobians(NlpEvaluations& at) {
  if (jacobians_generation_ == at.generation()) return jacobians_;
  at.for_each_range(size(), [this](int, RootWrenchDerivatives& evaluator, int begin, int end) {
    for (int n = begin; n < end; ++n) {
      evaluator.wrench_jacobian_on_span(nodes_[n].span, nodes_[n].xi, jacobians_[n],
                                        span_length_rates_[n]);
      values_[n] = jacobians_[n].value;
    }
  });
  values_generation_ = jacobians_generation_ = at.generation();
  return jacobians_;
}

}  // namespace saltus
