#include "saltus/optim/terms/keyframe_rotation_block.h"

#include "saltus/optim/nlp.h"

namespace saltus {

KeyframeRotationBlock::KeyframeRotationBlock(const TrajectoryLayout& layout,
                                             const KeyframeTargets& targets, double tolerance,
                                             double bound)
    : layout_(layout), targets_(targets), scale_(1.0 / (tolerance * tolerance)), bound_(bound) {
  std::vector<int> times;
  for (int i = 0; i < layout.keyframe_count; ++i)
    if (layout.time_variable(i) >= 0) times.push_back(layout.time_variable(i));
  for (int i = 0; i < layout.keyframe_count; ++i) {
    const int c0 = layout.keyframe_span(i) - 3;
    for (int k = 0; k < layout.segment_count; ++k) {
      std::vector<int> columns;
      for (int c = c0; c < c0 + 4; ++c)
        for (int d = 0; d < 3; ++d)
          columns.push_back(layout.control_variable(k + 1, c, d));
      columns.insert(columns.end(), times.begin(), times.end());
      sparsity_.push_back(columns);
    }
  }
}

void KeyframeRotationBlock::bounds(double* lower, double* upper) const {
  for (int r = 0; r < rows(); ++r) {
    lower[r] = -kUnbounded;
    upper[r] = bound_;
  }
}

std::vector<std::vector<int>> KeyframeRotationBlock::sparsity() const {
  return sparsity_;
}

void KeyframeRotationBlock::values(NlpEvaluations& at, double* g) {
  at.need_keyframe_values();
  int row = 0;
  for (int i = 0; i < layout_.keyframe_count; ++i)
    for (int k = 0; k < layout_.segment_count; ++k) {
      const Eigen::Vector4d q = at.keyframe_rotation(i, k).value;
      g[row++] = scale_ * (q - aligned_target(targets_.rotation(i, k), q)).squaredNorm();
    }
}

void KeyframeRotationBlock::jacobian(NlpEvaluations& at, double* values) {
  at.need_keyframe_derivatives();
  int entry = 0, row = 0;
  for (int i = 0; i < layout_.keyframe_count; ++i)
    for (int k = 0; k < layout_.segment_count; ++k, ++row) {
      const LocalJacobian<4>& rj = at.keyframe_rotation(i, k);
      const Eigen::Matrix<double, 1, 4> w =
          2.0 * scale_ * (rj.value - aligned_target(targets_.rotation(i, k), rj.value)).transpose();
      for (int column : sparsity_[row])
        values[entry++] = local_derivative<4>(rj, w, column);
    }
}

void KeyframeRotationBlock::add_curvature(NlpEvaluations& at, const double* multipliers,
                                          const HessianBand& band, double* values) {
  // ∇²g ≈ 2·scale·JᵀJ (Gauss–Newton of g = scale·‖r‖²), counted only where the multiplier makes
  // it positive semi-definite.
  at.need_keyframe_derivatives();
  int row = 0;
  for (int i = 0; i < layout_.keyframe_count; ++i)
    for (int k = 0; k < layout_.segment_count; ++k, ++row)
      if (multipliers[row] > 0)
        band.add_gauss_newton(at.keyframe_rotation(i, k), 2.0 * scale_ * multipliers[row], values);
}

}  // namespace saltus
