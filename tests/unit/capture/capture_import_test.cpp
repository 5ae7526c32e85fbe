// Pieces of the capture import (capture/capture_import.h) on closed forms: the somersault angle
// of rotations about x by known angles, unwrapped past half a turn; the capture's own trajectory
// through every captured frame (root positions and rotations), with its free ends outside the
// flight. Whole imports of exact free flights are in integration/capture_import_test.cpp.

#include "saltus/capture/capture_import.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/math/quaternion.h"
#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(SomersaultAngles, AreTheTurnAboutXUnwrapped) {
  // Rx(θ)·Ry(φ): the long (y) axis turns by θ about x whatever the twist φ about it; θ runs
  // backward past −360° in 35° steps, so atan2 alone would jump by 2π.
  std::vector<Eigen::Quaterniond> rotations;
  std::vector<double> expected;
  for (int k = 0; k <= 16; ++k) {
    const double theta = -35.0 * k / kDegreesPerRadian, phi = 0.3 * k;
    expected.push_back(theta);
    rotations.push_back(Eigen::Quaterniond(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitX()) *
                                           Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitY())));
  }
  const std::vector<double> angles = somersault_angles(rotations);
  ASSERT_EQ(angles.size(), expected.size());
  for (std::size_t k = 0; k < angles.size(); ++k)
    EXPECT_NEAR(angles[k], expected[k], 1e-12) << k;
}

TEST(CapturedTrajectory, PassesThroughEveryCapturedFrame) {
  // Frames of the twisting motion's interpolation, 1/60 s apart, root positions on the
  // interpolation's root curve: the capture's own splines meet each of them.
  const BodyModel model = test::bundled_model();
  const Motion source = test::twist_motion(model);
  const Trajectory<double> curve = interpolate_keyframes(source, model);
  Motion captured = source;
  captured.keyframes.clear();
  const int frames = 61;
  const double frame_time = curve.duration() / (frames - 1);
  BodyState<double> state(model.size());
  for (int f = 0; f < frames; ++f) {
    curve.sample(f * frame_time, state);
    Keyframe k;
    k.time = f * frame_time;
    for (const auto& joint : state.joints)
      k.rotations.push_back(joint.q);
    k.root_position = state.root_position;
    captured.keyframes.push_back(k);
  }
  const Trajectory<double> own = captured_trajectory(captured, model);
  EXPECT_LT(own.knots.front(), 0.0);
  EXPECT_GT(own.knots.back(), captured.flight_time());
  for (const Keyframe& k : captured.keyframes) {
    EXPECT_LT((own.root_translation.evaluate(k.time).position - *k.root_position).norm(), 1e-9)
        << k.time;
    for (int s = 0; s < model.size(); ++s)
      EXPECT_LT(rotation_angle_between(own.rotations[s].evaluate(k.time).q, k.rotations[s]), 1e-6)
          << k.time << " segment " << s;
  }
  captured.keyframes[5].root_position.reset();
  EXPECT_THROW(captured_trajectory(captured, model), std::invalid_argument);
  captured.keyframes.resize(2);
  EXPECT_THROW(captured_trajectory(captured, model), std::invalid_argument);
}

}  // namespace
}  // namespace saltus
