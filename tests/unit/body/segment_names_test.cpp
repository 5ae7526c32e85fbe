// Human names of segments and joints: every segment and joint of the bundled model gets a name
// without underscores or side suffixes, left and right differ only in the side word, and the
// names coaches use are right.

#include <gtest/gtest.h>

#include <set>

#include "saltus/body/segment_names.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(SegmentNames, SaysWhatACoachSays) {
  EXPECT_EQ(segment_label("thigh_r"), "right thigh");
  EXPECT_EQ(segment_label("forearm_l"), "left forearm");
  EXPECT_EQ(segment_label("shank_l"), "left lower leg");
  EXPECT_EQ(segment_label("upper_arm_r"), "right upper arm");
  EXPECT_EQ(joint_label("knee_r"), "right knee");
  EXPECT_EQ(joint_label("hip_l"), "left hip");
  EXPECT_EQ(joint_label("lumbar"), "lower back");
  EXPECT_EQ(capitalised(joint_label("shoulder_l")), "Left shoulder");
  // Names of other models keep their words.
  EXPECT_EQ(segment_label("tail_fin"), "tail fin");
  EXPECT_EQ(joint_label("neck"), "neck");
}

TEST(SegmentNames, EveryBundledSegmentAndJointReadsAsWords) {
  const BodyModel model = test::bundled_model();
  std::set<std::string> segments, joints;
  for (const Segment& s : model.segments) {
    const std::string segment = segment_label(s.name), joint = joint_label(s.joint);
    for (const std::string& name : {segment, joint}) {
      EXPECT_EQ(name.find('_'), std::string::npos) << name;
      EXPECT_FALSE(name.empty());
    }
    segments.insert(segment);
    joints.insert(joint);
    // Left and right differ only in the side word.
    if (s.name.size() > 2 && s.name.substr(s.name.size() - 2) == "_l") {
      const std::string right = s.name.substr(0, s.name.size() - 2) + "_r";
      EXPECT_EQ(segment.substr(5), segment_label(right).substr(6)) << s.name;
    }
  }
  EXPECT_EQ(segments.size(), model.segments.size());  // no two segments named alike
  EXPECT_EQ(joints.size(), model.segments.size());
}

TEST(SegmentNames, ScalingLabelsNameTheSegmentsAndTheFactor) {
  EXPECT_EQ(mass_scaling_label({"thigh_l", "thigh_r"}, 1.5), "left and right thighs × 1.5");
  EXPECT_EQ(mass_scaling_label({"thigh_r"}, 1.5), "right thigh × 1.5");
  EXPECT_EQ(mass_scaling_label({"foot_l", "foot_r"}, 2), "left and right feet × 2");
  EXPECT_EQ(mass_scaling_label({"thigh_r", "upper_arm_l", "pelvis"}, 0.8),
            "right thigh, left upper arm and pelvis × 0.8");
  EXPECT_EQ(mass_scaling_label({}, 1.1), "every segment × 1.1");
}

}  // namespace
}  // namespace saltus
