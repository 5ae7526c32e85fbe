#pragma once
// Rewrites a clip in Saltus's own skeleton (what `saltus export` writes) as another capture
// convention would record the same performance: other names (with spine, clavicle, neck, head,
// hand, finger, toe and helper joints the model lacks), other world axes (z up, facing −y or
// +x), other units, another Euler order, a T- or A-pose rest, and the performer facing elsewhere
// than the rest pose. Every joint's world placement follows from the Saltus segments' by the
// convention's definition, not by the importer's rules: the joints the model lacks get arbitrary
// rotations that move no body part the model has (a clavicle twisting about its own bone, the
// neck nodding, the wrist and toes bending), and each limb's T/A rest turns its bone about the
// forward axis.

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "saltus/capture/mocap_clip.h"

namespace saltus::test {

struct CaptureConvention {
  /// Name of each part: pelvis, spine, spine1, chest, neck, head, helper and, per side (_l/_r),
  /// clavicle, upper_arm, forearm, hand, finger, thigh, shank, foot, toe.
  std::map<std::string, std::string> names;
  Eigen::Matrix3d source_from_saltus = Eigen::Matrix3d::Identity();  ///< a rotation
  double units_per_metre = 100.0;
  std::vector<int> rotation_axes{2, 0, 1};
  double arm_rest_deg = 0.0;         ///< 0 arms down, 90 T-pose, 45 A-pose
  double performance_yaw_deg = 0.0;  ///< the whole performance turned about the vertical
  bool legs_first = false;
};

namespace detail {

inline Eigen::Quaterniond about(const Eigen::Vector3d& axis, double deg) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(deg * 3.14159265358979323846 / 180, axis));
}

struct PartSpec {
  std::string part;        ///< key into names
  std::string parent;      ///< part key, "" for the root
  Eigen::Vector3d offset;  ///< Saltus axes, metres, rest
  std::vector<Eigen::Vector3d> end_sites;
};

}  // namespace detail

/// `saltus_clip` is a clip of the model's skeleton (model_clip.h), y up, cm.
inline MocapClip convert_clip(const MocapClip& saltus_clip, const CaptureConvention& c) {
  using detail::about;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  // Each arm's rest: a turn about the forward axis taking "down" towards its side.
  const Eigen::Quaterniond rest_l = about(z, c.arm_rest_deg), rest_r = about(z, -c.arm_rest_deg);
  const Eigen::Vector3d down(0, -1, 0);
  std::vector<detail::PartSpec> parts{{"pelvis", "", Eigen::Vector3d::Zero(), {}}};
  auto legs = [&]() {
    for (const std::string s : {"_l", "_r"}) {
      const double side = s == "_l" ? 1 : -1;
      parts.push_back({"thigh" + s, "pelvis", Eigen::Vector3d(side * 0.085, 0, 0), {}});
      parts.push_back({"shank" + s, "thigh" + s, Eigen::Vector3d(0, -0.4123, 0), {}});
      parts.push_back({"foot" + s, "shank" + s, Eigen::Vector3d(0, -0.4299, 0), {}});
      parts.push_back({"toe" + s, "foot" + s, Eigen::Vector3d(0, -0.05, 0.12), {0.05 * z}});
    }
  };
  auto trunk = [&]() {
    parts.push_back({"spine", "pelvis", Eigen::Vector3d(0, 0.1423, 0), {}});
    parts.push_back({"helper", "spine", Eigen::Vector3d::Zero(), {Eigen::Vector3d::Zero()}});
    parts.push_back({"spine1", "spine", Eigen::Vector3d(0, 0.1052, 0), {}});
    parts.push_back({"chest", "spine1", Eigen::Vector3d(0, 0.1052, 0), {}});
    parts.push_back({"neck", "chest", Eigen::Vector3d(0, 0.22, 0), {}});
    parts.push_back({"head", "neck", Eigen::Vector3d(0, 0.1, 0), {0.12 * y}});
    for (const std::string s : {"_l", "_r"}) {
      const double side = s == "_l" ? 1 : -1;
      const Eigen::Quaterniond& rest = s == "_l" ? rest_l : rest_r;
      parts.push_back({"clavicle" + s, "chest", Eigen::Vector3d(side * 0.03, 0.1507, 0), {}});
      parts.push_back({"upper_arm" + s, "clavicle" + s, Eigen::Vector3d(side * 0.15, 0, 0), {}});
      parts.push_back({"forearm" + s, "upper_arm" + s, rest * (0.2751 * down), {}});
      parts.push_back({"hand" + s, "forearm" + s, rest * (0.27 * down), {}});
      parts.push_back({"finger" + s, "hand" + s, rest * (0.08 * down), {rest * (0.03 * down)}});
    }
  };
  if (c.legs_first) {
    legs();
    trunk();
  } else {
    trunk();
    legs();
  }

  MocapClip out;
  std::map<std::string, int> index;
  for (const detail::PartSpec& p : parts) {
    MocapJoint joint;
    joint.name = c.names.at(p.part);
    joint.parent = p.parent.empty() ? -1 : index.at(p.parent);
    joint.offset = c.units_per_metre * (c.source_from_saltus * p.offset);
    for (const Eigen::Vector3d& site : p.end_sites)
      joint.end_sites.push_back(c.units_per_metre * (c.source_from_saltus * site));
    if (joint.parent < 0)
      joint.channels = {MocapChannel::kXposition, MocapChannel::kYposition,
                        MocapChannel::kZposition};
    for (int axis : c.rotation_axes)
      joint.channels.push_back(axis == 0   ? MocapChannel::kXrotation
                               : axis == 1 ? MocapChannel::kYrotation
                                           : MocapChannel::kZrotation);
    joint.first_column = out.column_count();
    index[p.part] = out.joint_count();
    out.joints.push_back(joint);
  }
  // Children must follow their parent's subtree contiguously: the part list is built that way.
  out.frame_time = saltus_clip.frame_time;

  const Eigen::Quaterniond yaw = about(y, c.performance_yaw_deg);
  const Eigen::Quaterniond axes(c.source_from_saltus);
  for (int f = 0; f < saltus_clip.frame_count(); ++f) {
    const MocapPose pose = mocap_pose(saltus_clip, f);
    auto world = [&](const std::string& segment) {
      return Eigen::Quaterniond(yaw * pose.world_rotation[saltus_clip.joint_index(segment)]);
    };
    const double phase = 0.3 * f;
    std::map<std::string, Eigen::Quaterniond> w;
    w["pelvis"] = world("pelvis");
    w["spine"] = w["spine1"] = world("abdomen");
    w["helper"] = world("abdomen") * about(Eigen::Vector3d(1, 2, 3).normalized(), 40 * phase);
    w["chest"] = world("thorax");
    w["neck"] = world("thorax") * about(x, 20 * std::sin(phase));
    w["head"] = w["neck"] * about(y, 30 * std::cos(phase));
    for (const std::string s : {"_l", "_r"}) {
      const Eigen::Quaterniond& rest = s == "_l" ? rest_l : rest_r;
      w["clavicle" + s] = world("thorax") * about(x, 25 * std::sin(2 * phase));
      w["upper_arm" + s] = world("upper_arm" + s) * rest.conjugate();
      w["forearm" + s] = world("forearm" + s) * rest.conjugate();
      w["hand" + s] = w["forearm" + s] * about(x, 35 * std::sin(phase));
      w["finger" + s] = w["hand" + s] * about(z, 50 * std::cos(phase));
      w["thigh" + s] = world("thigh" + s);
      w["shank" + s] = world("shank" + s);
      w["foot" + s] = world("foot" + s);
      w["toe" + s] = world("foot" + s) * about(x, 30 * std::sin(phase));
    }
    // The hip centre: midway between the model's hip joints.
    const Eigen::Vector3d hip_centre =
        yaw * (0.5 * (pose.world_position[saltus_clip.joint_index("thigh_l")] +
                      pose.world_position[saltus_clip.joint_index("thigh_r")]));

    std::vector<double> row;
    for (const detail::PartSpec& p : parts) {
      const Eigen::Quaterniond local =
          p.parent.empty() ? w.at(p.part) : w.at(p.parent).conjugate() * w.at(p.part);
      if (p.parent.empty()) {
        // Saltus clips are in cm.
        const Eigen::Vector3d position =
            c.units_per_metre * (c.source_from_saltus * (hip_centre / 100.0));
        row.insert(row.end(), {position.x(), position.y(), position.z()});
      }
      for (double angle : euler_deg_from_rotation(c.rotation_axes, axes * local * axes.conjugate()))
        row.push_back(angle);
    }
    out.frames.push_back(row);
  }
  validate_clip(out);
  return out;
}

/// Mixamo: "mixamorig:" names, z up facing −y, metres, X-Y-Z, T-pose, legs first, performed
/// facing 150° away from the rest pose.
inline CaptureConvention mixamo_convention() {
  CaptureConvention c;
  const std::string p = "mixamorig:";
  c.names = {{"pelvis", p + "Hips"},     {"spine", p + "Spine"}, {"spine1", p + "Spine1"},
             {"chest", p + "Spine2"},    {"neck", p + "Neck"},   {"head", p + "Head"},
             {"helper", "Spine_RIGMESH"}};
  for (const auto& [s, side] :
       {std::pair<std::string, std::string>{"_l", "Left"}, {"_r", "Right"}}) {
    c.names["clavicle" + s] = p + side + "Shoulder";
    c.names["upper_arm" + s] = p + side + "Arm";
    c.names["forearm" + s] = p + side + "ForeArm";
    c.names["hand" + s] = p + side + "Hand";
    c.names["finger" + s] = p + side + "HandIndex1";
    c.names["thigh" + s] = p + side + "UpLeg";
    c.names["shank" + s] = p + side + "Leg";
    c.names["foot" + s] = p + side + "Foot";
    c.names["toe" + s] = p + side + "ToeBase";
  }
  c.source_from_saltus << 1, 0, 0, 0, 0, -1, 0, 1, 0;  // x = x, y -> z, z -> −y
  c.units_per_metre = 1.0;
  c.rotation_axes = {0, 1, 2};
  c.arm_rest_deg = 90;
  c.performance_yaw_deg = 150;
  c.legs_first = true;
  return c;
}

/// CMU's BVH conversions: LowerBack/Spine/Spine1 names, y up facing −z, inches, Z-Y-X, A-pose,
/// performed facing 70° to the right of the rest pose.
inline CaptureConvention cmu_convention() {
  CaptureConvention c;
  c.names = {{"pelvis", "Hips"},     {"spine", "LowerBack"}, {"spine1", "Spine"},
             {"chest", "Spine1"},    {"neck", "Neck"},       {"head", "Head"},
             {"helper", "LHipJoint"}};
  for (const auto& [s, side] :
       {std::pair<std::string, std::string>{"_l", "Left"}, {"_r", "Right"}}) {
    c.names["clavicle" + s] = side + "Shoulder";
    c.names["upper_arm" + s] = side + "Arm";
    c.names["forearm" + s] = side + "ForeArm";
    c.names["hand" + s] = side + "Hand";
    c.names["finger" + s] = side + "FingerBase";
    c.names["thigh" + s] = side + "UpLeg";
    c.names["shank" + s] = side + "Leg";
    c.names["foot" + s] = side + "Foot";
    c.names["toe" + s] = side + "ToeBase";
  }
  c.source_from_saltus << -1, 0, 0, 0, 1, 0, 0, 0, -1;  // turned half a turn: facing −z
  c.units_per_metre = 1.0 / 0.0254;
  c.rotation_axes = {2, 1, 0};
  c.arm_rest_deg = 45;
  c.performance_yaw_deg = -70;
  return c;
}

/// Blender Rigify deform bones: y up facing +x, metres, Y-X-Z, arms down.
inline CaptureConvention rigify_convention() {
  CaptureConvention c;
  c.names = {{"pelvis", "DEF-spine"},    {"spine", "DEF-spine.001"}, {"spine1", "DEF-spine.002"},
             {"chest", "DEF-spine.003"}, {"neck", "DEF-spine.004"},  {"head", "DEF-spine.006"},
             {"helper", "DEF-pelvis.L"}};
  for (const auto& [s, side] : {std::pair<std::string, std::string>{"_l", "L"}, {"_r", "R"}}) {
    c.names["clavicle" + s] = "DEF-shoulder." + side;
    c.names["upper_arm" + s] = "DEF-upper_arm." + side;
    c.names["forearm" + s] = "DEF-forearm." + side;
    c.names["hand" + s] = "DEF-hand." + side;
    c.names["finger" + s] = "DEF-f_index.01." + side;
    c.names["thigh" + s] = "DEF-thigh." + side;
    c.names["shank" + s] = "DEF-shin." + side;
    c.names["foot" + s] = "DEF-foot." + side;
    c.names["toe" + s] = "DEF-toe." + side;
  }
  c.source_from_saltus << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // x -> −z, z -> x
  c.units_per_metre = 1.0;
  c.rotation_axes = {1, 0, 2};
  return c;
}

}  // namespace saltus::test
