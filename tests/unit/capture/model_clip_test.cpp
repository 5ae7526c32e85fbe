// The body model as a motion-capture clip (capture/model_clip.h), checked by an independent path:
// the clip's own forward kinematics (BVH offsets in cm, Z·X·Y Euler channels) puts every joint
// where the dynamics' forward kinematics puts its segment, on seeded random poses; an export
// samples the trajectory at the stated rate, its last frame the landing.

#include "saltus/capture/model_clip.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <stdexcept>

#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/math/quaternion.h"
#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

std::vector<BodyState<double>> random_states(const BodyModel& model, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<BodyState<double>> states(count, BodyState<double>(model.size()));
  for (BodyState<double>& s : states) {
    s.root_position = Eigen::Vector3d(n(rng), 1.0 + n(rng), n(rng));
    for (auto& joint : s.joints)
      joint.q = Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
  }
  return states;
}

TEST(ModelClip, ItsForwardKinematicsIsTheBodysOwn) {
  const BodyModel model = test::bundled_model();
  for (unsigned seed : {1u, 2u, 3u}) {
    const std::vector<BodyState<double>> states = random_states(model, 5, seed);
    const MocapClip clip = model_clip_from_states(model, 1.0 / 60, states);
    ASSERT_EQ(clip.joint_count(), model.size());
    ASSERT_EQ(clip.frame_count(), 5);
    EXPECT_DOUBLE_EQ(clip.frame_time, 1.0 / 60);
    std::set<int> segments;
    for (const MocapJoint& joint : clip.joints)
      segments.insert(model.segment_index(joint.name));
    EXPECT_EQ(static_cast<int>(segments.size()), model.size()) << "each segment once";
    EXPECT_EQ(clip.joints[0].parent, -1);
    EXPECT_LT(model.segments[model.segment_index(clip.joints[0].name)].parent, 0);
    DynamicsData<double> data(model);
    for (int f = 0; f < clip.frame_count(); ++f) {
      inverse_dynamics(model, data, states[f]);
      const MocapPose pose = mocap_pose(clip, f);
      for (int j = 0; j < clip.joint_count(); ++j) {
        const int s = model.segment_index(clip.joints[j].name);
        EXPECT_LT((pose.world_position[j] / 100.0 - data.world_position[s]).norm(), 1e-12)
            << "seed " << seed << " frame " << f << " " << clip.joints[j].name;
        EXPECT_LT((pose.world_rotation[j].toRotationMatrix() - data.world_rotation[s]).norm(),
                  1e-12)
            << "seed " << seed << " frame " << f << " " << clip.joints[j].name;
      }
    }
  }
}

TEST(ModelClip, TheRestPoseIsTheIdentityPose) {
  // BVH's rest pose (every channel zero) is Saltus's identity pose: the model's own joint
  // positions, and an End Site at each segment tip no joint continues.
  const BodyModel model = test::bundled_model();
  const MocapClip clip = model_skeleton_clip(model);
  EXPECT_EQ(clip.frame_count(), 0);
  BodyState<double> identity(model.size());
  DynamicsData<double> data(model);
  inverse_dynamics(model, data, identity);
  MocapClip with_frame = clip;
  with_frame.frame_time = 0.1;
  with_frame.frames.assign(1, std::vector<double>(clip.column_count(), 0.0));
  const MocapPose rest = mocap_rest_pose(with_frame);
  int end_sites = 0;
  for (int j = 0; j < clip.joint_count(); ++j) {
    const int s = model.segment_index(clip.joints[j].name);
    EXPECT_LT((rest.world_position[j] / 100.0 - data.world_position[s]).norm(), 1e-12);
    end_sites += static_cast<int>(clip.joints[j].end_sites.size());
    for (const Eigen::Vector3d& tip : clip.joints[j].end_sites)
      EXPECT_NEAR(tip.y() / 100.0, model.segments[s].shape.length, 1e-12);
  }
  EXPECT_GT(end_sites, 0);
}

TEST(ModelClip, TheFrameCountRoundsAndIsAtLeastTwo) {
  EXPECT_EQ(motion_clip_frame_count(1.0, 60.0), 61.0);
  EXPECT_EQ(motion_clip_frame_count(1.0, 99999.6), 100001.0) << "rounded, not floored";
  EXPECT_EQ(motion_clip_frame_count(1.0, 99999.4), 100000.0);
  EXPECT_EQ(motion_clip_frame_count(1.0, 0.1), 2.0);
  EXPECT_EQ(motion_clip_frame_count(1.0, 1e300), 1e300) << "no overflow";
  EXPECT_TRUE(std::isnan(motion_clip_frame_count(1.0, std::nan(""))));
}

TEST(ModelClip, AMotionIsSampledAtTheRateWithTheLandingLast) {
  const BodyModel model = test::bundled_model();
  const Motion motion = test::tuck_motion(model);
  const Trajectory<double> trajectory = interpolate_keyframes(motion, model);
  const double duration = trajectory.duration();
  for (double fps : {24.0, 60.0, 120.0, 0.1}) {
    const MocapClip clip = motion_clip(model, trajectory, fps);
    const int frames = std::max(2, static_cast<int>(std::lround(duration * fps)) + 1);
    ASSERT_EQ(motion_clip_frame_count(duration, fps), frames) << fps;
    ASSERT_EQ(clip.frame_count(), frames) << fps;
    EXPECT_NEAR(clip.frame_time * (frames - 1), duration, 1e-12) << fps;
    // The last frame is the landing pose: root position and every joint's local rotation.
    BodyState<double> landing(model.size());
    trajectory.sample(duration, landing);
    for (int j = 0; j < clip.joint_count(); ++j) {
      const int s = model.segment_index(clip.joints[j].name);
      EXPECT_LT(
          rotation_angle_between(mocap_local_rotation(clip, j, frames - 1), landing.joints[s].q),
          1e-9)
          << fps << " " << clip.joints[j].name;
    }
    const std::vector<double>& last = clip.frames.back();
    EXPECT_LT((Eigen::Vector3d(last[0], last[1], last[2]) / 100.0 - landing.root_position).norm(),
              1e-12);
  }
  EXPECT_THROW(motion_clip(model, trajectory, 0.0), std::invalid_argument);
  EXPECT_THROW(motion_clip(model, trajectory, 1e300), std::invalid_argument) << "no int count";
  EXPECT_THROW(model_clip_from_states(model, 0.0, random_states(model, 1, 4)),
               std::invalid_argument);
  EXPECT_THROW(model_clip_from_states(model, 0.1, {BodyState<double>(model.size() - 1)}),
               std::invalid_argument);
}

}  // namespace
}  // namespace saltus
