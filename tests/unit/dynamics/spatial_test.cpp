// Spatial algebra (dynamics/spatial.h) against its physical meaning (Featherstone 2008, ch. 2):
// power is the same in every frame (the force transform is the dual of the motion transform), the
// two cross products are dual, the structured transform equals its 6×6 matrix, and a rigid
// inertia's kinetic energy splits into translation of the CoM and rotation about it (König).

#include "saltus/dynamics/spatial.h"

#include <gtest/gtest.h>

#include <random>

namespace saltus {
namespace {

struct Random {
  std::mt19937 rng{11};
  std::uniform_real_distribution<double> u{-1.0, 1.0};
  Eigen::Vector3d vector3() { return Eigen::Vector3d(u(rng), u(rng), u(rng)); }
  Vector6d vector6() {
    Vector6d v;
    for (int i = 0; i < 6; ++i)
      v[i] = u(rng);
    return v;
  }
  FramePlacement<double> placement() {
    return {Eigen::Quaterniond(Eigen::AngleAxisd(2 * u(rng), vector3().normalized()))
                .toRotationMatrix(),
            vector3()};
  }
};

TEST(Spatial, SkewIsTheCrossProduct) {
  Random r;
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::Vector3d a = r.vector3(), b = r.vector3();
    EXPECT_LT((skew(a) * b - a.cross(b)).norm(), 1e-15);
  }
}

TEST(Spatial, PowerIsTheSameInParentAndChildCoordinates) {
  Random r;
  for (int trial = 0; trial < 20; ++trial) {
    const FramePlacement<double> x = r.placement();
    const Vector6d m_parent = r.vector6(), f_child = r.vector6();
    const double child = f_child.dot(x.motion_to_child(m_parent));
    const double parent = x.force_to_parent(f_child).dot(m_parent);
    EXPECT_NEAR(child, parent, 1e-14);
    EXPECT_LT((x.motion_matrix_to_child() * m_parent - x.motion_to_child(m_parent)).norm(), 1e-15);
  }
}

TEST(Spatial, MotionToChildGivesTheVelocityOfTheChildOrigin) {
  // A parent spinning with ω about its origin (no linear velocity there): the child origin at t
  // moves with ω × t; both expressed in child axes.
  Random r;
  const FramePlacement<double> x = r.placement();
  const Eigen::Vector3d omega = r.vector3();
  Vector6d m = Vector6d::Zero();
  m.head<3>() = omega;
  const Vector6d c = x.motion_to_child(m);
  EXPECT_LT((c.head<3>() - x.rotation.transpose() * omega).norm(), 1e-15);
  EXPECT_LT((c.tail<3>() - x.rotation.transpose() * omega.cross(x.translation)).norm(), 1e-15);
}

TEST(Spatial, CrossProductsAreDual) {
  // v ×* f = −(v ×m)ᵀ f: (v ×* f) · m = −f · (v ×m m) for every m.
  Random r;
  for (int trial = 0; trial < 20; ++trial) {
    const Vector6d v = r.vector6(), f = r.vector6(), m = r.vector6();
    EXPECT_NEAR(cross_force(v, f).dot(m), -f.dot(cross_motion(v, m)), 1e-14);
  }
}

TEST(Spatial, RigidInertiaKineticEnergyIsTranslationPlusRotationAboutTheCom) {
  Random r;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Matrix3d a = Eigen::Matrix3d::Random();
    const RigidInertia<double> inertia{2.0 + r.u(r.rng), r.vector3(),
                                       a * a.transpose() + 0.1 * Eigen::Matrix3d::Identity()};
    const Vector6d v = r.vector6();
    const Eigen::Vector3d omega = v.head<3>();
    const Eigen::Vector3d com_velocity = v.tail<3>() + omega.cross(inertia.com);
    const double koenig = 0.5 * inertia.mass * com_velocity.squaredNorm() +
                          0.5 * omega.dot(inertia.inertia_com * omega);
    EXPECT_NEAR(0.5 * v.dot(inertia.apply(v)), koenig, 1e-13);
    EXPECT_LT((inertia.matrix() * v - inertia.apply(v)).norm(), 1e-13);
    EXPECT_LT((inertia.matrix() - inertia.matrix().transpose()).norm(), 1e-15);
  }
}

}  // namespace
}  // namespace saltus
