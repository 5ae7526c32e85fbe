// The stroboscopic figure's poses: equal time steps from take-off to landing, the spin rate of a
// rigid body against its root segment's angular velocity from the spline (an independent path),
// the side the flight is seen from, and the stated spread.

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/base/constants.h"
#include "saltus/body/mass_properties.h"
#include "saltus/evaluation/stroboscope.h"
#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// A straight back somersault in one fixed pose (every joint still): a rigid body.
Motion rigid_somersault(const BodyModel& model) {
  Motion m = test::base_motion("rigid");
  m.keyframes = {test::keyframe(model, 0.0, {0, 0, -40, -20}),
                 test::keyframe(model, 0.68, {-120, 0, -40, -20}),
                 test::keyframe(model, 1.36, {-240, 0, -40, -20}),
                 test::keyframe(model, 2.04, {-360, 0, -40, -20})};
  return m;
}

TEST(Stroboscope, PosesAtEqualStepsFromTakeoffToLanding) {
  const BodyModel model = test::bundled_model();
  const Trajectory<double> trajectory = interpolate_keyframes(test::tuck_motion(model), model);
  const Stroboscope s = stroboscope(model, trajectory, 9);
  ASSERT_EQ(s.poses.size(), 9u);
  EXPECT_DOUBLE_EQ(s.poses.front().time, 0.0);
  EXPECT_DOUBLE_EQ(s.poses.back().time, trajectory.duration());
  for (std::size_t i = 0; i < s.poses.size(); ++i) {
    EXPECT_NEAR(s.poses[i].time, trajectory.duration() * static_cast<double>(i) / 8.0, 1e-12);
    // Each pose is the trajectory's at its time, moved by its shift.
    const SampleRecord exact = evaluate_trajectory(model, trajectory, {s.poses[i].time}).front();
    for (int k = 0; k < model.size(); ++k) {
      EXPECT_LT(
          (s.poses[i].sample.segment_position[k] - s.poses[i].shift - exact.segment_position[k])
              .norm(),
          1e-12);
      EXPECT_LT(s.poses[i].sample.segment_rotation[k].angularDistance(exact.segment_rotation[k]),
                1e-12);
    }
  }
  EXPECT_EQ(s.com_path.size(), static_cast<std::size_t>(kDefaultSamples));
  EXPECT_THROW(stroboscope(model, trajectory, 1), std::invalid_argument);
}

TEST(Stroboscope, SpinOfARigidBodyIsItsRootSegmentsAngularVelocity) {
  const BodyModel model = test::bundled_model();
  const Trajectory<double> trajectory = interpolate_keyframes(rigid_somersault(model), model);
  const Stroboscope s = stroboscope(model, trajectory, 12);
  BodyState<double> state(model.size());
  double fastest = 0.0;
  for (const StroboscopePose& pose : s.poses) {
    trajectory.sample(pose.time, state);
    // The root's angular velocity in its own frame, turned into the world: a rigid body's ω.
    const Eigen::Vector3d omega = state.joints[0].q * state.joints[0].omega;
    const double rev_per_s = omega.norm() / (2.0 * kPi);
    EXPECT_NEAR(pose.spin_rev_per_s, rev_per_s, 1e-6 * (1.0 + rev_per_s)) << "t = " << pose.time;
    fastest = std::max(fastest, pose.spin_rev_per_s);
  }
  // One somersault in 2.04 s: about half a turn a second on average.
  EXPECT_GT(fastest, 0.4);
}

TEST(Stroboscope, SeenAcrossTheTakeoffVelocityTheFlightRunningRight) {
  const BodyModel model = test::bundled_model();
  Motion motion = test::tuck_motion(model);
  motion.takeoff.com_velocity = Eigen::Vector3d(9.0, 10.0, 0.0);  // travels far along +x
  const Trajectory<double> trajectory = interpolate_keyframes(motion, model);
  const Stroboscope s = stroboscope(model, trajectory);
  EXPECT_TRUE(s.along_velocity);
  // The interpolated keyframes' CoM keeps to the take-off parabola within centimetres.
  EXPECT_LT((s.right - Eigen::Vector3d::UnitX()).norm(), 0.02);
  EXPECT_NEAR(s.view_direction.dot(Eigen::Vector3d::UnitY()), 0.0, 1e-12);
  EXPECT_NEAR(s.view_direction.dot(s.right), 0.0, 1e-12);
  // right = view × up: the flight runs to the right of the picture.
  EXPECT_LT((s.view_direction.cross(Eigen::Vector3d::UnitY()) - s.right).norm(), 1e-12);
  EXPECT_GT(s.travel_m, 10.0);
  EXPECT_EQ(s.spread_m, 0.0);  // far enough apart on their own
  EXPECT_EQ(s.poses.size(), static_cast<std::size_t>(kDefaultStroboscopePoses));
  for (const StroboscopePose& pose : s.poses)
    EXPECT_EQ(pose.shift.norm(), 0.0);
}

TEST(Stroboscope, AFlightInPlaceIsSpreadByTheStatedStep) {
  const BodyModel model = test::bundled_model();
  Motion motion = test::tuck_motion(model);
  motion.takeoff.com_velocity = Eigen::Vector3d(0.0, 10.0, 0.0);
  const Trajectory<double> trajectory = interpolate_keyframes(motion, model);
  const Stroboscope s = stroboscope(model, trajectory, 10);
  // No horizontal speed: seen from the athlete's right, along the body's left at take-off (x).
  EXPECT_FALSE(s.along_velocity);
  EXPECT_LT((s.view_direction - Eigen::Vector3d::UnitX()).norm(), 1e-9);
  EXPECT_LT((s.right - Eigen::Vector3d::UnitZ()).norm(), 1e-9);
  const double wanted = kStroboscopeSpacingPerHeight * standing_body(model).height();
  EXPECT_NEAR(s.step_m, wanted, 1e-12);
  EXPECT_NEAR(s.spread_m, wanted - s.travel_m / 9.0, 1e-12);
  EXPECT_GT(s.spread_m, 0.5);
  for (std::size_t i = 0; i < s.poses.size(); ++i)
    EXPECT_LT((s.poses[i].shift - s.spread_m * static_cast<double>(i) * s.right).norm(), 1e-12);
  // The drawn CoMs go from take-off to landing by the travel and the spread together, and the
  // drawn path passes through them.
  const double drawn = (s.poses.back().sample.com - s.poses.front().sample.com).dot(s.right);
  EXPECT_NEAR(drawn, s.travel_m + 9.0 * s.spread_m, 1e-9);
  EXPECT_LT((s.com_path.front() - s.poses.front().sample.com).norm(), 1e-9);
  EXPECT_LT((s.com_path.back() - s.poses.back().sample.com).norm(), 1e-9);
}

}  // namespace
}  // namespace saltus
