#pragma once
/// @file
/// The spatial cross products (spatial.h) as matrices, for the analytic derivatives of inverse
/// dynamics (root_wrench_state_jacobian, joint_wrench_state_jacobian). S = [I₃; 0] is a ball
/// joint's motion subspace; angular part first.

#include "saltus/dynamics/spatial.h"

namespace saltus {

/// A 6×3 block: a spatial quantity's derivative with respect to a 3-vector.
using Mat63d = Eigen::Matrix<double, 6, 3>;

/// crm(v)·S = [[ω]×; [v_lin]×]: m ↦ v ×m m restricted to pure rotations m = [δ; 0].
inline Mat63d motion_cross_rotation(const Vec6<double>& v) {
  Mat63d m;
  m.topRows<3>() = skew(Eigen::Vector3d(v.head<3>()));
  m.bottomRows<3>() = skew(Eigen::Vector3d(v.tail<3>()));
  return m;
}

/// crf(v) = −crm(v)ᵀ: f ↦ v ×* f (spatial.h's cross_force as a matrix).
inline Mat6<double> force_cross_matrix(const Vec6<double>& v) {
  const Eigen::Matrix3d w = skew(Eigen::Vector3d(v.head<3>()));
  Mat6<double> m = Mat6<double>::Zero();
  m.topLeftCorner<3, 3>() = w;
  m.topRightCorner<3, 3>() = skew(Eigen::Vector3d(v.tail<3>()));
  m.bottomRightCorner<3, 3>() = w;
  return m;
}

/// The matrix of δv ↦ δv ×* h for a fixed force h = [n; f]: [[−[n]×, −[f]×]; [−[f]×, 0]]. With
/// force_cross_matrix it differentiates the velocity product v ×* I v.
inline Mat6<double> cross_force_by_velocity(const Vec6<double>& h) {
  const Eigen::Matrix3d f = skew(Eigen::Vector3d(h.tail<3>()));
  Mat6<double> m = Mat6<double>::Zero();
  m.topLeftCorner<3, 3>() = -skew(Eigen::Vector3d(h.head<3>()));
  m.topRightCorner<3, 3>() = -f;
  m.bottomLeftCorner<3, 3>() = -f;
  return m;
}

/// crm(Sω) = diag([ω]×, [ω]×): m ↦ Sω ×m m.
inline Mat6<double> joint_rate_cross_matrix(const Eigen::Vector3d& omega) {
  const Eigen::Matrix3d w = skew(omega);
  Mat6<double> m = Mat6<double>::Zero();
  m.topLeftCorner<3, 3>() = w;
  m.bottomRightCorner<3, 3>() = w;
  return m;
}

}  // namespace saltus
