#pragma once
/// @file
/// Retargeting a capture onto the body model by world-frame segment orientations.
///
/// For every frame, forward kinematics gives each source joint's world rotation W_j (its bone
/// turns with it). A model segment driven by joint j takes the world orientation
///     R_s = A · W_j · Aᵀ · T_s,
/// where A turns the source's axes into Saltus's (up -> +y, the skeleton's left -> +x, units to
/// metres for positions) and T_s removes the rest-pose difference: for arms and legs T_s is the
/// shortest rotation taking the model segment's long axis (its -y) onto the source bone's rest
/// direction, so a T-pose or A-pose arm and a slightly bent rest knee map to what they are; the
/// trunk and the feet take the source's rest pose as upright and neutral (T_s = I): a BVH rest
/// pose stands upright, and the model's foot at identity is the neutral standing foot (see
/// docs/motion-capture.md for the model's foot and hand conventions). Joint rotations follow as
/// parent_from_child = R_parent⁻¹ R_child. The root (abdomen) is placed so that the model's hip
/// centre (midway between its hip joints) is at the source's hip centre.
///
/// The heading (yaw about the vertical) is left as the source has it; capture_import.h turns the
/// somersault axis onto x afterwards (apply_heading).

#include <array>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/capture/mocap_clip.h"
#include "saltus/capture/skeleton_mapping.h"

namespace saltus {

/// How one model segment gets its orientation from the source.
struct SegmentDrive {
  enum class Kind {
    kJoint,    ///< one source joint
    kAverage,  ///< several source joints' world rotations averaged (weights: bone lengths)
    kHalfway,  ///< halfway between the pelvis and the thorax (abdomen without spine joints)
    kFollows,  ///< no source joint: the segment keeps its parent's orientation (foot)
  };
  Kind kind = Kind::kJoint;
  std::vector<int> joints;      ///< source joints (kJoint: one; kAverage: several)
  std::vector<double> weights;  ///< kAverage, summing to 1
  /// Limbs: the source bone's rest direction (source axes, unit) that the segment's long axis
  /// follows; trunk and feet: unused (rest taken as upright).
  bool along_bone = false;
  Eigen::Vector3d rest_direction = Eigen::Vector3d::Zero();
  std::string rest_direction_to;  ///< what the bone points at ("LeftForeArm", "End Site of …")
  Eigen::Quaterniond rest_correction = Eigen::Quaterniond::Identity();  ///< T_s, Saltus axes
  std::string description;  ///< for result.json, e.g. "average of Spine, Spine1"
};

/// The source's units and axes.
struct CaptureAxes {
  double metres_per_unit = 1.0;
  std::string unit;            ///< "m", "cm", "mm", "inch" (or "given" by a mapping file)
  bool unit_detected = true;   ///< from the skeleton's height, not given
  double rest_height_m = 0.0;  ///< the rest skeleton's extent along up, in metres
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();  ///< source axes
  std::string up_name;                            ///< "+y", "+z", ...
  bool up_detected = true;
  /// Source direction -> Saltus direction (a rotation): up -> +y, the rest skeleton's left -> +x.
  Eigen::Matrix3d saltus_from_source = Eigen::Matrix3d::Identity();
};

/// Everything fixed about a clip's retargeting (skeleton, mapping, model); per-frame work is
/// retarget_frame.
struct Retargeting {
  SkeletonMapping mapping;
  CaptureAxes axes;
  std::vector<SegmentDrive> drives;  ///< per model segment, model order
  int pelvis_joint = -1;             ///< source joints of the pelvis and the thorax
  int thorax_joint = -1;
  std::array<int, 2> hip_joints{-1, -1};  ///< source thigh joints, left then right
  Eigen::Vector3d model_hip_centre = Eigen::Vector3d::Zero();  ///< pelvis frame, m
  /// Per foot (left, right): (source joint, offset in its frame) pairs whose world positions are
  /// the foot's points (ankle, toes, End Sites) for ground contact.
  std::array<std::vector<std::pair<int, Eigen::Vector3d>>, 2> foot_points;
  /// Source joints that play no part, with the reason (helper, finger, neck/head, ...).
  std::vector<std::pair<std::string, std::string>> unused_joints;
};

/// The model segments a capture can drive; the model must have all of them (docs/formats.md,
/// "Body model").
const std::vector<std::string>& retargeted_segments();

/// Plans the retargeting. Throws std::invalid_argument when the mapping names joints the clip
/// lacks, the model lacks a segment of docs/formats.md, or the rest skeleton is degenerate (hips at
/// one point).
Retargeting plan_retargeting(const MocapClip& clip, const BodyModel& model,
                             const SkeletonMapping& mapping);

/// One frame on the model, in Saltus axes and metres, heading as in the source.
struct RetargetedFrame {
  std::vector<Eigen::Quaterniond> world_rotation;  ///< world_from_segment, per model segment
  std::vector<Eigen::Quaterniond> joint_rotation;  ///< parent_from_child (root: world)
  Eigen::Vector3d root_position = Eigen::Vector3d::Zero();  ///< abdomen origin, world, m
  std::array<std::vector<Eigen::Vector3d>, 2> foot_points;  ///< world, m (left, right)
};

RetargetedFrame retarget_frame(const MocapClip& clip, const BodyModel& model,
                               const Retargeting& plan, int frame);

std::vector<RetargetedFrame> retarget_clip(const MocapClip& clip, const BodyModel& model,
                                           const Retargeting& plan);

/// Turns every frame about the vertical (+y) through the world origin by `yaw` (rad): root
/// orientation, world rotations, positions.
void apply_heading(std::vector<RetargetedFrame>& frames, double yaw);

/// Shortest rotation taking unit vector `from` onto unit vector `to` (about x when they are
/// opposite and perpendicular to x, else about the axis perpendicular to both).
Eigen::Quaterniond shortest_rotation(const Eigen::Vector3d& from, const Eigen::Vector3d& to);

/// Weighted average of rotations (sign-aligned to the first, normalised sum): the chordal L2
/// mean, exact for equal rotations, for the spine joints composed into one segment.
Eigen::Quaterniond average_rotation(const std::vector<Eigen::Quaterniond>& rotations,
                                    const std::vector<double>& weights);

}  // namespace saltus
