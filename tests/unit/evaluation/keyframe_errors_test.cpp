// Keyframe errors (evaluation/keyframe_errors.h) on keyframes taken from the trajectory itself
// (errors zero) and then moved by known amounts: a root target shifted by d gives d, a rotation
// turned by θ gives θ degrees and the quaternion distance 2·sin(θ/4).

#include "saltus/evaluation/keyframe_errors.h"

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// The tucked somersault's interpolation and a motion whose keyframes lie exactly on it.
struct OnTrajectory {
  BodyModel model = test::bundled_model();
  Trajectory<double> trajectory = interpolate_keyframes(test::tuck_motion(model), model);
  Motion motion;
  std::vector<double> times{0.0, 0.3, 0.95, 1.5, 2.04};
  std::vector<Eigen::Vector3d> targets;

  OnTrajectory() {
    for (double t : times) {
      Keyframe k;
      k.time = t;
      for (const auto& r : trajectory.rotations)
        k.rotations.push_back(r.evaluate(t).q);
      motion.keyframes.push_back(k);
      targets.push_back(trajectory.root_translation.evaluate(t).position);
    }
  }
  KeyframeErrors errors() const { return keyframe_errors(motion, trajectory, times, targets); }
};

TEST(KeyframeErrors, AreZeroForKeyframesOnTheTrajectory) {
  const KeyframeErrors e = OnTrajectory().errors();
  EXPECT_LT(e.max_translation_error_m, 1e-14);
  EXPECT_LT(e.max_quaternion_error, 1e-14);
  EXPECT_LT(e.max_rotation_error_deg, 1e-12);
}

TEST(KeyframeErrors, MeasureAShiftedRootTargetPerCoordinate) {
  OnTrajectory c;
  c.targets[2] += Eigen::Vector3d(0.03, -0.07, 0.05);
  EXPECT_NEAR(c.errors().max_translation_error_m, 0.07, 1e-12);
}

TEST(KeyframeErrors, MeasureATurnedRotationAsAngleAndQuaternionDistance) {
  const double theta = 10.0 * M_PI / 180.0;
  OnTrajectory c;
  const int knee = c.model.joint_index("knee_l");
  Eigen::Quaterniond& q = c.motion.keyframes[3].rotations[knee];
  q = q * Eigen::Quaterniond(Eigen::AngleAxisd(theta, Eigen::Vector3d(1, 2, -1).normalized()));
  const KeyframeErrors e = c.errors();
  EXPECT_NEAR(e.max_rotation_error_deg, 10.0, 1e-9);
  EXPECT_NEAR(e.max_quaternion_error, 2 * std::sin(theta / 4), 1e-12);
  // The sign of a keyframe quaternion does not matter (paper eq. 3 aligns it).
  q.coeffs() *= -1.0;
  EXPECT_NEAR(c.errors().max_quaternion_error, 2 * std::sin(theta / 4), 1e-12);
  EXPECT_NEAR(c.errors().max_rotation_error_deg, 10.0, 1e-9);
}

TEST(KeyframeErrors, AreMeasuredAtTheGivenTimes) {
  // The same keyframes judged at times 0.05 s late: the trajectory has moved on.
  OnTrajectory c;
  std::vector<double> late = c.times;
  for (std::size_t i = 1; i + 1 < late.size(); ++i)
    late[i] += 0.05;
  const KeyframeErrors e = keyframe_errors(c.motion, c.trajectory, late, c.targets);
  EXPECT_GT(e.max_rotation_error_deg, 1.0);
  EXPECT_GT(e.max_translation_error_m, 0.005);
}

}  // namespace
}  // namespace saltus
