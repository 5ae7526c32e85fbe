#pragma once
/// @file
/// Unit-quaternion helpers (Hamilton convention, Eigen::Quaternion storage). Templated on the
/// scalar so that automatic differentiation passes through.
///
/// Convention for exp/log (Kim-Kim-Shin 1995): exp(v) = (cos|v|, sin|v| v/|v|), a rotation by the
/// angle 2|v| about v. log is its inverse on unit quaternions:
/// it returns |v| = θ in [0, π], so it does not fold the sign of q.

#include <Eigen/Geometry>
#include <string>

#include "saltus/base/constants.h"
#include "saltus/math/scalar.h"

namespace saltus {

template <typename Scalar>
using Quat = Eigen::Quaternion<Scalar>;
template <typename Scalar>
using Vec3 = Eigen::Matrix<Scalar, 3, 1>;
template <typename Scalar>
using Mat3 = Eigen::Matrix<Scalar, 3, 3>;

/// exp of the pure quaternion (0, v): rotation by 2|v| about v.
template <typename Scalar>
Quat<Scalar> quat_exp(const Vec3<Scalar>& v) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const Scalar theta2 = v.squaredNorm();
  Scalar c, sinc;
  if (value_of(theta2) < 1e-12) {
    // Taylor series: exact to double precision here and free of 0/0 in the derivatives.
    c = Scalar(1) - theta2 / Scalar(2) + theta2 * theta2 / Scalar(24);
    sinc = Scalar(1) - theta2 / Scalar(6) + theta2 * theta2 / Scalar(120);
  } else {
    const Scalar theta = sqrt(theta2);
    c = cos(theta);
    sinc = sin(theta) / theta;
  }
  return Quat<Scalar>(c, sinc * v.x(), sinc * v.y(), sinc * v.z());
}

/// log of a unit quaternion: the v with exp(v) = q, |v| in [0, π]. Allocation-free for
/// fixed-size AD scalars (atan2_same_type).
template <typename Scalar>
Vec3<Scalar> quat_log(const Quat<Scalar>& q) {
  using std::sqrt;
  const Vec3<Scalar> u = q.vec();
  const Scalar s2 = u.squaredNorm();
  Scalar factor;  // θ / sin θ, with θ = atan2(|u|, w)
  if (value_of(s2) < 1e-12 && value_of(q.w()) > 0) {
    // atan2(s, w)/s = (1/w)(1 - s²/(3w²) + ...) for small s, w > 0.
    const Scalar w = q.w();
    factor = (Scalar(1) - s2 / (Scalar(3) * w * w)) / w;
  } else {
    const Scalar s = sqrt(s2);
    factor = atan2_same_type(s, q.w()) / s;
  }
  return factor * u;
}

/// Rotation angle in radians between two orientations (sign of the quaternions ignored).
template <typename Scalar>
Scalar rotation_angle_between(const Quat<Scalar>& a, const Quat<Scalar>& b) {
  using std::abs;
  const Quat<Scalar> d = a.conjugate() * b;
  return Scalar(2) * atan2_same_type(d.vec().norm(), abs(d.w()));
}

/// The turn in radians, in [0, 2π], from control a to control b of a quaternion spline: signs
/// count (the spline goes the way the signs say), so b = −a is a full turn. Near 2π the relative
/// log the spline is built on has its branch point (see QuaternionSpline::largest_control_turn).
template <typename Scalar>
Scalar control_turn(const Quat<Scalar>& a, const Quat<Scalar>& b) {
  const Quat<Scalar> d = a.conjugate() * b;
  return Scalar(2) * atan2_same_type(d.vec().norm(), d.w());
}

/// ‖a − b‖ after flipping b to a's hemisphere: the paper's quaternion distance (eq. 3).
template <typename Scalar>
Scalar quaternion_distance(const Quat<Scalar>& a, const Quat<Scalar>& b) {
  const Scalar dot = a.coeffs().dot(b.coeffs());
  const Scalar sign = value_of(dot) < 0 ? Scalar(-1) : Scalar(1);
  return (a.coeffs() - sign * b.coeffs()).norm();
}

/// Quaternion from intrinsic Euler angles in degrees, e.g. order "XYZ" means rotate about x,
/// then about the new y, then the new z (R = Rx(a) Ry(b) Rz(c)). Throws std::invalid_argument
/// for an order that is not three letters from {X, Y, Z} with no two adjacent equal.
Quat<double> quat_from_euler_deg(const Eigen::Vector3d& angles_deg, const std::string& order);

}  // namespace saltus
