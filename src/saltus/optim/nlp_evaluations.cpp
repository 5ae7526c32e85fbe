#include "saltus/optim/nlp_evaluations.h"

#include <cstring>

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

}  // namespace saltus
