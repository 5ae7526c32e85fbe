#pragma once
/// @file
/// Minimal spatial (6D) algebra after Featherstone, "Rigid Body Dynamics Algorithms" (2008),
/// ch. 2. Motion vectors are [ω; v] and force vectors [n; f] (angular part first), both in the
/// coordinates of one body frame about its origin. Transforms are stored as a rotation and a
/// translation, never as 6×6 matrices, because the structured forms cost a fraction of the flops.
/// Outside this file (files, the paper's F1..F6) wrenches are written force first.

#include <Eigen/Core>

#include "saltus/math/quaternion.h"

namespace saltus {

template <typename Scalar>
using Vec6 = Eigen::Matrix<Scalar, 6, 1>;
template <typename Scalar>
using Mat6 = Eigen::Matrix<Scalar, 6, 6>;
using Vector6d = Vec6<double>;

template <typename Scalar>
Mat3<Scalar> skew(const Vec3<Scalar>& v) {
  Mat3<Scalar> m;
  m << Scalar(0), -v.z(), v.y(), v.z(), Scalar(0), -v.x(), -v.y(), v.x(), Scalar(0);
  return m;
}

/// Placement of a child frame in its parent: p_parent = rotation · p_child + translation.
/// (Featherstone's X from parent to child has E = rotationᵀ, r = translation.)
template <typename Scalar>
struct FramePlacement {
  Mat3<Scalar> rotation;     ///< parent_from_child
  Vec3<Scalar> translation;  ///< child origin in parent coordinates

  /// Motion vector from parent to child coordinates.
  Vec6<Scalar> motion_to_child(const Vec6<Scalar>& m) const {
    Vec6<Scalar> out;
    const Vec3<Scalar> w = m.template head<3>();
    const Vec3<Scalar> v = m.template tail<3>();
    out.template head<3>() = rotation.transpose() * w;
    out.template tail<3>() = rotation.transpose() * (v + w.cross(translation));
    return out;
  }
  /// Force vector from child to parent coordinates (Xᵀ for the dual transform).
  Vec6<Scalar> force_to_parent(const Vec6<Scalar>& f) const {
    Vec6<Scalar> out;
    const Vec3<Scalar> force = rotation * f.template tail<3>();
    out.template tail<3>() = force;
    out.template head<3>() = rotation * f.template head<3>() + translation.cross(force);
    return out;
  }
  /// 6×6 motion transform parent -> child (for the composite inertia only).
  Mat6<Scalar> motion_matrix_to_child() const {
    Mat6<Scalar> x = Mat6<Scalar>::Zero();
    const Mat3<Scalar> e = rotation.transpose();
    x.template topLeftCorner<3, 3>() = e;
    x.template bottomRightCorner<3, 3>() = e;
    x.template bottomLeftCorner<3, 3>() = -e * skew(translation);
    return x;
  }
};

/// Spatial cross product for motion vectors, v ×m m.
template <typename Scalar>
Vec6<Scalar> cross_motion(const Vec6<Scalar>& v, const Vec6<Scalar>& m) {
  Vec6<Scalar> out;
  const Vec3<Scalar> w = v.template head<3>();
  const Vec3<Scalar> lin = v.template tail<3>();
  out.template head<3>() = w.cross(m.template head<3>());
  out.template tail<3>() = w.cross(m.template tail<3>()) + lin.cross(m.template head<3>());
  return out;
}

/// Spatial cross product for force vectors, v ×* f.
template <typename Scalar>
Vec6<Scalar> cross_force(const Vec6<Scalar>& v, const Vec6<Scalar>& f) {
  Vec6<Scalar> out;
  const Vec3<Scalar> w = v.template head<3>();
  const Vec3<Scalar> lin = v.template tail<3>();
  out.template head<3>() = w.cross(f.template head<3>()) + lin.cross(f.template tail<3>());
  out.template tail<3>() = w.cross(f.template tail<3>());
  return out;
}

/// Rigid-body inertia about a frame's origin from mass, CoM c and rotational inertia about the
/// CoM, all in that frame. Applied without forming the 6×6 matrix.
template <typename Scalar>
struct RigidInertia {
  Scalar mass;
  Vec3<Scalar> com;
  Mat3<Scalar> inertia_com;

  /// Spatial momentum I·v: f = m(v + ω × c), n = I_c ω + c × f.
  Vec6<Scalar> apply(const Vec6<Scalar>& v) const {
    Vec6<Scalar> out;
    const Vec3<Scalar> w = v.template head<3>();
    const Vec3<Scalar> f = mass * (v.template tail<3>() + w.cross(com));
    out.template tail<3>() = f;
    out.template head<3>() = inertia_com * w + com.cross(f);
    return out;
  }
  Mat6<Scalar> matrix() const {
    Mat6<Scalar> m;
    const Mat3<Scalar> c = skew(com);
    m.template topLeftCorner<3, 3>() = inertia_com + mass * c * c.transpose();
    m.template topRightCorner<3, 3>() = mass * c;
    m.template bottomLeftCorner<3, 3>() = mass * c.transpose();
    m.template bottomRightCorner<3, 3>() = mass * Mat3<Scalar>::Identity();
    return m;
  }
};

}  // namespace saltus
