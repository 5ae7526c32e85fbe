// Keyframe editing: Euler angles against the library's own quat_from_euler_deg, the time rules
// (first 0, last T, strictly increasing), and edits that the library then evaluates.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "core/document.h"
#include "core/motion_edit.h"
#include "gui_core/test_motion.h"
#include "saltus/base/input_error.h"
#include "saltus/formats/motion_file.h"
#include "saltus/math/quaternion.h"

namespace saltus::gui {
namespace {

TEST(EulerAngles, InvertTheLibrarysXyzConvention) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> any(-179.0, 179.0), pitch(-89.0, 89.0);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d angles(any(rng), pitch(rng), any(rng));
    const Eigen::Quaterniond q = quat_from_euler_deg(angles, "XYZ");
    const Eigen::Vector3d back = euler_xyz_deg(q);
    EXPECT_NEAR((back - angles).norm(), 0.0, 1e-8) << angles.transpose();
  }
  // Gimbal lock still gives angles that rebuild the rotation.
  const Eigen::Quaterniond locked = quat_from_euler_deg(Eigen::Vector3d(30, 90, 20), "XYZ");
  const Eigen::Quaterniond rebuilt = quat_from_euler_deg(euler_xyz_deg(locked), "XYZ");
  EXPECT_NEAR(std::abs(rebuilt.dot(locked)), 1.0, 1e-9);
}

class MotionEditTest : public ::testing::Test {
 protected:
  void SetUp() override { file_ = load_motion_file(test::gui_test_motion_path()); }
  const Motion& motion() const { return file_.motion; }
  const BodyModel& model() const { return file_.model; }
  MotionFile file_;
};

TEST_F(MotionEditTest, TimesStayStrictlyIncreasingFromZeroToTheEnd) {
  const int n = static_cast<int>(motion().keyframes.size());
  ASSERT_GE(n, 3);
  const double t1 = motion().keyframes[1].time, t2 = motion().keyframes[2].time;
  EXPECT_FALSE(keyframe_time_problem(motion(), 0, 0.0));
  EXPECT_TRUE(keyframe_time_problem(motion(), 0, 0.1));
  EXPECT_FALSE(keyframe_time_problem(motion(), 1, 0.5 * (t1 + t2)));
  EXPECT_TRUE(keyframe_time_problem(motion(), 1, t2));
  EXPECT_TRUE(keyframe_time_problem(motion(), 1, 0.0));
  EXPECT_TRUE(keyframe_time_problem(motion(), n, 1.0));
  EXPECT_FALSE(keyframe_time_problem(motion(), n - 1, motion().flight_time() + 0.1));
  EXPECT_TRUE(keyframe_time_problem(motion(), n - 1, motion().keyframes[n - 2].time));
  EXPECT_FALSE(new_keyframe_time_problem(motion(), 0.5 * t1));
  EXPECT_TRUE(new_keyframe_time_problem(motion(), t1));
  EXPECT_TRUE(new_keyframe_time_problem(motion(), 0.0));
  EXPECT_TRUE(new_keyframe_time_problem(motion(), motion().flight_time()));
  EXPECT_THROW(with_keyframe_time(motion(), model(), 1, t2), std::invalid_argument);
  const Motion moved = with_keyframe_time(motion(), model(), 1, 0.5 * (t1 + t2));
  EXPECT_DOUBLE_EQ(moved.keyframes[1].time, 0.5 * (t1 + t2));
}

TEST_F(MotionEditTest, JointAnglesChangeTheKeyframeAndTheRootForce) {
  const int knee = model().joint_index("knee_l");
  ASSERT_GE(knee, 0);
  const Eigen::Vector3d before = euler_xyz_deg(motion().keyframes[2].rotations[knee]);
  const Eigen::Vector3d bent = before + Eigen::Vector3d(-40.0, 0.0, 0.0);
  const Motion edited = with_joint_angles(motion(), model(), 2, knee, bent);
  EXPECT_NEAR((euler_xyz_deg(edited.keyframes[2].rotations[knee]) - bent).norm(), 0.0, 1e-8);
  EXPECT_FALSE(edited.spline.has_value());
  // Only that rotation changed.
  for (int s = 0; s < model().size(); ++s) {
    if (s == knee) continue;
    EXPECT_TRUE(edited.keyframes[2].rotations[s].isApprox(motion().keyframes[2].rotations[s]));
  }
  // The library sees another motion: its root force changes.
  EvaluateOptions o;
  o.samples = 41;
  const double f0 = evaluate_motion(motion(), model(), o).metrics.avg_root_force;
  const double f1 = evaluate_motion(edited, model(), o).metrics.avg_root_force;
  EXPECT_GT(std::abs(f1 - f0), 0.01 * f0);
  EXPECT_THROW(with_joint_angles(motion(), model(), 2, knee, Eigen::Vector3d(NAN, 0, 0)),
               std::invalid_argument);
}

TEST_F(MotionEditTest, AddAndDeleteKeyframes) {
  Document document;
  document.load(test::gui_test_motion_path(), "", 41);
  const double t = 0.5 * motion().keyframes[1].time;
  const Motion added =
      with_keyframe_added(motion(), model(), t, document.sample_at(Stage::kBefore, t));
  ASSERT_EQ(added.keyframes.size(), motion().keyframes.size() + 1);
  EXPECT_DOUBLE_EQ(added.keyframes[1].time, t);
  for (std::size_t i = 1; i < added.keyframes.size(); ++i)
    EXPECT_LT(added.keyframes[i - 1].time, added.keyframes[i].time);
  // The new keyframe is the pose the motion had there: re-interpolating barely moves it.
  const SampleRecord there = document.sample_at(Stage::kBefore, t);
  document.set_motion(added);
  EXPECT_TRUE(document.edited());
  const SampleRecord after = document.sample_at(Stage::kBefore, t);
  for (std::size_t s = 0; s < there.segment_rotation.size(); ++s)
    EXPECT_GT(std::abs(after.segment_rotation[s].dot(there.segment_rotation[s])), 0.999) << s;

  const Motion removed = with_keyframe_deleted(added, model(), 1);
  EXPECT_EQ(removed.keyframes.size(), motion().keyframes.size());
  EXPECT_THROW(with_keyframe_deleted(motion(), model(), 0), std::invalid_argument);
  EXPECT_THROW(
      with_keyframe_deleted(motion(), model(), static_cast<int>(motion().keyframes.size()) - 1),
      std::invalid_argument);
  EXPECT_THROW(with_keyframe_added(motion(), model(), motion().keyframes[1].time, there),
               std::invalid_argument);
}

TEST_F(MotionEditTest, TheLibrarysParserJudgesTheResult) {
  EXPECT_NO_THROW(validate_motion(motion(), model()));
  Motion broken = motion();
  broken.keyframes[1].time = broken.keyframes[2].time;  // not strictly increasing
  try {
    validate_motion(broken, model());
    ADD_FAILURE() << "the library accepted equal keyframe times";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("edited motion"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace saltus::gui
