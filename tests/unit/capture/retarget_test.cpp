// Retargeting by world-frame segment orientations, checked on hand-written files: the same six
// poses written in Saltus's own skeleton (y up, cm, facing +z, Z-X-Y channels), in a z-up,
// metre, X-Y-Z, T-pose file with HumanIK names and a split spine (facing −y, as the shared
// deepmimic-backflip-zup.bvh), and in a DeepMimic-style file (y up, cm, facing +x, legs listed
// first). Every channel value below was worked out by hand from the poses' description.

#include "saltus/capture/retarget.h"

#include <gtest/gtest.h>

#include <map>

#include "saltus/capture/model_clip.h"
#include "saltus/formats/bvh_file.h"
#include "saltus/math/quaternion.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// Per frame: joint name -> its channel values in file order (joints not named are zero).
using Frames = std::vector<std::map<std::string, std::vector<double>>>;

/// A clip from a hierarchy and hand-written channel values.
MocapClip clip_with_frames(MocapClip clip, const Frames& frames) {
  clip.frame_time = 0.1;
  clip.frames.clear();
  for (const auto& frame : frames) {
    std::vector<double> row(clip.column_count(), 0.0);
    for (const auto& [name, values] : frame) {
      const int j = clip.joint_index(name);
      EXPECT_GE(j, 0) << name;
      EXPECT_EQ(values.size(), clip.joints[j].channels.size()) << name;
      for (std::size_t c = 0; c < values.size(); ++c)
        row[clip.joints[j].first_column + c] = values[c];
    }
    clip.frames.push_back(row);
  }
  // Through the text format, as a file would come.
  return parse_bvh(bvh_text(clip), "hand-written.bvh");
}

// The poses (Saltus axes): 0 upright; 1 leaning back 60° (about x); 2 left elbow bent 90°;
// 3 right hip flexed 90° with the knee bent 90°; 4 turned 30° to the left (about y); 5 leaning
// back 60° after turning 30°. The hip centre stays at (0, 0.9, 0) m. Saltus's skeleton comes
// from the model (its own convention); the channels are written by hand: the root (abdomen)
// sits 14.23 cm above the hip centre along its own y.
Frames saltus_frames() {
  const double c60 = 14.23 * 0.5, s60 = 14.23 * std::sqrt(3.0) / 2;
  const std::vector<double> upright{0, 104.23, 0, 0, 0, 0};
  const std::vector<double> leaning{0, 90 + c60, -s60, 0, -60, 0};
  return {{{"abdomen", upright}},
          {{"abdomen", leaning}},
          {{"abdomen", upright}, {"forearm_l", {0, -90, 0}}},
          {{"abdomen", upright}, {"thigh_r", {0, -90, 0}}, {"shank_r", {0, 90, 0}}},
          {{"abdomen", {0, 104.23, 0, 0, 0, 30}}},
          {{"abdomen", {0, 90 + c60, -s60, 0, -60, 30}}}};
}

// z up, metres, facing −y (so Saltus x = x, Saltus y = z, Saltus z = −y), X-Y-Z channels,
// T-pose arms. A turn about Saltus x is one about x, about Saltus y one about z. The arms are
// brought down from the T by a quarter turn about y (+90° left, −90° right); the left elbow's
// bend about Saltus x becomes, along the T-pose arm, a bend about z.
const char* kZupHierarchy = R"(HIERARCHY
ROOT Hips
{
  OFFSET 0 0 0
  CHANNELS 6 Xposition Yposition Zposition Xrotation Yrotation Zrotation
  JOINT LeftUpLeg
  {
    OFFSET 0.085 0 0
    CHANNELS 3 Xrotation Yrotation Zrotation
    JOINT LeftLeg
    {
      OFFSET 0 0 -0.4123
      CHANNELS 3 Xrotation Yrotation Zrotation
      JOINT LeftFoot
      {
        OFFSET 0 0 -0.4299
        CHANNELS 3 Xrotation Yrotation Zrotation
        JOINT LeftToeBase
        {
          OFFSET 0 -0.12 -0.05
          CHANNELS 3 Xrotation Yrotation Zrotation
          End Site
          {
            OFFSET 0 -0.03 0
          }
        }
      }
    }
  }
  JOINT RightUpLeg
  {
    OFFSET -0.085 0 0
    CHANNELS 3 Xrotation Yrotation Zrotation
    JOINT RightLeg
    {
      OFFSET 0 0 -0.4123
      CHANNELS 3 Xrotation Yrotation Zrotation
      JOINT RightFoot
      {
        OFFSET 0 0 -0.4299
        CHANNELS 3 Xrotation Yrotation Zrotation
        End Site
        {
          OFFSET 0 -0.13 -0.05
        }
      }
    }
  }
  JOINT Spine
  {
    OFFSET 0 0 0.1423
    CHANNELS 3 Xrotation Yrotation Zrotation
    JOINT Spine1
    {
      OFFSET 0 0 0.1052
      CHANNELS 3 Xrotation Yrotation Zrotation
      JOINT Spine2
      {
        OFFSET 0 0 0.1052
        CHANNELS 3 Xrotation Yrotation Zrotation
        JOINT LeftArm
        {
          OFFSET 0.18 0 0.1507
          CHANNELS 3 Xrotation Yrotation Zrotation
          JOINT LeftForeArm
          {
            OFFSET 0.2751 0 0
            CHANNELS 3 Xrotation Yrotation Zrotation
            JOINT LeftHand
            {
              OFFSET 0.27 0 0
              CHANNELS 3 Xrotation Yrotation Zrotation
              End Site
              {
                OFFSET 0.08 0 0
              }
            }
          }
        }
        JOINT RightArm
        {
          OFFSET -0.18 0 0.1507
          CHANNELS 3 Xrotation Yrotation Zrotation
          JOINT RightForeArm
          {
            OFFSET -0.2751 0 0
            CHANNELS 3 Xrotation Yrotation Zrotation
            End Site
            {
              OFFSET -0.3467 0 0
            }
          }
        }
        JOINT Neck
        {
          OFFSET 0 0 0.2
          CHANNELS 3 Xrotation Yrotation Zrotation
          End Site
          {
            OFFSET 0 0 0.24
          }
        }
      }
    }
  }
}
)";

Frames zup_frames() {
  auto hips = [&](double x, double z) { return std::vector<double>{0, 0, 0.9, x, 0, z}; };
  auto with_arms = [](std::map<std::string, std::vector<double>> frame) {
    frame["LeftArm"] = {0, 90, 0};
    frame["RightArm"] = {0, -90, 0};
    return frame;
  };
  return {with_arms({{"Hips", hips(0, 0)}}),
          with_arms({{"Hips", hips(-60, 0)}}),
          with_arms({{"Hips", hips(0, 0)}, {"LeftForeArm", {0, 0, -90}}}),
          with_arms({{"Hips", hips(0, 0)}, {"RightUpLeg", {-90, 0, 0}}, {"RightLeg", {90, 0, 0}}}),
          with_arms({{"Hips", hips(0, 30)}}),
          with_arms({{"Hips", hips(-60, 30)}})};
}

// y up, cm, facing +x with the body's left towards −z (Saltus x = −z, Saltus z = x), Z-X-Y
// channels, arms down at rest, legs listed first. A turn about Saltus x by θ is one about z by
// −θ; about y stays about y.
const char* kDeepMimicHierarchy = R"(HIERARCHY
ROOT root
{
	OFFSET 0 0 0
	CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation
	JOINT right_hip
	{
		OFFSET 0 0 8.5
		CHANNELS 3 Zrotation Xrotation Yrotation
		JOINT right_knee
		{
			OFFSET 0 -41.23 0
			CHANNELS 3 Zrotation Xrotation Yrotation
			JOINT right_ankle
			{
				OFFSET 0 -42.99 0
				CHANNELS 3 Zrotation Xrotation Yrotation
				End Site
				{
					OFFSET 13 -5 0
				}
			}
		}
	}
	JOINT left_hip
	{
		OFFSET 0 0 -8.5
		CHANNELS 3 Zrotation Xrotation Yrotation
		JOINT left_knee
		{
			OFFSET 0 -41.23 0
			CHANNELS 3 Zrotation Xrotation Yrotation
			JOINT left_ankle
			{
				OFFSET 0 -42.99 0
				CHANNELS 3 Zrotation Xrotation Yrotation
				End Site
				{
					OFFSET 13 -5 0
				}
			}
		}
	}
	JOINT chest
	{
		OFFSET 0 35.27 0
		CHANNELS 3 Zrotation Xrotation Yrotation
		JOINT neck
		{
			OFFSET 0 20 0
			CHANNELS 3 Zrotation Xrotation Yrotation
			End Site
			{
				OFFSET 0 23.88 0
			}
		}
		JOINT right_shoulder
		{
			OFFSET 0 15.07 18
			CHANNELS 3 Zrotation Xrotation Yrotation
			JOINT right_elbow
			{
				OFFSET 0 -27.51 0
				CHANNELS 3 Zrotation Xrotation Yrotation
				End Site
				{
					OFFSET 0 -34.67 0
				}
			}
		}
		JOINT left_shoulder
		{
			OFFSET 0 15.07 -18
			CHANNELS 3 Zrotation Xrotation Yrotation
			JOINT left_elbow
			{
				OFFSET 0 -27.51 0
				CHANNELS 3 Zrotation Xrotation Yrotation
				End Site
				{
					OFFSET 0 -34.67 0
				}
			}
		}
	}
}
)";

Frames deepmimic_frames() {
  auto root = [](double z, double y) { return std::vector<double>{0, 90, 0, z, 0, y}; };
  return {{{"root", root(0, 0)}},
          {{"root", root(60, 0)}},
          {{"root", root(0, 0)}, {"left_elbow", {90, 0, 0}}},
          {{"root", root(0, 0)}, {"right_hip", {90, 0, 0}}, {"right_knee", {-90, 0, 0}}},
          {{"root", root(0, 30)}},
          {{"root", root(60, 30)}}};
}

Eigen::Quaterniond about(const Eigen::Vector3d& axis, double deg) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(deg * M_PI / 180, axis));
}

class HandWrittenConventions : public ::testing::Test {
 protected:
  std::vector<RetargetedFrame> retarget(const MocapClip& clip) {
    return retarget_clip(clip, model_,
                         plan_retargeting(clip, model_, guess_skeleton_mapping(clip)));
  }
  BodyModel model_ = test::bundled_model();
};

/// The skeleton of a hierarchy text (parsed with one frame of zeros).
MocapClip skeleton_of(const std::string& text) {
  int columns = 0;
  for (std::size_t at = text.find("CHANNELS "); at != std::string::npos;
       at = text.find("CHANNELS ", at + 1))
    columns += std::stoi(text.substr(at + 9));
  std::string row = "0";
  for (int c = 1; c < columns; ++c)
    row += " 0";
  return parse_bvh(text + "MOTION\nFrames: 1\nFrame Time: 1\n" + row + "\n", "hierarchy.bvh");
}

TEST_F(HandWrittenConventions, ImportToTheSamePoses) {
  const MocapClip saltus = clip_with_frames(model_skeleton_clip(model_), saltus_frames());
  const MocapClip zup = clip_with_frames(skeleton_of(kZupHierarchy), zup_frames());
  const MocapClip deepmimic =
      clip_with_frames(skeleton_of(kDeepMimicHierarchy), deepmimic_frames());

  // The intended poses, in Saltus's frame.
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY();
  std::vector<std::map<std::string, Eigen::Quaterniond>> expected{
      {},
      {{"root", about(x, -60)}},
      {{"elbow_l", about(x, -90)}},
      {{"hip_r", about(x, -90)}, {"knee_r", about(x, 90)}},
      {{"root", about(y, 30)}},
      {{"root", about(x, -60) * about(y, 30)}}};

  for (const MocapClip* clip : {&saltus, &zup, &deepmimic}) {
    const std::vector<RetargetedFrame> frames = retarget(*clip);
    const std::string label = clip->joints[0].name;
    ASSERT_EQ(frames.size(), expected.size());
    for (std::size_t f = 0; f < frames.size(); ++f) {
      for (int s = 0; s < model_.size(); ++s) {
        const std::string& joint = model_.segments[s].joint;
        const Eigen::Quaterniond want =
            expected[f].count(joint) ? expected[f].at(joint) : Eigen::Quaterniond::Identity();
        EXPECT_LT(rotation_angle_between(frames[f].joint_rotation[s], want), 1e-9)
            << label << " frame " << f << " joint " << joint;
      }
      // The hip centre stays at (0, 0.9, 0).
      const Eigen::Vector3d hip_centre =
          frames[f].root_position +
          frames[f].world_rotation[model_.segment_index("pelvis")] * Eigen::Vector3d(0, -0.1423, 0);
      EXPECT_LT((hip_centre - Eigen::Vector3d(0, 0.9, 0)).norm(), 1e-9) << label << " frame " << f;
    }
  }
}

TEST_F(HandWrittenConventions, AxesAndUnitsAreFoundFromTheRestSkeleton) {
  const MocapClip zup = clip_with_frames(skeleton_of(kZupHierarchy), zup_frames());
  const Retargeting plan = plan_retargeting(zup, model_, guess_skeleton_mapping(zup));
  EXPECT_EQ(plan.axes.unit, "m");
  EXPECT_EQ(plan.axes.up_name, "+z");
  // Saltus x = x, y = z, z = −y.
  Eigen::Matrix3d expected;
  expected << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  EXPECT_LT((plan.axes.saltus_from_source - expected).norm(), 1e-12);
  EXPECT_EQ(plan.mapping.convention, "HumanIK");
  EXPECT_EQ(plan.drives[model_.segment_index("abdomen")].joints.size(), 2u);  // Spine, Spine1
  EXPECT_EQ(zup.joints[plan.thorax_joint].name, "Spine2");
  const MocapClip dm = clip_with_frames(skeleton_of(kDeepMimicHierarchy), deepmimic_frames());
  const Retargeting dm_plan = plan_retargeting(dm, model_, guess_skeleton_mapping(dm));
  EXPECT_EQ(dm_plan.axes.unit, "cm");
  EXPECT_EQ(dm_plan.drives[model_.segment_index("abdomen")].kind, SegmentDrive::Kind::kHalfway);
}

TEST(Retarget, ShortestRotationAndAverage) {
  const Eigen::Vector3d down(0, -1, 0);
  for (const Eigen::Vector3d& to : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                    Eigen::Vector3d(0.6, -0.8, 0), Eigen::Vector3d(0, -1, 0)}) {
    const Eigen::Quaterniond q = shortest_rotation(down, to);
    EXPECT_LT((q * down - to).norm(), 1e-12);
    // Shortest: the axis is perpendicular to both directions.
    const Eigen::AngleAxisd aa(q);
    if (aa.angle() > 1e-9) {
      EXPECT_NEAR(aa.axis().dot(down), 0.0, 1e-12);
    }
  }
  const Eigen::Quaterniond a = about(Eigen::Vector3d::UnitX(), 10);
  const Eigen::Quaterniond b = about(Eigen::Vector3d::UnitX(), 30);
  Eigen::Quaterniond flipped = b;
  flipped.coeffs() *= -1;  // the same rotation
  EXPECT_LT(rotation_angle_between(average_rotation({a, flipped}, {0.5, 0.5}),
                                   about(Eigen::Vector3d::UnitX(), 20)),
            1e-12);
}

}  // namespace
}  // namespace saltus
