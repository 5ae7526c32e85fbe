// Inverse dynamics against analytic cases: free fall, torque-free spin, static support.

#include "saltus/dynamics/inverse_dynamics.h"

#include <gtest/gtest.h>

#include "saltus/base/constants.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

BodyModel single_body(const Eigen::Matrix3d& inertia, const Eigen::Vector3d& com) {
  BodyModel m;
  m.name = "brick";
  Segment s;
  s.name = "brick";
  s.joint = "root";
  s.mass = 7.0;
  s.com = com;
  s.inertia = inertia;
  m.segments.push_back(s);
  return m;
}

Eigen::Vector3d force_of(const Vec6<double>& w) {
  return w.head<3>();
}
Eigen::Vector3d moment_of(const Vec6<double>& w) {
  return w.tail<3>();
}

TEST(InverseDynamics, RigidBodyInFreeFallNeedsNoWrench) {
  const BodyModel model =
      single_body(Eigen::Vector3d(0.1, 0.2, 0.3).asDiagonal(), Eigen::Vector3d(0.05, -0.1, 0.02));
  DynamicsData<double> data(model);
  BodyState<double> state(1);
  state.joints[0].q =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  state.root_position = Eigen::Vector3d(1, 2, 3);
  state.root_velocity = Eigen::Vector3d(0.3, 4.0, -1.0);
  // The CoM (not the origin) falls with g; at rest rotationally the origin does too.
  state.root_acceleration = gravity();
  inverse_dynamics(model, data, state);
  EXPECT_LT(root_wrench_force_first(data).norm(), 1e-12);
  EXPECT_LT(residual_world_about_com(data).norm(), 1e-12);
}

TEST(InverseDynamics, SpinAboutPrincipalAxisNeedsNoMoment) {
  const BodyModel model =
      single_body(Eigen::Vector3d(0.1, 0.2, 0.3).asDiagonal(), Eigen::Vector3d::Zero());
  DynamicsData<double> data(model);
  BodyState<double> state(1);
  state.joints[0].omega = Eigen::Vector3d(0, 5.0, 0);  // about the y principal axis
  state.root_acceleration = gravity();
  inverse_dynamics(model, data, state);
  EXPECT_LT(root_wrench_force_first(data).norm(), 1e-12);
}

TEST(InverseDynamics, SpinAboutNonPrincipalAxisNeedsOmegaCrossIOmega) {
  const Eigen::Matrix3d inertia = Eigen::Vector3d(0.1, 0.2, 0.3).asDiagonal();
  const BodyModel model = single_body(inertia, Eigen::Vector3d::Zero());
  DynamicsData<double> data(model);
  BodyState<double> state(1);
  const Eigen::Vector3d omega(1.0, 2.0, -0.5);
  state.joints[0].omega = omega;
  state.root_acceleration = gravity();
  inverse_dynamics(model, data, state);
  const Vec6<double> w = root_wrench_force_first(data);
  const Eigen::Vector3d expected = omega.cross(inertia * omega);  // Euler's equations, α = 0
  EXPECT_GT(expected.norm(), 0.1);
  EXPECT_LT((moment_of(w) - expected).norm(), 1e-12);
  EXPECT_LT(force_of(w).norm(), 1e-12);
}

TEST(InverseDynamics, StaticUprightPoseNeedsExactlyBodyWeight) {
  const BodyModel model = test::bundled_model();
  DynamicsData<double> data(model);
  BodyState<double> state(model.size());
  state.root_position = Eigen::Vector3d(0.2, 1.0, -0.3);
  inverse_dynamics(model, data, state);
  const double weight = model.total_mass() * 9.81;
  const Vec6<double> root = root_wrench_force_first(data);
  EXPECT_NEAR(root[0], 0.0, 1e-10);
  EXPECT_NEAR(root[1], weight, 1e-10);
  EXPECT_NEAR(root[2], 0.0, 1e-10);
  // About the CoM the support must be a pure force: the moment vanishes.
  const Vec6<double> res = residual_world_about_com(data);
  EXPECT_NEAR(res[1], weight, 1e-10);
  EXPECT_LT(moment_of(res).norm(), 1e-10);
  // About the root origin the moment is (c − root) × W.
  const Eigen::Vector3d lever = data.com - state.root_position;
  EXPECT_LT((moment_of(root) - lever.cross(Eigen::Vector3d(0, weight, 0))).norm(), 1e-10);
}

TEST(InverseDynamics, StaticPoseInAnyOrientationStillNeedsBodyWeight) {
  const BodyModel model = test::bundled_model();
  DynamicsData<double> data(model);
  BodyState<double> state(model.size());
  state.joints[0].q =
      Eigen::Quaterniond(Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 0.3, 0).normalized()));
  state.joints[model.joint_index("hip_l")].q =
      Eigen::Quaterniond(Eigen::AngleAxisd(-1.2, Eigen::Vector3d::UnitX()));
  inverse_dynamics(model, data, state);
  const Vec6<double> res = residual_world_about_com(data);
  EXPECT_LT((force_of(res) - Eigen::Vector3d(0, model.total_mass() * 9.81, 0)).norm(), 1e-10);
  EXPECT_LT(moment_of(res).norm(), 1e-10);
}

}  // namespace
}  // namespace saltus
