// Motion-capture clips in memory: Euler channels in every order, forward kinematics, validation.

#include "saltus/capture/mocap_clip.h"

#include <gtest/gtest.h>

#include <random>

#include "saltus/math/quaternion.h"

namespace saltus {
namespace {

const std::vector<std::pair<std::string, std::vector<int>>> kOrders{
    {"XYZ", {0, 1, 2}}, {"XZY", {0, 2, 1}}, {"YXZ", {1, 0, 2}},
    {"YZX", {1, 2, 0}}, {"ZXY", {2, 0, 1}}, {"ZYX", {2, 1, 0}}};

TEST(MocapClip, EulerChannelsAgreeWithTheLibrarysIntrinsicEuler) {
  // Two implementations: the clip's channel product and math/quaternion's Euler parser.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-180.0, 180.0);
  for (const auto& [name, axes] : kOrders) {
    for (int i = 0; i < 20; ++i) {
      const Eigen::Vector3d a(angle(rng), angle(rng), angle(rng));
      const Eigen::Quaterniond q = rotation_from_euler_deg(axes, {a[0], a[1], a[2]});
      EXPECT_LT(rotation_angle_between(q, quat_from_euler_deg(a, name)), 1e-12) << name;
    }
  }
}

TEST(MocapClip, EulerDecompositionRoundTripsInEveryOrder) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> outer(-179.0, 179.0);
  std::uniform_real_distribution<double> middle(-89.0, 89.0);
  for (const auto& [name, axes] : kOrders) {
    for (int i = 0; i < 200; ++i) {
      const std::vector<double> a{outer(rng), middle(rng), outer(rng)};
      const Eigen::Quaterniond q = rotation_from_euler_deg(axes, a);
      const std::vector<double> back = euler_deg_from_rotation(axes, q);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(back[k], a[k], 1e-9) << name << " angle " << k;
      EXPECT_LT(rotation_angle_between(rotation_from_euler_deg(axes, back), q), 1e-12) << name;
    }
  }
}

TEST(MocapClip, EulerDecompositionIsExactAtGimbalLock) {
  for (const auto& [name, axes] : kOrders) {
    for (double middle : {90.0, -90.0}) {
      for (double outer : {-150.0, -20.0, 0.0, 35.0, 170.0}) {
        const Eigen::Quaterniond q = rotation_from_euler_deg(axes, {outer, middle, 40.0});
        const std::vector<double> back = euler_deg_from_rotation(axes, q);
        EXPECT_NEAR(std::abs(back[1]), 90.0, 1e-6) << name;
        EXPECT_LT(rotation_angle_between(rotation_from_euler_deg(axes, back), q), 1e-7) << name;
      }
    }
  }
}

/// root (position channels, then Z rotation) -> arm (X rotation) -> End Site.
MocapClip two_joint_clip() {
  MocapClip clip;
  MocapJoint root;
  root.name = "root";
  root.offset = Eigen::Vector3d(5, 5, 5);  // replaced by the position channels
  root.channels = {MocapChannel::kXposition, MocapChannel::kYposition, MocapChannel::kZposition,
                   MocapChannel::kZrotation};
  MocapJoint arm;
  arm.name = "arm";
  arm.parent = 0;
  arm.offset = Eigen::Vector3d(0, 1, 0);
  arm.channels = {MocapChannel::kXrotation};
  arm.first_column = 4;
  arm.end_sites = {Eigen::Vector3d(0, 2, 0)};
  clip.joints = {root, arm};
  clip.frame_time = 0.1;
  clip.frames = {{1, 2, 3, 90, 90}};
  return clip;
}

TEST(MocapClip, ForwardKinematicsByHand) {
  const MocapClip clip = two_joint_clip();
  validate_clip(clip);
  const MocapPose pose = mocap_pose(clip, 0);
  EXPECT_LT((pose.world_position[0] - Eigen::Vector3d(1, 2, 3)).norm(), 1e-12);
  // Rz(90) takes the arm's offset (0, 1, 0) to (−1, 0, 0).
  EXPECT_LT((pose.world_position[1] - Eigen::Vector3d(0, 2, 3)).norm(), 1e-12);
  // The End Site (0, 2, 0) turned by Rx(90) to (0, 0, 2), then by Rz(90): still (0, 0, 2).
  const Eigen::Vector3d tip =
      pose.world_position[1] + pose.world_rotation[1] * Eigen::Vector3d(0, 2, 0);
  EXPECT_LT((tip - Eigen::Vector3d(0, 2, 5)).norm(), 1e-12);
  const MocapPose rest = mocap_rest_pose(clip);
  EXPECT_LT((rest.world_position[1] - Eigen::Vector3d(5, 6, 5)).norm(), 1e-12);
}

TEST(MocapClip, ValidationNamesTheProblem) {
  MocapClip clip = two_joint_clip();
  clip.joints[1].name = "root";
  EXPECT_THROW(validate_clip(clip), std::invalid_argument);
  clip = two_joint_clip();
  clip.frames[0].pop_back();
  try {
    validate_clip(clip);
    FAIL() << "a short frame was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("frame 0 has 4 values, expected 5"), std::string::npos)
        << e.what();
  }
  clip = two_joint_clip();
  clip.frames[0][2] = std::nan("");
  EXPECT_THROW(validate_clip(clip), std::invalid_argument);
  clip = two_joint_clip();
  clip.frame_time = 0;
  EXPECT_THROW(validate_clip(clip), std::invalid_argument);
}

}  // namespace
}  // namespace saltus
