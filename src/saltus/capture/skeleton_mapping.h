#pragma once
/// @file
/// Which source joints drive which segment of the body model (the 13 segments of docs/formats.md,
/// "Body model"), found by name for the common naming conventions or given explicitly
/// (formats/capture_mapping_file.h).
///
/// A mapping names, per model segment, the source joint whose world orientation the segment
/// takes, or several joints whose world orientations are averaged (spine joints the model lacks
/// composed into one trunk segment), or none (the abdomen then lies halfway between the pelvis
/// and the thorax; a foot without a source joint follows its shank). Two landmarks complete it:
/// the wrist joints ("hand_l", "hand_r"), where the forearm (which includes the hand) points.
/// The thorax includes neck and head, so their rotations relative to the chest are dropped.

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "saltus/capture/mocap_clip.h"

namespace saltus {

/// The keys a mapping may give: the 13 model segments and the two wrist landmarks.
const std::vector<std::string>& mapping_keys();

/// A mapping that does not fit the skeleton, caused by the entry for `key` (a mapping key such as
/// "forearm_l"): a front end names the mapping file's /joints/<key> when the key came from it.
class MappingError : public std::invalid_argument {
 public:
  MappingError(std::string key, const std::string& problem)
      : std::invalid_argument(problem), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

struct SkeletonMapping {
  /// "Saltus", "DeepMimic", "Mixamo", "MotionBuilder", "CMU", "HumanIK", "Rigify" or
  /// "mapping file"; what result.json reports.
  std::string convention;
  /// Mapping key -> source joint names (exact names as in the file). An empty list means
  /// "derived" (see the file comment); a key that is absent is found automatically when the
  /// mapping is merged over a guessed one.
  std::map<std::string, std::vector<std::string>> joints;
  /// Source length unit in metres per unit (0.01 for cm); unset: detected from the skeleton's
  /// height (see detect_unit).
  std::optional<double> metres_per_unit;
  /// The source world's up direction (a unit coordinate axis, e.g. (0, 0, 1)); unset: the axis
  /// closest to the rest pose's pelvis-to-thorax direction.
  std::optional<Eigen::Vector3d> up;
};

/// Guesses the mapping from joint names. Names are compared after dropping a namespace
/// ("mixamorig:"), the prefixes "Character1_", "DEF-", "ORG-", case and punctuation. Tables:
/// Saltus's own segment names (what `saltus export` writes); DeepMimic (root, chest, neck,
/// left_hip, left_knee, left_ankle, left_shoulder, left_elbow, left_wrist); HumanIK names used by
/// Mixamo, MotionBuilder (Character1_*) and the CMU BVH conversions (Hips, Spine…, LeftUpLeg,
/// LeftLeg, LeftFoot, LeftArm, LeftForeArm, LeftHand; LowerBack/LHipJoint mark CMU); CMU's
/// ASF names (hip, lfemur, ltibia, lfoot, lhumerus, lradius, lwrist); Blender Rigify (spine =
/// the pelvis bone, spine.001…, thigh.L, shin.L, foot.L, upper_arm.L, forearm.L, hand.L).
/// The first table that names the pelvis, both thighs, shanks, upper arms and forearms wins.
/// Throws std::invalid_argument listing what is missing when no table fits.
SkeletonMapping guess_skeleton_mapping(const MocapClip& clip);

/// `explicit_mapping`'s entries replace the guessed ones; keys it does not give are guessed by
/// name (if that fails the explicit mapping must give every required key). Unit and up come
/// from the explicit mapping when set.
SkeletonMapping merge_skeleton_mapping(const MocapClip& clip,
                                       const SkeletonMapping& explicit_mapping);

/// A joint name with namespace and rig prefixes dropped, lower case, letters and digits only:
/// "mixamorig:LeftForeArm" -> "leftforearm", "DEF-upper_arm.L" -> "upperarml".
std::string normalized_joint_name(const std::string& name);

/// Why a source joint plays no part in the mapping, for result.json: "helper (_RIGMESH)",
/// "zero-length bone", "finger", "roll/twist helper", "clavicle (part of the thorax)",
/// "neck/head (part of the thorax)", "toe (part of the foot)", or "not needed".
std::string unused_joint_reason(const MocapClip& clip, int joint);

/// True for joints that carry no body part, by name: *_RIGMESH and similar mesh helpers,
/// fingers, roll and twist bones.
bool is_helper_joint(const MocapClip& clip, int joint);

}  // namespace saltus
