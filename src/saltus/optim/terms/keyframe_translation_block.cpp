#include "saltus/optim/terms/keyframe_translation_block.h"

namespace saltus {

namespace {
std::vector<int> time_variables(const TrajectoryLayout& layout) {
  std::vector<int> times;
  for (int i = 0; i < layout.keyframe_count; ++i)
    if (layout.time_variable(i) >= 0) times.push_back(layout.time_variable(i));
  return times;
}
}  // namespace

KeyframeTranslationBlock::KeyframeTranslationBlock(const TrajectoryLayout& layout,
                                                   const KeyframeTargets& targets, double tolerance,
                                                   double bound)
    : layout_(layout), targets_(targets), scale_(1.0 / tolerance), bound_(bound) {
  // A keyframe's translation depends on its span's 4 root controls and, through the knots, on
  // the keyframe times.
  const std::vector<int> times = time_variables(layout);
  for (int i = 0; i < layout.keyframe_count; ++i) {
    const int c0 = layout.keyframe_span(i) - 3;
    for (int d = 0; d < 3; ++d) {
      std::vector<int> columns;
      for (int c = c0; c < c0 + 4; ++c)
        columns.push_back(layout.control_variable(0, c, d));
      columns.insert(columns.end(), times.begin(), times.end());
      sparsity_.push_back(columns);
    }
  }
}

void KeyframeTranslationBlock::bounds(double* lower, double* upper) const {
  for (int r = 0; r < rows(); ++r) {
    lower[r] = -bound_;
    upper[r] = bound_;
  }
}

std::vector<std::vector<int>> KeyframeTranslationBlock::sparsity() const {
  return sparsity_;
}

void KeyframeTranslationBlock::values(NlpEvaluations& at, double* g) {
  at.need_keyframe_values();
  int row = 0;
  for (int i = 0; i < layout_.keyframe_count; ++i) {
    const Eigen::Vector3d r =
        at.keyframe_translation(i).value - targets_.root(i, at.keyframe_times()[i]);
    for (int d = 0; d < 3; ++d)
      g[row++] = scale_ * r[d];
  }
}

void KeyframeTranslationBlock::jacobian(NlpEvaluations& at, double* values) {
  at.need_keyframe_derivatives();
  int entry = 0;
  for (int i = 0; i < layout_.keyframe_count; ++i) {
    const LocalJacobian<3>& tj = at.keyframe_translation(i);
    const int own_time = layout_.time_variable(i);
    const Eigen::Vector3d target_rate = targets_.root_rate(i, at.keyframe_times()[i]);
    for (int d = 0; d < 3; ++d) {
      Eigen::Matrix<double, 1, 3> pick = Eigen::Matrix<double, 1, 3>::Zero();
      pick[d] = scale_;
      for (int column : sparsity_[3 * i + d])
        values[entry++] = local_derivative<3>(tj, pick, column) -
                          (column == own_time ? scale_ * target_rate[d] : 0.0);
    }
  }
}

}  // namespace saltus
