#include "saltus/capture/skeleton_mapping.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace saltus {

namespace {

/// One naming convention: per mapping key, candidate normalized names. "{side}" stands for
/// "left"/"right", "{s}" for "l"/"r" (the key's _l or _r decides).
struct NameTable {
  const char* convention;
  std::vector<std::pair<std::string, std::vector<std::string>>> keys;
};

const std::vector<NameTable>& name_tables() {
  static const std::vector<NameTable> kTables{
      {"Saltus",
       {{"pelvis", {"pelvis"}},
        {"abdomen", {"abdomen"}},
        {"thorax", {"thorax"}},
        {"upper_arm", {"upperarm{s}"}},
        {"forearm", {"forearm{s}"}},
        {"thigh", {"thigh{s}"}},
        {"shank", {"shank{s}"}},
        {"foot", {"foot{s}"}}}},
      {"DeepMimic",
       {{"pelvis", {"root"}},
        {"thorax", {"chest"}},
        {"upper_arm", {"{side}shoulder"}},
        {"forearm", {"{side}elbow"}},
        {"hand", {"{side}wrist"}},
        {"thigh", {"{side}hip"}},
        {"shank", {"{side}knee"}},
        {"foot", {"{side}ankle"}}}},
      {"HumanIK",
       {{"pelvis", {"hips", "hip", "pelvis"}},
        {"upper_arm", {"{side}arm", "{side}upperarm"}},
        {"forearm", {"{side}forearm", "{side}lowerarm"}},
        {"hand", {"{side}hand", "{side}wrist"}},
        {"thigh", {"{side}upleg", "{side}upperleg", "{side}thigh"}},
        {"shank", {"{side}leg", "{side}lowerleg", "{side}shin"}},
        {"foot", {"{side}foot", "{side}ankle"}}}},
      {"CMU",
       {{"pelvis", {"hip", "hips", "root"}},
        {"upper_arm", {"{s}humerus"}},
        {"forearm", {"{s}radius"}},
        {"hand", {"{s}wrist"}},
        {"thigh", {"{s}femur"}},
        {"shank", {"{s}tibia"}},
        {"foot", {"{s}foot"}}}},
      {"Rigify",
       {{"pelvis", {"spine", "hips"}},
        {"upper_arm", {"upperarm{s}"}},
        {"forearm", {"forearm{s}"}},
        {"hand", {"hand{s}"}},
        {"thigh", {"thigh{s}"}},
        {"shank", {"shin{s}"}},
        {"foot", {"foot{s}"}}}},
  };
  return kTables;
}

const std::vector<std::string>& required_keys() {
  static const std::vector<std::string> kRequired{"pelvis",      "thigh_l",   "thigh_r",
                                                  "shank_l",     "shank_r",   "upper_arm_l",
                                                  "upper_arm_r", "forearm_l", "forearm_r"};
  return kRequired;
}

std::string lower(const std::string& s) {
  std::string out;
  for (char c : s)
    out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  return out;
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

/// "thigh_l" -> ("thigh", "l"); "pelvis" -> ("pelvis", "").
std::pair<std::string, std::string> split_side(const std::string& key) {
  if (key.size() > 2 && (key.substr(key.size() - 2) == "_l" || key.substr(key.size() - 2) == "_r"))
    return {key.substr(0, key.size() - 2), key.substr(key.size() - 1)};
  return {key, ""};
}

/// Normalized name -> joint indices with that name (a rig may hold DEF- and ORG- copies).
std::map<std::string, std::vector<int>> names_by_normalized(const MocapClip& clip) {
  std::map<std::string, std::vector<int>> out;
  for (int j = 0; j < clip.joint_count(); ++j)
    out[normalized_joint_name(clip.joints[j].name)].push_back(j);
  return out;
}

/// Of several joints with the same normalized name, the deforming one ("DEF-") else the first.
int preferred(const MocapClip& clip, const std::vector<int>& joints) {
  for (int j : joints)
    if (starts_with(lower(clip.joints[j].name), "def")) return j;
  return joints.front();
}

std::string convention_label(const MocapClip& clip, const std::string& table) {
  if (table != "HumanIK") return table;
  bool mixamo = false, motion_builder = false, cmu = false;
  for (const MocapJoint& joint : clip.joints) {
    const std::string name = lower(joint.name);
    if (starts_with(name, "mixamorig")) mixamo = true;
    if (starts_with(name, "character") && contains(name, "_")) motion_builder = true;
    const std::string n = normalized_joint_name(joint.name);
    if (n == "lowerback" || n == "lhipjoint" || n == "rhipjoint") cmu = true;
  }
  if (mixamo) return "Mixamo";
  if (motion_builder) return "MotionBuilder";
  if (cmu) return "CMU";
  return "HumanIK";
}

/// The mapping one table gives, and the required keys it misses.
std::pair<SkeletonMapping, std::vector<std::string>> apply_table(const MocapClip& clip,
                                                                 const NameTable& table) {
  const auto names = names_by_normalized(clip);
  SkeletonMapping mapping;
  mapping.convention = convention_label(clip, table.convention);
  for (const std::string& key : mapping_keys()) {
    const auto [base, side] = split_side(key);
    for (const auto& [table_key, patterns] : table.keys) {
      if (table_key != base) continue;
      for (const std::string& pattern : patterns) {
        std::string name = replace_all(pattern, "{side}", side == "l" ? "left" : "right");
        name = replace_all(name, "{s}", side);
        const auto it = names.find(name);
        if (it != names.end()) {
          mapping.joints[key] = {clip.joints[preferred(clip, it->second)].name};
          break;
        }
      }
    }
  }
  std::vector<std::string> missing;
  for (const std::string& key : required_keys())
    if (mapping.joints.count(key) == 0) missing.push_back(key);
  return {mapping, missing};
}

double rest_extent(const MocapClip& clip) {
  const MocapPose rest = mocap_rest_pose(clip);
  Eigen::Vector3d lo = rest.world_position[0], hi = lo;
  for (int j = 0; j < clip.joint_count(); ++j) {
    lo = lo.cwiseMin(rest.world_position[j]);
    hi = hi.cwiseMax(rest.world_position[j]);
  }
  return (hi - lo).maxCoeff();
}

bool is_finger(const std::string& n) {
  for (const char* part : {"finger", "thumb", "index", "middle", "ring", "pinky", "little"})
    if (contains(n, part)) return true;
  return false;
}

}  // namespace

const std::vector<std::string>& mapping_keys() {
  static const std::vector<std::string> kKeys{
      "pelvis",      "abdomen",   "thorax",  "upper_arm_l", "forearm_l",
      "upper_arm_r", "forearm_r", "thigh_l", "shank_l",     "foot_l",
      "thigh_r",     "shank_r",   "foot_r",  "hand_l",      "hand_r"};
  return kKeys;
}

std::string normalized_joint_name(const std::string& name) {
  std::string s = name;
  const std::size_t colon = s.rfind(':');
  if (colon != std::string::npos) s = s.substr(colon + 1);
  s = lower(s);
  // Rig prefixes: MotionBuilder's "Character1_", Rigify's "DEF-"/"ORG-", Mixamo without a
  // namespace ("mixamorig_"), 3ds Max Biped's "Bip01 ".
  if (starts_with(s, "character")) {
    std::size_t i = 9;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])))
      ++i;
    if (i < s.size() && s[i] == '_') s = s.substr(i + 1);
  }
  for (const char* prefix : {"def-", "def_", "org-", "org_", "mixamorig_", "bip01 ", "bip001 "})
    if (starts_with(s, prefix)) s = s.substr(std::string(prefix).size());
  std::string out;
  for (char c : s)
    if (std::isalnum(static_cast<unsigned char>(c))) out.push_back(c);
  return out;
}

SkeletonMapping guess_skeleton_mapping(const MocapClip& clip) {
  std::string report;
  for (const NameTable& table : name_tables()) {
    auto [mapping, missing] = apply_table(clip, table);
    if (missing.empty()) return mapping;
    std::string list;
    for (const std::string& key : missing)
      list += (list.empty() ? "" : ", ") + key;
    report += std::string(report.empty() ? "" : "; ") + table.convention + " names lack " + list;
  }
  throw CaptureError(CapturePart::kSkeleton,
                     "no naming convention fits the skeleton (" + report +
                         "); give a mapping file (--mapping, see docs/motion-capture.md)");
}

SkeletonMapping merge_skeleton_mapping(const MocapClip& clip,
                                       const SkeletonMapping& explicit_mapping) {
  SkeletonMapping merged;
  std::string guess_problem;
  try {
    merged = guess_skeleton_mapping(clip);
  } catch (const std::invalid_argument& e) {
    guess_problem = e.what();
    // The best partial guess still fills keys the file leaves out.
    std::size_t best = 0;
    for (const NameTable& table : name_tables()) {
      auto [mapping, missing] = apply_table(clip, table);
      if (mapping.joints.size() > best) best = mapping.joints.size(), merged = mapping;
    }
  }
  merged.convention = "mapping file";
  for (const auto& [key, joints] : explicit_mapping.joints)
    merged.joints[key] = joints;
  merged.metres_per_unit = explicit_mapping.metres_per_unit;
  merged.up = explicit_mapping.up;
  std::string missing;
  for (const std::string& key : required_keys())
    if (merged.joints.count(key) == 0 || merged.joints[key].empty())
      missing += (missing.empty() ? "" : ", ") + key;
  if (!missing.empty())
    throw CaptureError(CapturePart::kMapping,
                       "the mapping gives no source joint for " + missing +
                           (guess_problem.empty() ? "" : " (" + guess_problem + ")"));
  return merged;
}

bool is_helper_joint(const MocapClip& clip, int joint) {
  const std::string n = normalized_joint_name(clip.joints[joint].name);
  return contains(n, "rigmesh") || is_finger(n) || contains(n, "roll") || contains(n, "twist");
}

std::string unused_joint_reason(const MocapClip& clip, int joint) {
  const std::string n = normalized_joint_name(clip.joints[joint].name);
  if (contains(n, "rigmesh")) return "helper (_RIGMESH)";
  if (is_finger(n)) return "finger";
  if (contains(n, "roll") || contains(n, "twist")) return "roll/twist helper";
  if (contains(n, "clavicle") || contains(n, "shoulder") || contains(n, "collar"))
    return "clavicle (part of the thorax)";
  if (contains(n, "neck") || contains(n, "head")) return "neck/head (part of the thorax)";
  if (contains(n, "toe")) return "toe (part of the foot)";
  // A bone whose children and End Sites all sit at its own joint has no extent.
  double length = 0.0;
  for (int child : clip.children(joint))
    length = std::max(length, clip.joints[child].offset.norm());
  for (const Eigen::Vector3d& site : clip.joints[joint].end_sites)
    length = std::max(length, site.norm());
  if (length <= 1e-3 * rest_extent(clip)) return "zero-length bone";
  return "not needed";
}

}  // namespace saltus
