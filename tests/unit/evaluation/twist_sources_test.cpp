// Where a twist comes from (evaluation/twist_sources.h), on flights whose answer is known by
// construction: a symmetric straight somersault has no tilt to share; the same movements with the
// angular momentum tilted at take-off owe all their tilt to the take-off; with the momentum about
// the somersault axis and one arm kept overhead, all of it to the arms and none to the take-off;
// the mirror image of that flight tilts the other way with the arms' shares swapped. Shares add
// up to the whole within the stated interaction.

#include "saltus/evaluation/twist_sources.h"

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/formats/motion_file.h"

namespace saltus {
namespace {

MotionFile m1() {
  return load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                          "/motions/M1-straight-back-somersault.motion.json");
}

double share(const TwistSources& s, const std::string& source) {
  for (const TwistShare& x : s.shares)
    if (x.source == source) return x.tilt_deg;
  ADD_FAILURE() << "no share " << source;
  return 0.0;
}

/// M1 with the joints of one arm kept as they are at take-off (overhead) for the whole flight.
Motion one_arm_up(const MotionFile& f, const std::string& side) {
  Motion m = f.motion;
  m.spline.reset();
  for (const char* joint : {"shoulder", "elbow"}) {
    const int k = f.model.joint_index(std::string(joint) + "_" + side);
    for (Keyframe& key : m.keyframes)
      key.rotations[k] = m.keyframes.front().rotations[k];
  }
  return m;
}

TEST(TwistSources, ASymmetricSomersaultHasNoTiltToShare) {
  const MotionFile f = m1();
  const TwistSources s = twist_sources(f.motion, f.model);
  EXPECT_LT(std::abs(s.total_tilt_deg), 0.01);
  for (const TwistShare& x : s.shares)
    EXPECT_LT(std::abs(x.tilt_deg), 0.01) << x.source;
  EXPECT_NE(s.sentence.find("nothing to twist with"), std::string::npos) << s.sentence;
}

TEST(TwistSources, AMomentumTiltedAtTakeOffOwesItAllTheTilt) {
  const MotionFile f = m1();
  Motion m = f.motion;
  const double L = f.motion.takeoff.angular_momentum->norm(), tilt = 20.0 * M_PI / 180.0;
  m.takeoff.angular_momentum = Eigen::Vector3d(-L * std::cos(tilt), 0.0, L * std::sin(tilt));
  const TwistSources s = twist_sources(m, f.model);
  EXPECT_GT(std::abs(s.total_tilt_deg), 5.0);
  EXPECT_NEAR(share(s, "take-off"), s.total_tilt_deg, 1e-6 * std::abs(s.total_tilt_deg));
  for (const char* movement : {"left arm", "right arm", "legs", "trunk"})
    EXPECT_LT(std::abs(share(s, movement)), 1e-6) << movement;
  EXPECT_LT(std::abs(s.interaction_deg), 1e-6);
  EXPECT_NE(s.sentence.find("100 % came from the take-off"), std::string::npos) << s.sentence;
}

TEST(TwistSources, OneArmKeptUpMakesAllTheTiltAndItsMirrorTheOpposite) {
  const MotionFile f = m1();
  const TwistSources right = twist_sources(one_arm_up(f, "r"), f.model);
  const TwistSources left = twist_sources(one_arm_up(f, "l"), f.model);
  EXPECT_GT(std::abs(right.total_tilt_deg), 2.0);
  // The take-off (momentum about the somersault axis) gives none; the arms give the tilt, in
  // halves (each arm is half of the asymmetry between them), the rest interacting little.
  EXPECT_LT(std::abs(share(right, "take-off")), 0.05 * std::abs(right.total_tilt_deg));
  const double arms = share(right, "left arm") + share(right, "right arm");
  EXPECT_NEAR(arms, right.total_tilt_deg, 0.25 * std::abs(right.total_tilt_deg));
  EXPECT_NEAR(right.interaction_deg,
              right.total_tilt_deg - arms - share(right, "take-off") - share(right, "legs") -
                  share(right, "trunk"),
              1e-9);
  // The mirror image: opposite tilt and twist, the arms' shares swapped.
  EXPECT_NEAR(left.total_tilt_deg, -right.total_tilt_deg, 1e-6 * std::abs(right.total_tilt_deg));
  EXPECT_NEAR(left.twists, -right.twists, 1e-6);
  EXPECT_NEAR(share(left, "left arm"), -share(right, "right arm"), 1e-6);
  EXPECT_NEAR(share(left, "right arm"), -share(right, "left arm"), 1e-6);
}

TEST(TwistSources, SymmetricPartsOfJoints) {
  const MotionFile f = m1();
  const Motion lifted = one_arm_up(f, "r");
  const Motion symmetric = with_symmetric_joints(lifted, f.model, {"shoulder_l", "shoulder_r"});
  const int l = f.model.joint_index("shoulder_l"), r = f.model.joint_index("shoulder_r");
  for (const Keyframe& k : symmetric.keyframes) {
    const Eigen::Quaterniond a = k.rotations[l], b = k.rotations[r];
    // Each side is the other's mirror image now.
    EXPECT_NEAR(std::abs(a.coeffs().dot(Eigen::Quaterniond(b.w(), b.x(), -b.y(), -b.z()).coeffs())),
                1.0, 1e-12);
  }
  // The root and the take-off are not touched.
  EXPECT_EQ(symmetric.keyframes[2].rotations[0].coeffs(),
            lifted.keyframes[2].rotations[0].coeffs());
  EXPECT_EQ(symmetric.takeoff.com_velocity, lifted.takeoff.com_velocity);
}

}  // namespace
}  // namespace saltus
