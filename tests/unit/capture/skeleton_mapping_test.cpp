// Skeleton mapping by joint names: each supported convention, composition of the spine, joints
// that play no part, and what happens when no convention fits.

#include "saltus/capture/skeleton_mapping.h"

#include <gtest/gtest.h>

#include "saltus/capture/retarget.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

struct Bone {
  std::string name;
  std::string parent;
  Eigen::Vector3d offset;
};

/// A skeleton (y up, cm, facing +z) from bones listed parent first, in depth-first order.
MocapClip skeleton(const std::vector<Bone>& bones) {
  MocapClip clip;
  for (const Bone& b : bones) {
    MocapJoint joint;
    joint.name = b.name;
    joint.parent = b.parent.empty() ? -1 : clip.joint_index(b.parent);
    joint.offset = b.offset;
    clip.joints.push_back(joint);
  }
  for (int j = 0; j < clip.joint_count(); ++j)
    if (clip.children(j).empty()) clip.joints[j].end_sites.push_back(Eigen::Vector3d(0, -5, 0));
  clip.frame_time = 0.01;
  clip.frames = {{}};
  return clip;
}

/// A HumanIK-named skeleton with `prefix` before every name (Mixamo, MotionBuilder).
std::vector<Bone> humanik_bones(const std::string& p) {
  std::vector<Bone> bones{{p + "Hips", "", {0, 95, 0}},
                          {p + "Spine", p + "Hips", {0, 10, 0}},
                          {p + "Spine1", p + "Spine", {0, 12, 0}},
                          {p + "Spine2", p + "Spine1", {0, 12, 0}},
                          {p + "Neck", p + "Spine2", {0, 15, 0}},
                          {p + "Head", p + "Neck", {0, 10, 0}}};
  for (const std::string side : {"Left", "Right"}) {
    const double s = side == "Left" ? 1 : -1;
    bones.push_back({p + side + "Shoulder", p + "Spine2", {s * 4, 12, 0}});
    bones.push_back({p + side + "Arm", p + side + "Shoulder", {s * 14, 0, 0}});
    bones.push_back({p + side + "ForeArm", p + side + "Arm", {s * 28, 0, 0}});
    bones.push_back({p + side + "Hand", p + side + "ForeArm", {s * 26, 0, 0}});
    bones.push_back({p + side + "HandIndex1", p + side + "Hand", {s * 9, 0, 0}});
  }
  for (const std::string side : {"Left", "Right"}) {
    const double s = side == "Left" ? 1 : -1;
    bones.push_back({p + side + "UpLeg", p + "Hips", {s * 9, -5, 0}});
    bones.push_back({p + side + "Leg", p + side + "UpLeg", {0, -42, 0}});
    bones.push_back({p + side + "Foot", p + side + "Leg", {0, -41, 0}});
    bones.push_back({p + side + "ToeBase", p + side + "Foot", {0, -6, 13}});
  }
  return bones;
}

TEST(SkeletonMapping, NormalizedNamesDropRigPrefixesCaseAndPunctuation) {
  EXPECT_EQ(normalized_joint_name("mixamorig:LeftForeArm"), "leftforearm");
  EXPECT_EQ(normalized_joint_name("Character1_LeftUpLeg"), "leftupleg");
  EXPECT_EQ(normalized_joint_name("DEF-upper_arm.L"), "upperarml");
  EXPECT_EQ(normalized_joint_name("ORG-thigh.R"), "thighr");
  EXPECT_EQ(normalized_joint_name("left_elbow"), "leftelbow");
  EXPECT_EQ(normalized_joint_name("Bip01 L Thigh"), "lthigh");
}

TEST(SkeletonMapping, MixamoAndMotionBuilderNames) {
  const SkeletonMapping mixamo = guess_skeleton_mapping(skeleton(humanik_bones("mixamorig:")));
  EXPECT_EQ(mixamo.convention, "Mixamo");
  EXPECT_EQ(mixamo.joints.at("upper_arm_l"), std::vector<std::string>{"mixamorig:LeftArm"});
  EXPECT_EQ(mixamo.joints.at("hand_r"), std::vector<std::string>{"mixamorig:RightHand"});
  EXPECT_EQ(mixamo.joints.at("shank_r"), std::vector<std::string>{"mixamorig:RightLeg"});
  const SkeletonMapping mb = guess_skeleton_mapping(skeleton(humanik_bones("Character1_")));
  EXPECT_EQ(mb.convention, "MotionBuilder");
  EXPECT_EQ(mb.joints.at("pelvis"), std::vector<std::string>{"Character1_Hips"});
}

TEST(SkeletonMapping, SpineJointsComposeIntoTheTrunkAndHelpersPlayNoPart) {
  std::vector<Bone> bones = humanik_bones("mixamorig:");
  bones.push_back({"L_Humerus_RIGMESH", "mixamorig:LeftArm", {0, 0, 0}});
  const MocapClip clip = skeleton(bones);
  const BodyModel model = test::bundled_model();
  const Retargeting plan = plan_retargeting(clip, model, guess_skeleton_mapping(clip));
  EXPECT_EQ(clip.joints[plan.thorax_joint].name, "mixamorig:Spine2");  // where the arms meet
  const SegmentDrive& abdomen = plan.drives[model.segment_index("abdomen")];
  EXPECT_EQ(abdomen.kind, SegmentDrive::Kind::kAverage);
  ASSERT_EQ(abdomen.joints.size(), 2u);
  EXPECT_EQ(clip.joints[abdomen.joints[0]].name, "mixamorig:Spine");
  EXPECT_EQ(clip.joints[abdomen.joints[1]].name, "mixamorig:Spine1");
  EXPECT_NEAR(abdomen.weights[0] + abdomen.weights[1], 1.0, 1e-15);
  // The arms hang in a T-pose: their rest correction is a quarter turn.
  const SegmentDrive& arm = plan.drives[model.segment_index("upper_arm_l")];
  EXPECT_TRUE(arm.along_bone);
  EXPECT_EQ(arm.rest_direction_to, "mixamorig:LeftForeArm");
  EXPECT_NEAR(arm.rest_correction.angularDistance(Eigen::Quaterniond::Identity()), M_PI / 2, 1e-12);
  std::map<std::string, std::string> unused(plan.unused_joints.begin(), plan.unused_joints.end());
  EXPECT_EQ(unused.at("mixamorig:LeftShoulder"), "clavicle (part of the thorax)");
  EXPECT_EQ(unused.at("mixamorig:Head"), "neck/head (part of the thorax)");
  EXPECT_EQ(unused.at("mixamorig:LeftHandIndex1"), "finger");
  EXPECT_EQ(unused.at("mixamorig:LeftToeBase"), "toe (part of the foot)");
  EXPECT_EQ(unused.at("L_Humerus_RIGMESH"), "helper (_RIGMESH)");
  EXPECT_EQ(unused.count("mixamorig:LeftHand"), 0u);  // the forearm points at it
  EXPECT_EQ(plan.axes.unit, "cm");
  EXPECT_EQ(plan.axes.up_name, "+y");
}

TEST(SkeletonMapping, DeepMimicCmuRigifyAndSaltusNames) {
  std::vector<Bone> dm{
      {"root", "", {0, 90, 0}}, {"chest", "root", {0, 24, 0}}, {"neck", "chest", {0, 22, 0}}};
  for (const std::string side : {"left", "right"}) {
    const double s = side == "left" ? 1 : -1;
    dm.push_back({side + "_shoulder", "chest", {s * 18, 24, 0}});
    dm.push_back({side + "_elbow", side + "_shoulder", {0, -27, 0}});
    dm.push_back({side + "_hip", "root", {s * 8, 0, 0}});
    dm.push_back({side + "_knee", side + "_hip", {0, -42, 0}});
    dm.push_back({side + "_ankle", side + "_knee", {0, -41, 0}});
  }
  const SkeletonMapping deepmimic = guess_skeleton_mapping(skeleton(dm));
  EXPECT_EQ(deepmimic.convention, "DeepMimic");
  EXPECT_EQ(deepmimic.joints.at("upper_arm_l"), std::vector<std::string>{"left_shoulder"});
  EXPECT_EQ(deepmimic.joints.at("thorax"), std::vector<std::string>{"chest"});

  std::vector<Bone> cmu{{"hip", "", {0, 95, 0}},
                        {"lowerback", "hip", {0, 10, 0}},
                        {"upperback", "lowerback", {0, 10, 0}},
                        {"thorax", "upperback", {0, 10, 0}}};
  for (const std::string s : {"l", "r"}) {
    const double x = s == "l" ? 1 : -1;
    cmu.push_back({s + "clavicle", "thorax", {x * 4, 10, 0}});
    cmu.push_back({s + "humerus", s + "clavicle", {x * 14, 0, 0}});
    cmu.push_back({s + "radius", s + "humerus", {x * 28, 0, 0}});
    cmu.push_back({s + "wrist", s + "radius", {x * 26, 0, 0}});
    cmu.push_back({s + "hipjoint", "hip", {x * 9, -5, 0}});
    cmu.push_back({s + "femur", s + "hipjoint", {0, -42, 0}});
    cmu.push_back({s + "tibia", s + "femur", {0, -41, 0}});
    cmu.push_back({s + "foot", s + "tibia", {0, -6, 13}});
  }
  const SkeletonMapping asf = guess_skeleton_mapping(skeleton(cmu));
  EXPECT_EQ(asf.convention, "CMU");
  EXPECT_EQ(asf.joints.at("thigh_r"), std::vector<std::string>{"rfemur"});
  EXPECT_EQ(asf.joints.at("hand_l"), std::vector<std::string>{"lwrist"});

  std::vector<Bone> rigify{{"DEF-spine", "", {0, 95, 0}},
                           {"DEF-spine.001", "DEF-spine", {0, 12, 0}},
                           {"DEF-spine.002", "DEF-spine.001", {0, 12, 0}},
                           {"DEF-spine.003", "DEF-spine.002", {0, 12, 0}}};
  for (const std::string s : {"L", "R"}) {
    const double x = s == "L" ? 1 : -1;
    rigify.push_back({"DEF-shoulder." + s, "DEF-spine.003", {x * 3, 10, 0}});
    rigify.push_back({"DEF-upper_arm." + s, "DEF-shoulder." + s, {x * 15, 0, 0}});
    rigify.push_back({"DEF-upper_arm." + s + ".001", "DEF-upper_arm." + s, {x * 14, 0, 0}});
    rigify.push_back({"DEF-forearm." + s, "DEF-upper_arm." + s + ".001", {x * 14, 0, 0}});
    rigify.push_back({"DEF-hand." + s, "DEF-forearm." + s, {x * 27, 0, 0}});
    rigify.push_back({"DEF-thigh." + s, "DEF-spine", {x * 9, 0, 0}});
    rigify.push_back({"DEF-shin." + s, "DEF-thigh." + s, {0, -42, 0}});
    rigify.push_back({"DEF-foot." + s, "DEF-shin." + s, {0, -41, 0}});
  }
  const MocapClip rigify_clip = skeleton(rigify);
  const SkeletonMapping rig = guess_skeleton_mapping(rigify_clip);
  EXPECT_EQ(rig.convention, "Rigify");
  EXPECT_EQ(rig.joints.at("pelvis"), std::vector<std::string>{"DEF-spine"});
  EXPECT_EQ(rig.joints.at("shank_l"), std::vector<std::string>{"DEF-shin.L"});
  // The upper arm's twist copy lies on its bone: the bone still points at the forearm.
  const BodyModel model = test::bundled_model();
  const Retargeting plan = plan_retargeting(rigify_clip, model, rig);
  EXPECT_EQ(plan.drives[model.segment_index("upper_arm_l")].rest_direction_to, "DEF-forearm.L");
  EXPECT_EQ(plan.drives[model.segment_index("abdomen")].joints.size(), 2u);

  std::vector<Bone> saltus{{"abdomen", "", {0, 100, 0}},
                           {"pelvis", "abdomen", {0, 0, 0}},
                           {"thigh_l", "pelvis", {8.5, -14, 0}},
                           {"shank_l", "thigh_l", {0, -41, 0}},
                           {"foot_l", "shank_l", {0, -43, 0}},
                           {"thigh_r", "pelvis", {-8.5, -14, 0}},
                           {"shank_r", "thigh_r", {0, -41, 0}},
                           {"foot_r", "shank_r", {0, -43, 0}},
                           {"thorax", "abdomen", {0, 21, 0}},
                           {"upper_arm_l", "thorax", {18, 15, 0}},
                           {"forearm_l", "upper_arm_l", {0, -27, 0}},
                           {"upper_arm_r", "thorax", {-18, 15, 0}},
                           {"forearm_r", "upper_arm_r", {0, -27, 0}}};
  const SkeletonMapping own = guess_skeleton_mapping(skeleton(saltus));
  EXPECT_EQ(own.convention, "Saltus");
  EXPECT_EQ(own.joints.at("abdomen"), std::vector<std::string>{"abdomen"});
}

TEST(SkeletonMapping, UnknownNamesAskForAMappingFile) {
  const MocapClip clip = skeleton({{"a", "", {0, 1, 0}}, {"b", "a", {0, 1, 0}}});
  try {
    guess_skeleton_mapping(clip);
    FAIL() << "an unknown skeleton was mapped";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("HumanIK names lack pelvis, thigh_l"), std::string::npos) << what;
    EXPECT_NE(what.find("--mapping"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace saltus
