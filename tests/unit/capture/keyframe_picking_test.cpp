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

}  // namespace
}  // namespace saltus
