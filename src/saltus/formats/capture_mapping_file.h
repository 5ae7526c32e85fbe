#pragma once
/// @file
/// "saltus-capture-mapping/1" files: an explicit skeleton mapping for captures whose joint
/// names no built-in convention knows (docs/motion-capture.md):
///
///     { "format": "saltus-capture-mapping/1",
///       "unit": "cm",                      // optional: "m", "cm", "mm", "inch" or metres/unit
///       "up": "z",                         // optional: "x", "y", "z", "-x", "-y", "-z"
///       "joints": {
///         "pelvis": "Hips",                // the pelvis: one joint
///         "abdomen": ["Spine", "Spine1"],  // several: their world rotations averaged
///         "thorax": "Chest",               // neck and head are part of the thorax
///         "upper_arm_l": "L_UpperArm", "forearm_l": "L_Forearm", "hand_l": "L_Hand",
///         "thigh_l": "L_Thigh", "shank_l": "L_Calf", "foot_l": null, ... } }
///
/// Keys are the model's segments plus the wrists "hand_l"/"hand_r" (where the forearm points).
/// null or [] means "none": the abdomen lies halfway between pelvis and thorax, the thorax is
/// the joint where the arms' chains meet, a foot follows its shank, a forearm points along its
/// longest child bone. Keys left out are found by name as without a mapping file.

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "saltus/capture/mocap_clip.h"
#include "saltus/capture/skeleton_mapping.h"

namespace saltus {

/// The range of a numeric "unit" (metres per unit): 0.1 mm to 10 m.
inline constexpr double kMinMetresPerUnit = 1e-4;
inline constexpr double kMaxMetresPerUnit = 10.0;

/// Parses a mapping document; `file` names it in errors (InputError with the JSON path).
SkeletonMapping parse_capture_mapping(const nlohmann::json& document, const std::string& file);

/// Reads a mapping file.
SkeletonMapping load_capture_mapping(const std::string& path);

/// Checks that every joint the mapping names is in the clip: InputError naming the mapping
/// file, the JSON path (/joints/thigh_l) and the capture file otherwise.
void check_capture_mapping(const SkeletonMapping& mapping, const MocapClip& clip,
                           const std::string& mapping_file, const std::string& capture_file);

}  // namespace saltus
