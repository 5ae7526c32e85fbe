#include "saltus/formats/motion_file.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "saltus/base/json_reader.h"
#include "saltus/base/resources.h"
#include "saltus/base/text_format.h"
#include "saltus/formats/model_file.h"
#include "saltus/math/quaternion.h"

namespace saltus {

namespace {

namespace fs = std::filesystem;

constexpr const char* kMotionFormat = kMotionFormatTag;
/// DESIGN §2: files may be off unit norm by rounding; worse than this is a mistake, not noise.
constexpr double kQuaternionNormTolerance = 1e-3;
/// The first keyframe time must be 0; allow only printing noise so "0.0" and "1e-15" both work.
constexpr double kFirstTimeTolerance = 1e-12;
/// A cubic spline needs at least 4 control points, i.e. 8 knots.
constexpr std::size_t kMinSplineKnots = 8;

/// Rejects members of a nested object that the format does not define. A typo such as
/// "angular_momentun" would otherwise be silently ignored and change the physics.
void reject_unknown_fields(const JsonNode& node, const std::set<std::string>& allowed) {
  for (const auto& [key, child] : node.members()) {
    if (allowed.count(key) == 0) child.fail("unknown field \"" + key + "\"");
  }
}

void check_format_tag(const JsonNode& root) {
  root.require_object();
  const JsonNode format = root.at("format");
  const std::string tag = format.as_string();
  if (tag != kMotionFormat)
    format.fail("expected format \"" + std::string(kMotionFormat) + "\", found \"" + tag + "\"");
}

/// "m1.motion.json" -> "m1": the default motion name.
std::string default_name(const std::string& file) {
  fs::path stem = fs::path(file).filename();
  if (stem.extension() == ".json") stem = stem.stem();
  if (stem.extension() == ".motion") stem = stem.stem();
  return stem.empty() ? std::string("unnamed") : stem.string();
}

/// A stored [w, x, y, z] quaternion, normalised when within tolerance of unit norm.
Eigen::Quaterniond parse_wxyz(const JsonNode& node) {
  const std::vector<double> c = node.as_doubles(4);
  const Eigen::Quaterniond q(c[0], c[1], c[2], c[3]);
  const double norm = q.norm();
  if (std::abs(norm - 1.0) > kQuaternionNormTolerance)
    node.fail("quaternion norm " + message_number(norm) + " is not 1 (tolerance 1e-3)");
  return q.normalized();
}

/// A keyframe rotation: [w, x, y, z] or {"euler_deg": [a, b, c], "order": "XYZ"} (intrinsic).
Eigen::Quaterniond parse_rotation(const JsonNode& node) {
  if (node.is_array()) return parse_wxyz(node);
  if (node.is_object()) {
    reject_unknown_fields(node, {"euler_deg", "order"});
    const Eigen::Vector3d angles = node.at("euler_deg").as_vector3();
    const JsonNode order_node = node.at("order");
    const std::string order = order_node.as_string();
    try {
      return quat_from_euler_deg(angles, order);
    } catch (const std::invalid_argument& e) {
      order_node.fail("invalid Euler order \"" + order + "\": " + e.what());
    }
  }
  node.fail(
      "expected a rotation [w, x, y, z] or {\"euler_deg\": [a, b, c], \"order\": \"XYZ\"}, found " +
      std::string(node.value().type_name()));
}

std::string joint_list(const BodyModel& model) {
  std::string out;
  for (const auto& segment : model.segments)
    out += (out.empty() ? "" : ", ") + segment.joint;
  return out;
}

/// Checks that an object keyed by joint name names every model joint exactly once and nothing
/// else. Returns the member nodes indexed by segment index.
std::vector<JsonNode> joint_members(const JsonNode& node, const BodyModel& model) {
  node.require_object();
  for (const auto& [key, child] : node.members()) {
    if (model.joint_index(key) < 0)
      child.fail("unknown joint \"" + key + "\" (model \"" + model.name +
                 "\" has joints: " + joint_list(model) + ")");
  }
  std::vector<JsonNode> out;
  out.reserve(model.segments.size());
  for (const auto& segment : model.segments) {
    if (!node.has(segment.joint)) node.fail("missing joint \"" + segment.joint + "\"");
    out.push_back(node.at(segment.joint));
  }
  return out;
}

Takeoff parse_takeoff(const JsonNode& node) {
  node.require_object();
  reject_unknown_fields(node, {"com_position", "com_velocity", "angular_momentum"});
  Takeoff takeoff;
  takeoff.com_position = node.at("com_position").as_vector3();
  takeoff.com_velocity = node.at("com_velocity").as_vector3();
  if (auto h = node.find("angular_momentum")) takeoff.angular_momentum = h->as_vector3();
  return takeoff;
}

double parse_positive(const JsonNode& node, const std::string& what) {
  const double v = node.as_double();
  if (!(v > 0.0)) node.fail(what + " must be > 0, found " + message_number(v));
  return v;
}

Tolerances parse_tolerances(const JsonNode& node) {
  node.require_object();
  reject_unknown_fields(node, {"translation_m", "quaternion"});
  Tolerances tolerances;
  if (auto t = node.find("translation_m"))
    tolerances.translation_m = parse_positive(*t, "translation_m");
  if (auto q = node.find("quaternion")) tolerances.quaternion = parse_positive(*q, "quaternion");
  return tolerances;
}

Keyframe parse_keyframe(const JsonNode& node, const BodyModel& model) {
  node.require_object();
  reject_unknown_fields(node, {"time", "rotations", "root_position"});
  Keyframe keyframe;
  keyframe.time = node.at("time").as_double();
  const std::vector<JsonNode> rotations = joint_members(node.at("rotations"), model);
  keyframe.rotations.reserve(rotations.size());
  for (const auto& rotation : rotations)
    keyframe.rotations.push_back(parse_rotation(rotation));
  if (auto p = node.find("root_position")) keyframe.root_position = p->as_vector3();
  return keyframe;
}

std::vector<Keyframe> parse_keyframes(const JsonNode& node, const BodyModel& model) {
  node.require_array();
  if (node.size() < 2)
    node.fail("at least 2 keyframes are required, found " + std::to_string(node.size()));
  std::vector<Keyframe> keyframes;
  keyframes.reserve(node.size());
  for (std::size_t i = 0; i < node.size(); ++i) {
    const JsonNode item = node.at(i);
    Keyframe keyframe = parse_keyframe(item, model);
    if (i == 0) {
      if (std::abs(keyframe.time) > kFirstTimeTolerance)
        item.at("time").fail("the first keyframe time must be 0, found " +
                             message_number(keyframe.time));
      keyframe.time = 0.0;  // exactly: downstream code relies on the flight starting at t = 0
    } else if (!(keyframe.time > keyframes.back().time)) {
      item.at("time").fail(
          "keyframe " + std::to_string(i) + " time " + message_number(keyframe.time) +
          " is not after keyframe " + std::to_string(i - 1) + " time " +
          message_number(keyframes.back().time) + " (times must strictly increase)");
    }
    keyframes.push_back(std::move(keyframe));
  }
  return keyframes;
}

/// Checks an array has the spline's control count (knots.size() - 4, bspline_basis.h).
void require_control_count(const JsonNode& node, std::size_t count) {
  node.require_array();
  if (node.size() != count)
    node.fail("expected " + std::to_string(count) + " control points (knots.size() - 4), found " +
              std::to_string(node.size()));
}

StoredSpline parse_spline(const JsonNode& node, const BodyModel& model) {
  node.require_object();
  reject_unknown_fields(node, {"knots", "root_translation", "joints"});
  StoredSpline spline;
  const JsonNode knots = node.at("knots");
  spline.knots = knots.as_double_array();
  if (spline.knots.size() < kMinSplineKnots)
    knots.fail("a cubic spline needs at least " + std::to_string(kMinSplineKnots) +
               " knots, found " + std::to_string(spline.knots.size()));
  for (std::size_t i = 1; i < spline.knots.size(); ++i) {
    if (spline.knots[i] < spline.knots[i - 1])
      knots.at(i).fail("knots must not decrease: " + message_number(spline.knots[i]) + " after " +
                       message_number(spline.knots[i - 1]));
  }
  const std::size_t count = spline.knots.size() - 4;

  const JsonNode translation = node.at("root_translation");
  require_control_count(translation, count);
  spline.root_translation.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
    spline.root_translation.push_back(translation.at(i).as_vector3());

  const std::vector<JsonNode> joints = joint_members(node.at("joints"), model);
  spline.joint_control.reserve(joints.size());
  for (const auto& joint : joints) {
    require_control_count(joint, count);
    std::vector<Eigen::Quaterniond> control;
    control.reserve(count);
    for (std::size_t i = 0; i < count; ++i)
      control.push_back(parse_wxyz(joint.at(i)));
    spline.joint_control.push_back(std::move(control));
  }
  return spline;
}

nlohmann::json vector_to_json(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

nlohmann::json quaternion_to_json(const Eigen::Quaterniond& q) {
  return {q.w(), q.x(), q.y(), q.z()};
}

/// Where resolve_model_path looks for `field`, for the "not found" message.
std::string model_search_description(const std::string& field, const std::string& motion_file) {
  std::string out = (fs::path(motion_file).parent_path() / field).string();
  const bool looks_like_path =
      field.find('/') != std::string::npos || fs::path(field).extension() == ".json";
  if (!looks_like_path) {
    for (const auto& dir : resource_directories())
      out += ", " + (fs::path(dir) / "models" / (field + ".json")).string();
  }
  return out;
}

}  // namespace

Motion parse_motion(const nlohmann::json& document, const std::string& file,
                    const BodyModel& model) {
  const JsonNode root(document, file);
  check_format_tag(root);
  Motion motion;
  motion.name = default_name(file);
  if (auto name = root.find("name")) motion.name = name->as_string();
  // Optional here so a caller that supplies the model (load_motion_file's override) may omit it.
  motion.model = model.name;
  if (auto field = root.find("model")) motion.model = field->as_string();
  motion.takeoff = parse_takeoff(root.at("takeoff"));
  if (auto tolerances = root.find("tolerances")) motion.tolerances = parse_tolerances(*tolerances);
  motion.keyframes = parse_keyframes(root.at("keyframes"), model);
  if (auto spline = root.find("spline")) motion.spline = parse_spline(*spline, model);
  return motion;
}

std::string read_motion_model_field(const nlohmann::json& document, const std::string& file) {
  const JsonNode root(document, file);
  check_format_tag(root);
  const JsonNode field = root.at("model");
  std::string model = field.as_string();
  if (model.empty()) field.fail("the model name is empty");
  return model;
}

MotionFile load_motion_file(const std::string& path, const std::string& model_override) {
  const nlohmann::json document = read_json_file(path);
  std::string model_path;
  std::string model_name;
  if (model_override.empty()) {
    model_name = read_motion_model_field(document, path);
    model_path = resolve_model_path(model_name, path);
    if (model_path.empty())
      throw InputError(path, "/model",
                       "model \"" + model_name + "\" not found (looked in " +
                           model_search_description(model_name, path) + ")");
  } else {
    // An override comes from the command line, so a path relative to the working directory is
    // what the user means; otherwise it resolves like the file's field.
    model_name = model_override;
    const bool is_file = fs::is_regular_file(model_override);
    model_path = is_file ? model_override : resolve_model_path(model_override, path);
    if (model_path.empty())
      throw InputError(path, "",
                       "model \"" + model_override + "\" (given instead of the file's) not found " +
                           "(looked in " + model_override + ", " +
                           model_search_description(model_override, path) + ")");
  }
  MotionFile result;
  result.path = path;
  result.model = load_body_model(model_path);
  result.motion = parse_motion(document, path, result.model);
  // The motion now refers to the model it was actually loaded with, so writing it back out
  // (e.g. optimized.motion.json) reproduces the run.
  result.motion.model = model_name;
  return result;
}

nlohmann::json motion_to_json(const Motion& motion, const BodyModel& model) {
  const std::size_t joints = model.segments.size();
  nlohmann::json out;
  out["format"] = kMotionFormat;
  out["name"] = motion.name;
  out["model"] = motion.model.empty() ? model.name : motion.model;

  nlohmann::json takeoff;
  takeoff["com_position"] = vector_to_json(motion.takeoff.com_position);
  takeoff["com_velocity"] = vector_to_json(motion.takeoff.com_velocity);
  if (motion.takeoff.angular_momentum)
    takeoff["angular_momentum"] = vector_to_json(*motion.takeoff.angular_momentum);
  out["takeoff"] = takeoff;

  out["tolerances"] = {{"translation_m", motion.tolerances.translation_m},
                       {"quaternion", motion.tolerances.quaternion}};

  nlohmann::json keyframes = nlohmann::json::array();
  for (std::size_t k = 0; k < motion.keyframes.size(); ++k) {
    const Keyframe& keyframe = motion.keyframes[k];
    if (keyframe.rotations.size() != joints)
      throw std::invalid_argument("motion_to_json: keyframe " + std::to_string(k) + " has " +
                                  std::to_string(keyframe.rotations.size()) +
                                  " rotations, model \"" + model.name + "\" has " +
                                  std::to_string(joints) + " joints");
    nlohmann::json item;
    item["time"] = keyframe.time;
    nlohmann::json rotations = nlohmann::json::object();
    for (std::size_t j = 0; j < joints; ++j)
      rotations[model.segments[j].joint] = quaternion_to_json(keyframe.rotations[j]);
    item["rotations"] = rotations;
    if (keyframe.root_position) item["root_position"] = vector_to_json(*keyframe.root_position);
    keyframes.push_back(item);
  }
  out["keyframes"] = keyframes;

  if (motion.spline) {
    const StoredSpline& spline = *motion.spline;
    if (spline.joint_control.size() != joints)
      throw std::invalid_argument(
          "motion_to_json: spline has " + std::to_string(spline.joint_control.size()) +
          " joint curves, model \"" + model.name + "\" has " + std::to_string(joints) + " joints");
    nlohmann::json stored;
    stored["knots"] = spline.knots;
    nlohmann::json translation = nlohmann::json::array();
    for (const auto& c : spline.root_translation)
      translation.push_back(vector_to_json(c));
    stored["root_translation"] = translation;
    nlohmann::json curves = nlohmann::json::object();
    for (std::size_t j = 0; j < joints; ++j) {
      nlohmann::json control = nlohmann::json::array();
      for (const auto& q : spline.joint_control[j])
        control.push_back(quaternion_to_json(q));
      curves[model.segments[j].joint] = control;
    }
    stored["joints"] = curves;
    out["spline"] = stored;
  }
  return out;
}

std::string motion_label(const std::string& path) {
  std::string stem = std::filesystem::path(path).filename().string();
  const std::string suffix = ".motion.json";
  if (stem.size() > suffix.size() &&
      stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0)
    stem.resize(stem.size() - suffix.size());
  if (stem.size() >= 2 && stem[0] == 'M' && std::isdigit(static_cast<unsigned char>(stem[1]))) {
    std::size_t end = 1;
    while (end < stem.size() && std::isdigit(static_cast<unsigned char>(stem[end])))
      ++end;
    return stem.substr(0, end);
  }
  return stem;
}

}  // namespace saltus
