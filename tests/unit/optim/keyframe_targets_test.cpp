// What the keyframes ask of the optimised motion (optim/keyframe_targets.h): at whatever time a
// keyframe moves to, its root target puts the keyframe pose's CoM on the take-off parabola
// (checked by inverse dynamics), its rate is the target's time derivative, a given root position
// stays put, and keyframe quaternions are compared sign-aligned.

#include "saltus/optim/keyframe_targets.h"

#include <gtest/gtest.h>

#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(KeyframeTargets, RootTargetPutsThePosesComOnTheParabolaAtAnyTime) {
  const BodyModel model = test::bundled_model();
  Motion motion = test::twist_motion(model);
  motion.keyframes[2].root_position = Eigen::Vector3d(0.2, 3.0, -0.1);
  const KeyframeTargets targets(motion, model);
  ASSERT_EQ(targets.size(), 4);
  DynamicsData<double> data(model);
  BodyState<double> state(model.size());
  for (int i : {0, 1, 3}) {
    EXPECT_TRUE(targets.root_moves_with_time(i));
    for (int s = 0; s < model.size(); ++s) {
      state.joints[s].q = motion.keyframes[i].rotations[s];
      EXPECT_EQ(targets.rotation(i, s).coeffs(), motion.keyframes[i].rotations[s].coeffs());
    }
    for (double t : {motion.keyframes[i].time, motion.keyframes[i].time + 0.07, 1.0}) {
      state.root_position = targets.root(i, t);
      inverse_dynamics(model, data, state);
      EXPECT_LT((data.com - ballistic_com(motion.takeoff, t)).norm(), 1e-12) << i << " " << t;
      const double h = 1e-6;
      const Eigen::Vector3d rate = (targets.root(i, t + h) - targets.root(i, t - h)) / (2 * h);
      EXPECT_LT((targets.root_rate(i, t) - rate).norm(), 1e-8);
    }
  }
  EXPECT_FALSE(targets.root_moves_with_time(2));
  EXPECT_EQ(targets.root(2, 0.3), *motion.keyframes[2].root_position);
  EXPECT_EQ(targets.root(2, 1.9), *motion.keyframes[2].root_position);
  EXPECT_EQ(targets.root_rate(2, 1.0), Eigen::Vector3d::Zero());
}

TEST(AlignedTarget, TakesTheKeyframeQuaternionOnTheCurvesSide) {
  const Eigen::Quaterniond target(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()));
  const Eigen::Vector4d wxyz(target.w(), target.x(), target.y(), target.z());
  const Eigen::Vector4d near = wxyz + Eigen::Vector4d(0.01, -0.02, 0.0, 0.01);
  EXPECT_EQ(aligned_target(target, near), wxyz);
  EXPECT_EQ(aligned_target(target, -near), -wxyz);
}

}  // namespace
}  // namespace saltus
