// Keyframe picking: the picked keyframes, interpolated as the motion verbs do, stay within the
// quaternion tolerance of every captured frame.

#include "saltus/capture/keyframe_picking.h"

#include <gtest/gtest.h>

#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// Every frame of the interpolated tuck at 30 Hz as a keyframe: a smooth "capture".
Motion sampled_tuck(const BodyModel& model) {
  const Motion tuck = test::tuck_motion(model);
  const Trajectory<double> trajectory = interpolate_keyframes(tuck, model);
  Motion captured = tuck;
  captured.keyframes.clear();
  const int frames = 62;
  BodyState<double> state(model.size());
  for (int f = 0; f < frames; ++f) {
    const double t = tuck.flight_time() * f / (frames - 1);
    trajectory.sample(t, state);
    Keyframe k;
    k.time = t;
    for (const auto& joint : state.joints)
      k.rotations.push_back(joint.q);
    captured.keyframes.push_back(k);
  }
  return captured;
}

/// The largest quaternion distance between the verbs' interpolation of `picked` and `captured`.
double interpolation_error(const Motion& picked, const Motion& captured, const BodyModel& model) {
  const Trajectory<double> trajectory = interpolate_keyframes(picked, model);
  double worst = 0.0;
  for (const Keyframe& k : captured.keyframes)
    for (int s = 0; s < model.size(); ++s)
      worst = std::max(
          worst, quaternion_distance(trajectory.rotations[s].evaluate(k.time).q, k.rotations[s]));
  return worst;
}

TEST(KeyframePicking, TheFewestKeyframesInGreedyOrderThatMeetTheTolerance) {
  const BodyModel model = test::bundled_model();
  const Motion captured = sampled_tuck(model);
  const KeyframePick pick = pick_keyframes(captured, model);
  const int n = static_cast<int>(pick.frames.size());
  EXPECT_EQ(pick.frames.front(), 0);
  EXPECT_EQ(pick.frames.back(), static_cast<int>(captured.keyframes.size()) - 1);
  EXPECT_LT(n, static_cast<int>(captured.keyframes.size()) / 3);  // a smooth capture needs few
  const Motion picked = keep_keyframes(captured, pick.frames);
  EXPECT_LE(interpolation_error(picked, captured, model), captured.tolerances.quaternion);
  EXPECT_NEAR(interpolation_error(picked, captured, model), pick.max_quaternion_error, 1e-9);
  // One fewer, picked the same way, misses.
  const KeyframePick fewer = pick_keyframes(captured, model, n - 1);
  EXPECT_GT(fewer.max_quaternion_error, captured.tolerances.quaternion);
  EXPECT_NE(pick.rule.find("tolerance"), std::string::npos);
}

TEST(KeyframePicking, AGivenCount) {
  const BodyModel model = test::bundled_model();
  const Motion captured = sampled_tuck(model);
  const KeyframePick five = pick_keyframes(captured, model, 5);
  EXPECT_EQ(five.frames.size(), 5u);
  EXPECT_TRUE(std::is_sorted(five.frames.begin(), five.frames.end()));
  EXPECT_THROW(pick_keyframes(captured, model, 1), std::invalid_argument);
  EXPECT_THROW(pick_keyframes(captured, model, 63), std::invalid_argument);
  std::vector<int> every(62);
  for (int f = 0; f < 62; ++f)
    every[f] = f;
  EXPECT_LT(keyframe_errors_of(captured, every).max_quaternion_error, 1e-9);  // through all
}

TEST(KeyframePicking, StopsAtTheMostKeyframesOnACaptureNoFewReproduce) {
  // Issue 28: every step refits through every picked frame, so a jerky 500-frame flight took
  // 81 s to pick 500 keyframes (2000 frames: over 5 minutes). A zigzag no interpolation follows
  // between its frames stops at kMaxPickedKeyframes, saying by how much it still misses.
  // One segment: picking costs the same per segment, and the test stays well under a second.
  BodyModel model = test::bundled_model();
  Motion zigzag = sampled_tuck(model);
  model.segments.resize(1);
  zigzag.keyframes.clear();
  for (int f = 0; f < 120; ++f) {
    Keyframe k;
    k.time = f / 30.0;
    const Eigen::Quaterniond q(Eigen::AngleAxisd(f % 2 ? 0.6 : -0.6, Eigen::Vector3d::UnitX()));
    k.rotations.assign(model.size(), q);
    zigzag.keyframes.push_back(k);
  }
  const KeyframePick pick = pick_keyframes(zigzag, model);
  EXPECT_EQ(pick.frames.size(), static_cast<std::size_t>(kMaxPickedKeyframes));
  EXPECT_GT(pick.max_quaternion_error, zigzag.tolerances.quaternion);
  EXPECT_NEAR(pick.max_quaternion_error,
              keyframe_errors_of(zigzag, pick.frames).max_quaternion_error, 1e-12);
  EXPECT_THROW(pick_keyframes(zigzag, model, kMaxPickedKeyframes + 1), std::invalid_argument);
}

}  // namespace
}  // namespace saltus
