#include "saltus/formats/capture_mapping_file.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "saltus/base/json_reader.h"
#include "saltus/base/text_format.h"

namespace saltus {

namespace {

constexpr const char* kMappingFormat = "saltus-capture-mapping/1";

std::string key_list() {
  std::string out;
  for (const std::string& key : mapping_keys())
    out += (out.empty() ? "" : ", ") + key;
  return out;
}

double parse_unit(const JsonNode& node) {
  if (node.value().is_string()) {
    const std::string unit = node.as_string();
    if (unit == "m") return 1.0;
    if (unit == "cm") return 0.01;
    if (unit == "mm") return 0.001;
    if (unit == "inch" || unit == "in") return 0.0254;
    node.fail("unknown unit \"" + message_text(unit) +
              "\" (expected m, cm, mm, inch or metres per unit)");
  }
  // Metres per unit: from a tenth of a millimetre to 10 m (a micrometre or a kilometre unit
  // makes a person's skeleton a speck or a mountain, and 1e308 overflowed the positions).
  return node.as_double_within(kMinMetresPerUnit, kMaxMetresPerUnit, "metres per unit");
}

Eigen::Vector3d parse_up(const JsonNode& node) {
  const std::string text = node.as_string();
  std::string axis = text;
  double sign = 1.0;
  if (!axis.empty() && (axis[0] == '-' || axis[0] == '+')) {
    sign = axis[0] == '-' ? -1.0 : 1.0;
    axis = axis.substr(1);
  }
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
  if (axis == "x" || axis == "X")
    up.x() = sign;
  else if (axis == "y" || axis == "Y")
    up.y() = sign;
  else if (axis == "z" || axis == "Z")
    up.z() = sign;
  else
    node.fail("unknown up axis \"" + message_text(text) + "\" (expected x, y, z, -x, -y or -z)");
  return up;
}

std::vector<std::string> parse_joint_names(const JsonNode& node) {
  if (node.is_null()) return {};
  if (node.value().is_string()) {
    const std::string name = node.as_string();
    if (name.empty()) node.fail("an empty joint name");
    return {name};
  }
  if (!node.is_array())
    node.fail("expected a joint name, a list of joint names or null, found " +
              std::string(node.value().type_name()));
  std::vector<std::string> names;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string name = node.at(i).as_string();
    if (name.empty()) node.at(i).fail("an empty joint name");
    names.push_back(name);
  }
  return names;
}

}  // namespace

SkeletonMapping parse_capture_mapping(const nlohmann::json& document, const std::string& file) {
  const JsonNode root(document, file);
  root.require_object();
  const JsonNode format = root.at("format");
  if (format.as_string() != kMappingFormat)
    format.fail("expected format \"" + std::string(kMappingFormat) + "\", found \"" +
                message_text(format.as_string()) + "\"");
  for (const auto& [key, child] : root.members())
    if (key != "format" && key != "unit" && key != "up" && key != "joints" && key != "comment")
      child.fail("unknown field \"" + message_text(key) +
                 "\" (expected format, unit, up, joints, comment)");
  SkeletonMapping mapping;
  mapping.convention = "mapping file";
  if (auto unit = root.find("unit")) mapping.metres_per_unit = parse_unit(*unit);
  if (auto up = root.find("up")) mapping.up = parse_up(*up);
  const JsonNode joints = root.at("joints");
  joints.require_object();
  for (const auto& [key, child] : joints.members()) {
    const auto& keys = mapping_keys();
    if (std::find(keys.begin(), keys.end(), key) == keys.end())
      child.fail("unknown key \"" + message_text(key) + "\" (expected " + key_list() + ")");
    std::vector<std::string> names = parse_joint_names(child);
    const bool single = key != "abdomen" && key != "thorax";
    if (single && names.size() > 1)
      child.fail(key + " takes one joint (only the abdomen and the thorax may average several)");
    const bool optional = key == "abdomen" || key == "thorax" || key == "foot_l" ||
                          key == "foot_r" || key == "hand_l" || key == "hand_r";
    if (!optional && names.empty())
      child.fail(key + " needs a source joint (only abdomen, thorax, feet and hands may be null)");
    mapping.joints[key] = names;
  }
  return mapping;
}

SkeletonMapping load_capture_mapping(const std::string& path) {
  return parse_capture_mapping(read_json_file(path), path);
}

void check_capture_mapping(const SkeletonMapping& mapping, const MocapClip& clip,
                           const std::string& mapping_file, const std::string& capture_file) {
  for (const auto& [key, names] : mapping.joints) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (clip.joint_index(names[i]) >= 0) continue;
      std::string path = "/joints/" + json_pointer_escape(key);
      if (names.size() > 1) path += "/" + std::to_string(i);
      throw InputError(mapping_file, path,
                       "joint \"" + message_text(names[i]) + "\" is not in " + capture_file);
    }
  }
}

}  // namespace saltus
