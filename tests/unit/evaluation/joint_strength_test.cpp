// Joint moments against published maxima (evaluation/joint_strength.h): the table finds a joint
// by its name without the side, the shares are the hand-computed peak / mass / published maximum,
// joints without a source have no bound rather than a guessed one, and the words name the largest.

#include "saltus/evaluation/joint_strength.h"

#include <gtest/gtest.h>

#include <cstring>

#include "saltus/evaluation/evaluate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(JointStrength, TheTableFindsAJointOnEitherSideAndOnlyThoseItCites) {
  ASSERT_NE(published_joint_moment("knee_l"), nullptr);
  EXPECT_EQ(published_joint_moment("knee_l"), published_joint_moment("knee_r"));
  EXPECT_DOUBLE_EQ(published_joint_moment("knee_r")->max_moment_per_kg, 2.92);
  EXPECT_STREQ(published_joint_moment("knee_r")->direction, "extension");
  EXPECT_DOUBLE_EQ(published_joint_moment("elbow_l")->max_moment_per_kg, 0.78);
  EXPECT_STREQ(published_joint_moment("elbow_l")->direction, "flexion");
  for (const char* joint : {"hip_l", "ankle_r", "shoulder_l", "lumbar", "thoracic", "root", "kn"})
    EXPECT_EQ(published_joint_moment(joint), nullptr) << joint;
  // Every entry names its source.
  for (const PublishedJointMoment& entry : published_joint_moments()) {
    EXPECT_GT(entry.max_moment_per_kg, 0.0) << entry.joint;
    EXPECT_GT(std::strlen(entry.source), 20u) << entry.joint;
  }
}

TEST(JointStrength, SharesAreThePeakPerKgOverThePublishedMaximum) {
  // 70 kg: 102.2 N·m at a knee is 1.46 N·m/kg, half of 2.92; 27.3 N·m at an elbow is
  // 0.39 N·m/kg, half of 0.78; 14 N·m at a hip is 0.2 N·m/kg with no bound.
  const std::vector<JointMomentShare> shares =
      joint_moment_shares({{"knee_l", 102.2}, {"elbow_r", 27.3}, {"hip_l", 14.0}}, 70.0);
  ASSERT_EQ(shares.size(), 3u);
  EXPECT_EQ(shares[0].joint, "knee_l");
  EXPECT_NEAR(shares[0].max_moment_per_kg, 1.46, 1e-12);
  EXPECT_DOUBLE_EQ(*shares[0].published_max_per_kg, 2.92);
  EXPECT_NEAR(*shares[0].share, 0.5, 1e-12);
  EXPECT_NEAR(shares[1].max_moment_per_kg, 0.39, 1e-12);
  EXPECT_NEAR(*shares[1].share, 0.5, 1e-12);
  EXPECT_NEAR(shares[2].max_moment_per_kg, 0.2, 1e-12);
  EXPECT_FALSE(shares[2].published_max_per_kg);
  EXPECT_FALSE(shares[2].share);
  EXPECT_TRUE(joint_moment_shares({{"knee_l", 1.0}}, 0.0).empty());
}

TEST(JointStrength, TheWordsNameTheLargestShareAndTheJointsWithoutABound) {
  // 80 kg: knee 23.36 N·m = 0.292 N·m/kg = 10 %; elbow 16 N·m = 0.2 N·m/kg = 25.6 %.
  const std::vector<JointMomentShare> shares = joint_moment_shares(
      {{"knee_l", 23.36}, {"elbow_r", 16.0}, {"hip_l", 40.0}, {"lumbar", 30.0}}, 80.0);
  const std::optional<JointMomentShare> largest = largest_joint_moment_share(shares);
  ASSERT_TRUE(largest);
  EXPECT_EQ(largest->joint, "elbow_r");
  EXPECT_NEAR(*largest->share, 0.2 / 0.78, 1e-12);
  EXPECT_EQ(joint_moment_share_words(shares),
            "largest 26 % of the published maximum (right elbow, 0.2 of 0.78 N·m/kg); 2 joints "
            "have no published maximum");
  EXPECT_EQ(joint_moment_share_words(joint_moment_shares({{"knee_r", 7.008}}, 80.0)),
            "largest 3.0 % of the published maximum (right knee, 0.0876 of 2.92 N·m/kg)");
  EXPECT_FALSE(largest_joint_moment_share(joint_moment_shares({{"hip_l", 40.0}}, 80.0)));
  EXPECT_EQ(joint_moment_share_words(joint_moment_shares({{"hip_l", 40.0}}, 80.0)),
            "no joint has a published maximum");
}

TEST(JointStrength, AModelsDenseCheckGivesEveryJointButTheRootInModelOrder) {
  const BodyModel model = test::bundled_model();
  const MotionEvaluation e = evaluate_motion(test::tuck_motion(model), model);
  const std::vector<JointMomentShare> shares = joint_moment_shares(model, e.check);
  ASSERT_EQ(static_cast<int>(shares.size()), model.size() - 1);
  for (int k = 1; k < model.size(); ++k) {
    const JointMomentShare& s = shares[k - 1];
    EXPECT_EQ(s.joint, model.segments[k].joint);
    EXPECT_DOUBLE_EQ(s.max_moment_per_kg, e.check.joint_peaks[k].moment_Nm / model.total_mass());
    EXPECT_EQ(s.share.has_value(), published_joint_moment(s.joint) != nullptr);
  }
}

}  // namespace
}  // namespace saltus
