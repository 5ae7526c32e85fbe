#include "saltus/optim/terms/keyframe_distance_term.h"

#include <cmath>

namespace saltus {

double KeyframeDistanceTerm::value(NlpEvaluations& at) {
  at.need_keyframe_values();
  const std::vector<double>& times = at.keyframe_times();
  const int segments = at.layout().segment_count;
  double f = 0.0;
  for (int i = 0; i < at.layout().keyframe_count; ++i) {
    f += translation_weight_ *
         (at.keyframe_translation(i).value - targets_.root(i, times[i])).squaredNorm();
    for (int k = 0; k < segments; ++k) {
      const Eigen::Vector4d q = at.keyframe_rotation(i, k).value;
      f += rotation_weight_ * (q - aligned_target(targets_.rotation(i, k), q)).squaredNorm();
    }
  }
  return f;
}

void KeyframeDistanceTerm::add_gradient(NlpEvaluations& at, double* gradient) {
  at.need_keyframe_derivatives();
  const std::vector<double>& times = at.keyframe_times();
  const TrajectoryLayout& layout = at.layout();
  for (int i = 0; i < layout.keyframe_count; ++i) {
    const LocalJacobian<3>& tj = at.keyframe_translation(i);
    const Eigen::Vector3d r = tj.value - targets_.root(i, times[i]);
    const Eigen::Matrix<double, 1, 3> w = 2.0 * translation_weight_ * r.transpose();
    Eigen::Map<Eigen::RowVectorXd>(gradient + tj.first_control_variable, tj.control.cols()) +=
        w * tj.control;
    for (int p = 0; p < tj.time_count; ++p)
      gradient[tj.time_variable[p]] += w * tj.time.col(p);
    const int tv = layout.time_variable(i);
    if (tv >= 0 && targets_.root_moves_with_time(i))
      gradient[tv] -= w * targets_.root_rate(i, times[i]);
    for (int k = 0; k < layout.segment_count; ++k) {
      const LocalJacobian<4>& rj = at.keyframe_rotation(i, k);
      const Eigen::Matrix<double, 1, 4> wq =
          2.0 * rotation_weight_ *
          (rj.value - aligned_target(targets_.rotation(i, k), rj.value)).transpose();
      Eigen::Map<Eigen::RowVectorXd>(gradient + rj.first_control_variable, rj.control.cols()) +=
          wq * rj.control;
      for (int p = 0; p < rj.time_count; ++p)
        gradient[rj.time_variable[p]] += wq * rj.time.col(p);
    }
  }
}

LocalJacobian<3> KeyframeDistanceTerm::translation_residual_jacobian(NlpEvaluations& at,
                                                                     int keyframe) const {
  LocalJacobian<3> jac = at.keyframe_translation(keyframe);
  const int tv = at.layout().time_variable(keyframe);
  if (tv < 0 || !targets_.root_moves_with_time(keyframe)) return jac;
  int slot = 0;
  while (slot < jac.time_count && jac.time_variable[slot] != tv)
    ++slot;
  if (slot == jac.time_count) {
    jac.time_variable[jac.time_count++] = tv;
    jac.time.col(slot).setZero();
  }
  jac.time.col(slot) -= targets_.root_rate(keyframe, at.keyframe_times()[keyframe]);
  return jac;
}

void KeyframeDistanceTerm::add_curvature(NlpEvaluations& at, double factor, const HessianBand& band,
                                         double* values) {
  at.need_keyframe_derivatives();
  for (int i = 0; i < at.layout().keyframe_count; ++i) {
    band.add_gauss_newton(translation_residual_jacobian(at, i), 2.0 * translation_weight_ * factor,
                          values);
    for (int k = 0; k < at.layout().segment_count; ++k)
      band.add_gauss_newton(at.keyframe_rotation(i, k), 2.0 * rotation_weight_ * factor, values);
  }
}

std::vector<double> KeyframeDistanceTerm::residuals(NlpEvaluations& at) {
  at.need_keyframe_values();
  const double translation_scale = std::sqrt(translation_weight_);
  const double rotation_scale = std::sqrt(rotation_weight_);
  std::vector<double> r;
  for (int i = 0; i < at.layout().keyframe_count; ++i) {
    const Eigen::Vector3d d = translation_scale * (at.keyframe_translation(i).value -
                                                   targets_.root(i, at.keyframe_times()[i]));
    r.insert(r.end(), d.data(), d.data() + 3);
    for (int k = 0; k < at.layout().segment_count; ++k) {
      const Eigen::Vector4d q = at.keyframe_rotation(i, k).value;
      const Eigen::Vector4d e = rotation_scale * (q - aligned_target(targets_.rotation(i, k), q));
      r.insert(r.end(), e.data(), e.data() + 4);
    }
  }
  return r;
}

}  // namespace saltus
