// Whole-body momentum and the composite inertia (dynamics/momentum.h) against independent paths:
// momentum from finite differences of the segments' world poses, the composite inertia against
// the momentum recursion and against the root wrench's response to a root acceleration.

#include "saltus/dynamics/momentum.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// Inverse dynamics of the interpolated tucked somersault at time t.
struct TuckAt {
  BodyModel model = test::bundled_model();
  Trajectory<double> trajectory = interpolate_keyframes(test::tuck_motion(model), model);
  DynamicsData<double> data{model};

  void at(double t) {
    BodyState<double> state(model.size());
    trajectory.sample(t, state);
    inverse_dynamics(model, data, state);
  }
};

TEST(WholeBodyMomentum, MatchesFiniteDifferencesOfTheSegmentPoses) {
  // P = Σ m_i ċ_i and L_G = Σ R_i I_i R_iᵀ ω_i + m_i (c_i − c) × ċ_i, with ċ_i and the world
  // angular velocities ω_i from central differences of the segments' world poses.
  TuckAt tuck;
  const double h = 1e-6;
  for (double t : {0.2, 0.7, 1.3, 1.9}) {
    tuck.at(t - h);
    const DynamicsData<double> before = tuck.data;
    tuck.at(t + h);
    const DynamicsData<double> after = tuck.data;
    tuck.at(t);
    const WholeBodyMomentum<double> m = whole_body_momentum(tuck.model, tuck.data);
    Eigen::Vector3d linear = Eigen::Vector3d::Zero(), angular = Eigen::Vector3d::Zero();
    for (int i = 0; i < tuck.model.size(); ++i) {
      const Segment& s = tuck.model.segments[i];
      auto com_of = [&](const DynamicsData<double>& d) {
        return Eigen::Vector3d(d.world_position[i] + d.world_rotation[i] * s.com);
      };
      const Eigen::Vector3d velocity = (com_of(after) - com_of(before)) / (2 * h);
      const Eigen::Matrix3d rotation_rate =
          (after.world_rotation[i] - before.world_rotation[i]) / (2 * h);
      const Eigen::Matrix3d w = rotation_rate * tuck.data.world_rotation[i].transpose();
      const Eigen::Vector3d omega(w(2, 1), w(0, 2), w(1, 0));
      const Eigen::Matrix3d& r = tuck.data.world_rotation[i];
      linear += s.mass * velocity;
      angular += r * s.inertia * r.transpose() * omega +
                 s.mass * (com_of(tuck.data) - tuck.data.com).cross(velocity);
    }
    EXPECT_GT(angular.norm(), 1.0) << "the body turns";
    EXPECT_LT((m.linear - linear).norm(), 1e-6 * linear.norm()) << "t=" << t;
    EXPECT_LT((m.angular_about_com - angular).norm(), 1e-6 * angular.norm()) << "t=" << t;
    EXPECT_LT((m.com_velocity - linear / tuck.model.total_mass()).norm(), 1e-6) << "t=" << t;
    EXPECT_EQ(m.com, tuck.data.com);
  }
}

TEST(CompositeInertia, GivesTheMomentumWhenTheJointsAreStill) {
  // With every joint still the body moves as one rigid body: its spatial momentum at the root,
  // summed segment by segment, is I_c times the root's spatial velocity.
  TuckAt tuck;
  BodyState<double> state(tuck.model.size());
  tuck.trajectory.sample(1.0, state);
  for (int i = 1; i < tuck.model.size(); ++i)
    state.joints[i].omega.setZero();
  state.joints[0].omega = Eigen::Vector3d(-6.0, 0.4, 1.1);
  state.root_velocity = Eigen::Vector3d(0.3, 2.0, -0.4);
  inverse_dynamics(tuck.model, tuck.data, state);
  const Vec6<double> momentum = spatial_momentum_at_root(tuck.model, tuck.data);
  const Vec6<double> predicted =
      composite_inertia_at_root(tuck.model, tuck.data) * tuck.data.velocity[0];
  EXPECT_GT(momentum.norm(), 10.0);
  EXPECT_LT((momentum - predicted).norm(), 1e-12 * momentum.norm());
  // I_c is a rigid-body inertia of the whole mass: symmetric, positive definite, mass block m·1.
  const Mat6<double> ic = composite_inertia_at_root(tuck.model, tuck.data);
  EXPECT_LT((ic - ic.transpose()).norm(), 1e-12);
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat6<double>>(ic).eigenvalues().minCoeff(), 0.0);
  EXPECT_LT(
      (ic.bottomRightCorner<3, 3>() - tuck.model.total_mass() * Eigen::Matrix3d::Identity()).norm(),
      1e-12);
}

TEST(InverseDynamics, CompositeInertiaPredictsTheRootWrench) {
  // The root wrench is affine in the root acceleration with slope I_c: check against two solves.
  const BodyModel model = test::bundled_model();
  DynamicsData<double> data(model);
  BodyState<double> state(model.size());
  state.joints[model.joint_index("knee_r")].q =
      Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitX()));
  state.joints[model.joint_index("knee_r")].omega = Eigen::Vector3d(3, 0, 0);
  state.joints[0].omega = Eigen::Vector3d(-4, 0.5, 0);
  inverse_dynamics(model, data, state);
  const Vec6<double> w0 = data.joint_wrench[0];
  const Mat6<double> ic = composite_inertia_at_root(model, data);
  state.joints[0].alpha = Eigen::Vector3d(1.5, -2, 0.25);
  inverse_dynamics(model, data, state);
  Vec6<double> da;
  da << state.joints[0].alpha, Eigen::Vector3d::Zero();
  EXPECT_LT((data.joint_wrench[0] - w0 - ic * da).norm(), 1e-10);
}

}  // namespace
}  // namespace saltus
