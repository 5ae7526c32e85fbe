// Quaternion helpers (math/quaternion.h) against Eigen's own rotations and hand-written rotation
// matrices: exp is a rotation by twice the vector's length, log inverts it without folding the
// sign, angles and distances agree with their geometric meaning, Euler angles compose as stated.

#include "saltus/math/quaternion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <unsupported/Eigen/AutoDiff>

namespace saltus {
namespace {

Eigen::Vector3d random_vector(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return scale * Eigen::Vector3d(u(rng), u(rng), u(rng));
}

Eigen::Quaterniond random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
}

TEST(QuatExp, IsARotationByTwiceTheLengthAboutTheVector) {
  std::mt19937 rng(1);
  for (double scale : {1e-9, 1e-4, 0.3, 1.4}) {
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::Vector3d v = random_vector(rng, scale);
      const Eigen::Quaterniond expected(Eigen::AngleAxisd(2 * v.norm(), v.normalized()));
      EXPECT_LT((quat_exp(v).coeffs() - expected.coeffs()).norm(), 1e-15) << v.transpose();
    }
  }
  EXPECT_EQ(quat_exp(Eigen::Vector3d(0, 0, 0)).coeffs(), Eigen::Quaterniond::Identity().coeffs());
}

TEST(QuatLog, InvertsExpUpToHalfATurnAndKeepsTheSign) {
  std::mt19937 rng(2);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Vector3d v = random_vector(rng, 1.8);  // |v| up to ~3.1 < π
    if (v.norm() >= M_PI) continue;
    EXPECT_LT((quat_log(quat_exp(v)) - v).norm(), 1e-12) << v.transpose();
    // Any unit quaternion, either sign: exp(log(q)) is q itself, with |log q| in [0, π].
    const Eigen::Quaterniond q = random_rotation(rng);
    const Eigen::Vector3d l = quat_log(q);
    EXPECT_LE(l.norm(), M_PI + 1e-15);
    EXPECT_LT((quat_exp(l).coeffs() - q.coeffs()).norm(), 1e-14);
  }
  // A small rotation and its negative are a short and a long way round.
  const Eigen::Quaterniond small = quat_exp(Eigen::Vector3d(1e-8, 0, 0));
  EXPECT_NEAR(quat_log(small).x(), 1e-8, 1e-22);
  EXPECT_NEAR(quat_log(Eigen::Quaterniond(-small.coeffs())).norm(), M_PI - 1e-8, 1e-14);
}

TEST(QuatExpLog, DerivativesThroughTheSmallAngleBranchMatchFiniteDifferences) {
  // The Taylor branches near zero must carry the derivatives of the functions they replace.
  using Ad3 = Eigen::AutoDiffScalar<Eigen::Vector3d>;
  for (const Eigen::Vector3d& v0 : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3e-7, -2e-7, 1e-7),
                                    Eigen::Vector3d(0.2, 0.1, -0.3)}) {
    Vec3<Ad3> v;
    for (int a = 0; a < 3; ++a)
      v[a] = Ad3(v0[a], 3, a);
    const Quat<Ad3> q = quat_exp(v);
    const Vec3<Ad3> back = quat_log(q);
    const double h = 1e-6;
    for (int a = 0; a < 3; ++a) {
      Eigen::Vector3d plus = v0, minus = v0;
      plus[a] += h;
      minus[a] -= h;
      const Eigen::Vector4d fd = (quat_exp(plus).coeffs() - quat_exp(minus).coeffs()) / (2 * h);
      for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(q.coeffs()[c].derivatives()[a], fd[c], 1e-8) << "v0 " << v0.transpose();
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(back[c].derivatives()[a], a == c ? 1.0 : 0.0, 1e-9);  // log ∘ exp = id
    }
  }
}

TEST(RotationAngles, AgreeWithEigenAndTellTheControlTurnsWay) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Quaterniond a = random_rotation(rng), b = random_rotation(rng);
    const double angle = a.angularDistance(b);  // Eigen: in [0, π]
    EXPECT_NEAR(rotation_angle_between(a, b), angle, 1e-12);
    EXPECT_NEAR(rotation_angle_between(a, Eigen::Quaterniond(-b.coeffs())), angle, 1e-12);
    // The control turn follows the signs: the same hemisphere goes the short way.
    const Eigen::Quaterniond near =
        a.coeffs().dot(b.coeffs()) >= 0 ? b : Eigen::Quaterniond(-b.coeffs());
    EXPECT_NEAR(control_turn(a, near), angle, 1e-12);
    EXPECT_NEAR(control_turn(a, Eigen::Quaterniond(-near.coeffs())), 2 * M_PI - angle, 1e-12);
    // The paper's distance: ‖a − b‖ with b on a's side, 2·sin(angle/4) for unit quaternions.
    EXPECT_NEAR(quaternion_distance(a, b), 2 * std::sin(angle / 4), 1e-12);
    EXPECT_NEAR(quaternion_distance(a, b), quaternion_distance(a, Eigen::Quaterniond(-b.coeffs())),
                1e-15);
  }
}

Eigen::Matrix3d rx(double a) {
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  return m;
}
Eigen::Matrix3d ry(double a) {
  Eigen::Matrix3d m;
  m << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);
  return m;
}
Eigen::Matrix3d rz(double a) {
  Eigen::Matrix3d m;
  m << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return m;
}

TEST(QuatFromEulerDeg, ComposesIntrinsicRotationsInTheGivenOrder) {
  const double d = M_PI / 180;
  const Eigen::Vector3d angles(30, -50, 120);
  const auto rotation = [&](const char* order) {
    return quat_from_euler_deg(angles, order).toRotationMatrix();
  };
  EXPECT_LT((rotation("XYZ") - rx(30 * d) * ry(-50 * d) * rz(120 * d)).norm(), 1e-14);
  EXPECT_LT((rotation("zyx") - rz(30 * d) * ry(-50 * d) * rx(120 * d)).norm(), 1e-14);
  EXPECT_LT((rotation("XYX") - rx(30 * d) * ry(-50 * d) * rx(120 * d)).norm(), 1e-14);
  EXPECT_NEAR(quat_from_euler_deg(Eigen::Vector3d(90, 0, 0), "XYZ").norm(), 1.0, 1e-15);
  for (const char* bad : {"XY", "XYZX", "XXY", "XYW", ""})
    EXPECT_THROW(quat_from_euler_deg(angles, bad), std::invalid_argument) << bad;
}

}  // namespace
}  // namespace saltus
