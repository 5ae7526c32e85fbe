// Joint coordinates: the Cardan split is the rotation's (round trip), its rate map is the
// angular velocity's (finite differences of the rotation), its moments do the same work as the
// moment vector, and each named coordinate means what an anatomist means, checked on poses built
// from where the limb points (a thigh swung forward is hip flexion on either side).

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "saltus/body/joint_coordinates.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

constexpr double kDeg = M_PI / 180.0;

Eigen::Quaterniond about(const Eigen::Vector3d& axis, double angle_rad) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle_rad, axis.normalized()));
}

/// The value of the coordinate named `name` of the joint of `segment` at rotation q.
double value_of(const BodyModel& model, const std::string& segment, const std::string& name,
                const Eigen::Quaterniond& q) {
  const int index = model.segment_index(segment);
  const JointCoordinates c = joint_coordinates(model, index);
  const JointCoordinateState s =
      joint_coordinate_state(c, q, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  for (int i = 0; i < 3; ++i)
    if (c.coordinates[i].name == name) return s.value[i];
  ADD_FAILURE() << "no coordinate " << name << " at " << segment;
  return 0.0;
}

TEST(JointCoordinates, CardanAnglesRebuildTheRotation) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), tilt(-1.4, 1.4);
  for (int n = 0; n < 200; ++n) {
    const Eigen::Vector3d abc(angle(rng), tilt(rng), angle(rng));
    const Eigen::Quaterniond q = from_cardan_xzy(abc);
    // Independent: the product of the three elementary rotations.
    const Eigen::Quaterniond product = about(Eigen::Vector3d::UnitX(), abc[0]) *
                                       about(Eigen::Vector3d::UnitZ(), abc[1]) *
                                       about(Eigen::Vector3d::UnitY(), abc[2]);
    EXPECT_LT(q.angularDistance(product), 1e-12);
    EXPECT_LT((cardan_xzy(q) - abc).norm(), 1e-9) << abc.transpose();
    EXPECT_LT((cardan_xzy(Eigen::Quaterniond(-q.coeffs())) - abc).norm(), 1e-9);
  }
}

TEST(JointCoordinates, RateMatrixIsTheAngularVelocityOfTheRotation) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(-2.5, 2.5), tilt(-1.2, 1.2), rate(-8.0, 8.0);
  const double h = 1e-6;
  for (int n = 0; n < 50; ++n) {
    const Eigen::Vector3d abc(angle(rng), tilt(rng), angle(rng));
    const Eigen::Vector3d rates(rate(rng), rate(rng), rate(rng));
    // ω_child from the rotation's central difference: R(t)ᵀ·Ṙ(t) = [ω]×.
    const Eigen::Matrix3d r = from_cardan_xzy(abc).toRotationMatrix();
    const Eigen::Matrix3d r_dot = (from_cardan_xzy(abc + h * rates).toRotationMatrix() -
                                   from_cardan_xzy(abc - h * rates).toRotationMatrix()) /
                                  (2 * h);
    const Eigen::Matrix3d w = r.transpose() * r_dot;
    const Eigen::Vector3d omega(w(2, 1), w(0, 2), w(1, 0));
    EXPECT_LT((cardan_rate_matrix(abc) * rates - omega).norm(), 1e-6 * (1 + omega.norm()));
  }
}

TEST(JointCoordinates, GeneralisedMomentsDoTheMomentsWork) {
  const BodyModel model = test::bundled_model();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-1.2, 1.2), u(-50.0, 50.0);
  for (int segment = 1; segment < model.size(); ++segment) {
    const JointCoordinates c = joint_coordinates(model, segment);
    const Eigen::Quaterniond q = from_cardan_xzy({angle(rng), angle(rng), angle(rng)});
    const Eigen::Vector3d omega(u(rng), u(rng), u(rng)), moment(u(rng), u(rng), u(rng));
    const JointCoordinateState s = joint_coordinate_state(c, q, omega, moment);
    EXPECT_NEAR(s.moment.dot(s.rate), moment.dot(omega), 1e-9 * std::abs(moment.dot(omega)) + 1e-9)
        << model.segments[segment].joint;
    // The values give the rotation back.
    EXPECT_LT(joint_rotation_from_coordinates(c, s.value).angularDistance(q), 1e-12);
  }
}

TEST(JointCoordinates, EveryCoordinateOfTheBundledModelHasItsOwnName) {
  const BodyModel model = test::bundled_model();
  std::set<std::string> names;
  for (int segment = 1; segment < model.size(); ++segment) {
    const JointCoordinates c = joint_coordinates(model, segment);
    EXPECT_NE(c.kind, "joint") << model.segments[segment].joint;
    for (const JointCoordinate& coordinate : c.coordinates)
      EXPECT_TRUE(names.insert(coordinate.name).second) << coordinate.name;
  }
  EXPECT_EQ(names.size(), 3u * (model.size() - 1));
}

TEST(JointCoordinates, ALimbSwungForwardIsFlexionOnEitherSide) {
  const BodyModel model = test::bundled_model();
  // The limb hangs along -y; swung forward by 30°, it points to (0, -cos 30°, sin 30°).
  for (const std::string side : {"_l", "_r"}) {
    const Eigen::Quaterniond forward = Eigen::Quaterniond::FromTwoVectors(
        -Eigen::Vector3d::UnitY(), Eigen::Vector3d(0, -std::cos(30 * kDeg), std::sin(30 * kDeg)));
    EXPECT_NEAR(value_of(model, "thigh" + side, "hip_flexion" + side, forward), 30 * kDeg, 1e-9);
    EXPECT_NEAR(value_of(model, "upper_arm" + side, "shoulder_flexion" + side, forward), 30 * kDeg,
                1e-9);
    EXPECT_NEAR(value_of(model, "forearm" + side, "elbow_flexion" + side, forward), 30 * kDeg,
                1e-9);
    // The shank swung backwards is knee flexion.
    const Eigen::Quaterniond backward = Eigen::Quaterniond::FromTwoVectors(
        -Eigen::Vector3d::UnitY(), Eigen::Vector3d(0, -std::cos(40 * kDeg), -std::sin(40 * kDeg)));
    EXPECT_NEAR(value_of(model, "shank" + side, "knee_flexion" + side, backward), 40 * kDeg, 1e-9);
  }
}

TEST(JointCoordinates, ALimbMovedAwayFromTheMidlineIsAbduction) {
  const BodyModel model = test::bundled_model();
  // Outwards is +x (left) for the left limbs and -x for the right ones.
  for (const auto& [side, outward] : {std::pair<std::string, double>{"_l", 1.0}, {"_r", -1.0}}) {
    const Eigen::Quaterniond out = Eigen::Quaterniond::FromTwoVectors(
        -Eigen::Vector3d::UnitY(),
        Eigen::Vector3d(outward * std::sin(20 * kDeg), -std::cos(20 * kDeg), 0));
    EXPECT_NEAR(value_of(model, "thigh" + side, "hip_adduction" + side, out), -20 * kDeg, 1e-9);
    EXPECT_NEAR(value_of(model, "upper_arm" + side, "shoulder_adduction" + side, out), -20 * kDeg,
                1e-9);
    // The front of the limb turned towards the midline is internal rotation.
    const Eigen::Quaterniond inward = about(Eigen::Vector3d::UnitY(), -outward * 25 * kDeg);
    EXPECT_GT((inward * Eigen::Vector3d::UnitZ()).x() * outward, -1.0);  // sanity of the setup
    EXPECT_LT((inward * Eigen::Vector3d::UnitZ()).x() * outward, 0.0);   // turned medially
    EXPECT_NEAR(value_of(model, "thigh" + side, "hip_rotation" + side, inward), 25 * kDeg, 1e-9);
    EXPECT_NEAR(value_of(model, "upper_arm" + side, "shoulder_rotation" + side, inward), 25 * kDeg,
                1e-9);
  }
}

TEST(JointCoordinates, TheIdentityFootIsPointedAndAForwardFootIsDorsiflexed) {
  const BodyModel model = test::bundled_model();
  EXPECT_NEAR(value_of(model, "foot_l", "ankle_dorsiflexion_l", Eigen::Quaterniond::Identity()),
              -50 * kDeg, 1e-9);
  // Foot swung forward by 50° from hanging: neutral.
  const Eigen::Quaterniond neutral = Eigen::Quaterniond::FromTwoVectors(
      -Eigen::Vector3d::UnitY(), Eigen::Vector3d(0, -std::cos(50 * kDeg), std::sin(50 * kDeg)));
  EXPECT_NEAR(value_of(model, "foot_r", "ankle_dorsiflexion_r", neutral), 0.0, 1e-9);
}

TEST(JointCoordinates, BendingForwardIsTrunkFlexionAtBothTrunkJoints) {
  const BodyModel model = test::bundled_model();
  // The thorax's long axis (+y) tipped forward by 20° relative to the abdomen.
  const Eigen::Quaterniond thorax_forward = Eigen::Quaterniond::FromTwoVectors(
      Eigen::Vector3d::UnitY(), Eigen::Vector3d(0, std::cos(20 * kDeg), std::sin(20 * kDeg)));
  EXPECT_NEAR(value_of(model, "thorax", "thoracic_extension", thorax_forward), -20 * kDeg, 1e-9);
  // The pelvis below: a pike brings its long axis (-y) forward, the same flexion.
  const Eigen::Quaterniond pelvis_forward = Eigen::Quaterniond::FromTwoVectors(
      -Eigen::Vector3d::UnitY(), Eigen::Vector3d(0, -std::cos(20 * kDeg), std::sin(20 * kDeg)));
  EXPECT_NEAR(value_of(model, "pelvis", "lumbar_extension", pelvis_forward), -20 * kDeg, 1e-9);
  // Bending left: the thorax's top goes left (+x); seen from the abdomen, so does the pelvis's
  // bottom (the abdomen above it leans left, so the pelvis below leans left of the abdomen's axis).
  const Eigen::Quaterniond thorax_left = Eigen::Quaterniond::FromTwoVectors(
      Eigen::Vector3d::UnitY(), Eigen::Vector3d(std::sin(15 * kDeg), std::cos(15 * kDeg), 0));
  EXPECT_NEAR(value_of(model, "thorax", "thoracic_bending", thorax_left), 15 * kDeg, 1e-9);
  const Eigen::Quaterniond pelvis_left = Eigen::Quaterniond::FromTwoVectors(
      -Eigen::Vector3d::UnitY(), Eigen::Vector3d(std::sin(15 * kDeg), -std::cos(15 * kDeg), 0));
  EXPECT_NEAR(value_of(model, "pelvis", "lumbar_bending", pelvis_left), 15 * kDeg, 1e-9);
  // Turning left: the thorax's front goes left; the pelvis's front goes right.
  const Eigen::Quaterniond thorax_turn = about(Eigen::Vector3d::UnitY(), 10 * kDeg);
  EXPECT_GT((thorax_turn * Eigen::Vector3d::UnitZ()).x(), 0.0);
  EXPECT_NEAR(value_of(model, "thorax", "thoracic_rotation", thorax_turn), 10 * kDeg, 1e-9);
  EXPECT_NEAR(value_of(model, "pelvis", "lumbar_rotation", thorax_turn.inverse()), 10 * kDeg, 1e-9);
}

}  // namespace
}  // namespace saltus
