#include "saltus/formats/model_file.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <unordered_map>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/base/text_format.h"
#include "saltus/body/joint_strength.h"
#include "saltus/formats/output_folder.h"
#include "saltus/formats/plausible_ranges.h"

namespace saltus {

namespace {

constexpr const char* kModelFormat = kModelFormatTag;
constexpr const char* kRootJoint = "root";

std::string in_quotes(const std::string& text) {
  return "\"" + text + "\"";
}

/// Segment names, by position, read leniently before validation proper, so that a parent named
/// later in the list can be reported as an ordering error instead of an unknown name.
std::vector<std::string> peek_segment_names(const nlohmann::json& segments) {
  std::vector<std::string> names;
  for (const auto& s : segments) {
    const bool has_name = s.is_object() && s.contains("name") && s["name"].is_string();
    names.push_back(has_name ? s["name"].get<std::string>() : std::string());
  }
  return names;
}

/// Checks principal moments (ascending or not) of a segment of `mass` kg: each one's radius of
/// gyration sqrt(I/m) plausible, and the triangle inequality Ia + Ib >= Ic that every rigid
/// body's principal moments obey (Ix + Iy = Σ m(x² + y²) + ... >= Σ m(x² + y²) = Iz, equality for
/// a flat body).
void check_principal_moments(const JsonNode& node, const Eigen::Vector3d& moments, double mass) {
  for (Eigen::Index k = 0; k < 3; ++k) {
    const double gyration = std::sqrt(moments[k] / mass);
    if (!(gyration >= plausible::kMinRadiusOfGyration &&
          gyration <= plausible::kMaxRadiusOfGyration))
      node.fail("principal moment " + message_number(moments[k]) + " kg·m² of a " +
                message_number(mass) + " kg segment means a radius of gyration of " +
                message_number(gyration) + " m, outside the plausible [" +
                message_number(plausible::kMinRadiusOfGyration) + ", " +
                message_number(plausible::kMaxRadiusOfGyration) + "] m");
  }
  for (Eigen::Index k = 0; k < 3; ++k) {
    const double a = moments[(k + 1) % 3];
    const double b = moments[(k + 2) % 3];
    const double c = moments[k];
    if (a + b < c * (1.0 - plausible::kInertiaTriangleSlack))
      node.fail("principal moments " + message_number(moments[0]) + ", " +
                message_number(moments[1]) + ", " + message_number(moments[2]) +
                " kg·m² violate the triangle inequality (" + message_number(a) + " + " +
                message_number(b) + " < " + message_number(c) +
                "): no rigid body has them; each moment must be at most the sum of the other two");
  }
}

/// Inertia about the CoM in segment axes. Three values are principal moments along the segment
/// axes; six are the matrix entries [Ixx, Iyy, Izz, Ixy, Ixz, Iyz] (I(0,1) = Ixy, i.e. the
/// tensor's off-diagonal entries themselves, not the negated products of inertia).
Eigen::Matrix3d parse_inertia(const JsonNode& node, double mass) {
  node.require_array();
  const std::size_t n = node.size();
  if (n == 3) {
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    for (std::size_t k = 0; k < 3; ++k) {
      const JsonNode element = node.at(k);
      const double moment = element.as_double();
      if (!(moment > 0.0))
        element.fail("principal moment of inertia must be positive, found " +
                     message_number(moment));
      inertia(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k)) = moment;
    }
    check_principal_moments(node, inertia.diagonal(), mass);
    return inertia;
  }
  if (n == 6) {
    const std::vector<double> v = node.as_doubles(6);
    Eigen::Matrix3d inertia;
    inertia << v[0], v[3], v[4],  //
        v[3], v[1], v[5],         //
        v[4], v[5], v[2];
    // Scale first: entries of 1e308 would overflow inside the eigensolver.
    const double scale = inertia.cwiseAbs().maxCoeff();
    if (!(scale > 0.0)) node.fail("inertia is zero");
    if (!(std::sqrt(scale / mass) <= plausible::kMaxRadiusOfGyration))
      node.fail("inertia entry " + message_number(scale) + " kg·m² of a " + message_number(mass) +
                " kg segment is implausibly large (radius of gyration " +
                message_number(std::sqrt(scale / mass)) + " m)");
    // LLT fails on indefinite and semi-definite matrices alike; the smallest eigenvalue tells
    // the user how far off the numbers are.
    const Eigen::LLT<Eigen::Matrix3d> llt(inertia);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia, Eigen::EigenvaluesOnly);
    const double smallest = eigen.eigenvalues()(0);
    if (llt.info() != Eigen::Success || !(smallest > 0.0))
      node.fail("inertia is not positive definite (smallest eigenvalue " +
                message_number(smallest) + ")");
    check_principal_moments(node, eigen.eigenvalues(), mass);
    return inertia;
  }
  node.fail("inertia must have 3 principal moments or 6 values [Ixx, Iyy, Izz, Ixy, Ixz, Iyz], " +
            std::string("found ") + std::to_string(n) + " values");
}

/// One entry of "parts": {"name", "type": "ellipsoid", "center", "radii"} or {"name", "type":
/// "capsule", "center", "length", "radius"}.
ShapePart parse_shape_part(const JsonNode& node) {
  const JsonNode type = node.at("type");
  const std::string kind = type.as_string();
  if (kind == "ellipsoid")
    node.require_keys_within({"name", "type", "center", "radii"});
  else if (kind == "capsule")
    node.require_keys_within({"name", "type", "center", "length", "radius"});
  ShapePart part;
  if (const auto name = node.find("name")) part.name = name->as_string();
  part.type = kind;
  part.center = node.at("center").as_vector3_within(plausible::kMaxSegmentLength, "m");
  if (part.type == "ellipsoid") {
    const JsonNode radii = node.at("radii");
    part.radii = radii.as_vector3();
    if (!(part.radii.minCoeff() > 0.0))
      radii.fail("ellipsoid radii must be positive, found " +
                 message_number(part.radii.minCoeff()));
    radii.as_vector3_within(plausible::kMaxSegmentLength, "m");
  } else if (part.type == "capsule") {
    // Signed, as a segment shape's length.
    part.length = node.at("length").as_double_within(-plausible::kMaxSegmentLength,
                                                     plausible::kMaxSegmentLength, "m");
    const JsonNode radius = node.at("radius");
    part.radius = radius.as_double();
    if (!(part.radius > 0.0))
      radius.fail("capsule radius must be positive, found " + message_number(part.radius));
    radius.as_double_within(0.0, plausible::kMaxSegmentLength, "m");
  } else {
    type.fail("part type must be \"ellipsoid\" or \"capsule\", found " + in_quotes(part.type));
  }
  return part;
}

SegmentShape parse_shape(const JsonNode& node) {
  node.require_keys_within({"type", "length", "radius", "parts"});
  SegmentShape shape;
  const JsonNode type = node.at("type");
  shape.type = type.as_string();
  if (shape.type != "capsule" && shape.type != "ellipsoid" && shape.type != "box")
    type.fail("shape type must be \"capsule\", \"ellipsoid\" or \"box\", found " +
              in_quotes(shape.type));
  // Signed: a negative length draws the shape along -y.
  shape.length = node.at("length").as_double_within(-plausible::kMaxSegmentLength,
                                                    plausible::kMaxSegmentLength, "m");
  const JsonNode radius = node.at("radius");
  shape.radius = radius.as_double();
  if (shape.radius < 0.0)
    radius.fail("shape radius must not be negative, found " + message_number(shape.radius));
  radius.as_double_within(0.0, plausible::kMaxSegmentLength, "m");
  if (const auto parts = node.find("parts")) {
    parts->require_array();
    for (std::size_t i = 0; i < parts->size(); ++i)
      shape.parts.push_back(parse_shape_part(parts->at(i)));
  }
  return shape;
}

/// Resolves and checks the "parent" field of segment `index`; returns the parent's index.
int parse_parent(const JsonNode& node, std::size_t index, const std::string& name,
                 const std::vector<std::string>& all_names) {
  if (index == 0) {
    if (!node.is_null()) {
      const std::string found = node.value().is_string()
                                    ? in_quotes(node.value().get<std::string>())
                                    : node.value().type_name();
      node.fail("the first segment must be the root: its parent must be null, found " + found);
    }
    return -1;
  }
  if (node.is_null())
    node.fail("only the first segment may be the root (parent null); segment " + in_quotes(name) +
              " needs a parent listed before it");
  const std::string parent = node.as_string();
  if (parent == name) node.fail("segment " + in_quotes(name) + " cannot be its own parent");
  for (std::size_t j = 0; j < index; ++j)
    if (all_names[j] == parent) return static_cast<int>(j);
  for (std::size_t j = index + 1; j < all_names.size(); ++j)
    if (all_names[j] == parent)
      node.fail(
          "parent " + in_quotes(parent) + " is listed after segment " + in_quotes(name) +
          " (at /segments/" + std::to_string(j) +
          "): segments must be in topological order, parent first, which also rules out cycles");
  node.fail("unknown parent " + in_quotes(parent) + ": no segment has this name");
}

/// The model's "strength" (docs/formats.md, "Body model"): whose strength and what was measured,
/// checked against the model's joints by building it (athlete_strength).
StrengthSpec parse_strength(const JsonNode& node, const BodyModel& model) {
  node.require_object();
  node.require_keys_within({"reference", "sex", "age_years", "measured"});
  StrengthSpec spec;
  if (const auto reference = node.find("reference")) {
    spec.reference = reference->as_string();
    if (spec.reference != "population" && spec.reference != "elite-gymnast")
      reference->fail("unknown strength reference " + in_quotes(spec.reference) +
                      " (population, elite-gymnast)");
  }
  if (const auto sex = node.find("sex")) {
    const std::string text = sex->as_string();
    if (text != "male" && text != "female")
      sex->fail("sex must be \"male\" or \"female\", found " + in_quotes(text));
    spec.female = text == "female";
  }
  if (const auto age = node.find("age_years"))
    spec.age_years =
        age->as_double_within(plausible::kMinAgeYears, plausible::kMaxAgeYears, "years");
  if (const auto measured = node.find("measured")) {
    measured->require_array();
    for (std::size_t i = 0; i < measured->size(); ++i) {
      const JsonNode entry = measured->at(i);
      entry.require_keys_within({"joint", "direction", "peak_moment_Nm"});
      StrengthSpec::Measured m;
      m.joint = entry.at("joint").as_string();
      m.direction = entry.at("direction").as_string();
      m.peak_moment_Nm =
          entry.at("peak_moment_Nm")
              .as_double_within(plausible::kMinJointMomentNm, plausible::kMaxJointMomentNm, "N·m");
      spec.measured.push_back(m);
      BodyModel with = model;
      with.strength = spec;
      try {
        athlete_strength(with);
      } catch (const std::invalid_argument& e) {
        entry.fail(e.what());
      }
    }
  }
  return spec;
}

nlohmann::json strength_to_json(const StrengthSpec& spec) {
  nlohmann::json out = {{"reference", spec.reference},
                        {"sex", spec.female ? "female" : "male"},
                        {"age_years", spec.age_years}};
  if (!spec.measured.empty()) {
    nlohmann::json measured = nlohmann::json::array();
    for (const StrengthSpec::Measured& m : spec.measured)
      measured.push_back(
          {{"joint", m.joint}, {"direction", m.direction}, {"peak_moment_Nm", m.peak_moment_Nm}});
    out["measured"] = std::move(measured);
  }
  return out;
}

}  // namespace

BodyModel parse_body_model(const nlohmann::json& document, const std::string& file) {
  // A model file Saltus wrote on its own carries its mark (model_file_kind()): read past it.
  if (has_json_mark(document)) return parse_body_model(without_json_mark(document), file);
  const JsonNode root(document, file);
  root.require_object();

  const JsonNode format = root.at("format");
  if (format.as_string() != kModelFormat)
    format.fail("unsupported format " + in_quotes(format.as_string()) + ", expected " +
                in_quotes(kModelFormat));
  root.require_keys_within({"format", "name", "source", "segments", "strength"});

  BodyModel model;
  model.name = root.at("name").as_string();
  if (const auto source = root.find("source")) model.source = source->as_string();

  const JsonNode segments = root.at("segments");
  segments.require_array();
  if (segments.size() == 0) segments.fail("segments must be a non-empty array");
  if (segments.size() > plausible::kMaxSegments)
    segments.fail(std::to_string(segments.size()) + " segments; a body model has at most " +
                  std::to_string(plausible::kMaxSegments));

  const std::vector<std::string> all_names = peek_segment_names(segments.value());
  std::unordered_map<std::string, std::size_t> segment_of_name;
  std::unordered_map<std::string, std::size_t> segment_of_joint;

  for (std::size_t i = 0; i < segments.size(); ++i) {
    const JsonNode node = segments.at(i);
    node.require_keys_within(
        {"name", "parent", "joint", "joint_position", "mass", "com", "inertia", "shape"});
    Segment segment;

    const JsonNode name = node.at("name");
    segment.name = name.as_string();
    if (segment.name.empty()) name.fail("segment name must not be empty");
    if (const auto it = segment_of_name.find(segment.name); it != segment_of_name.end())
      name.fail("duplicate segment name " + in_quotes(segment.name) + " (also segment " +
                std::to_string(it->second) + ")");
    segment_of_name.emplace(segment.name, i);

    segment.parent = parse_parent(node.at("parent"), i, segment.name, all_names);

    const JsonNode joint = node.at("joint");
    segment.joint = joint.as_string();
    if (segment.joint.empty()) joint.fail("joint name must not be empty");
    if (i == 0 && segment.joint != kRootJoint)
      joint.fail("the root segment's joint must be named \"root\", found " +
                 in_quotes(segment.joint));
    if (i > 0 && segment.joint == kRootJoint)
      joint.fail("joint name \"root\" is reserved for the root segment (the first)");
    if (const auto it = segment_of_joint.find(segment.joint); it != segment_of_joint.end())
      joint.fail("duplicate joint name " + in_quotes(segment.joint) + " (also segment " +
                 std::to_string(it->second) + ")");
    segment_of_joint.emplace(segment.joint, i);

    // The root's placement is a motion variable, so its joint_position may be left out.
    if (i == 0) {
      if (const auto position = node.find("joint_position"))
        segment.joint_position = position->as_vector3_within(plausible::kMaxSegmentLength, "m");
    } else {
      segment.joint_position =
          node.at("joint_position").as_vector3_within(plausible::kMaxSegmentLength, "m");
    }

    const JsonNode mass = node.at("mass");
    segment.mass = mass.as_double();
    if (!(segment.mass > 0.0))
      mass.fail("mass must be positive, found " + message_number(segment.mass));
    mass.as_double_within(plausible::kMinSegmentMass, plausible::kMaxSegmentMass, "kg");

    segment.com = node.at("com").as_vector3_within(plausible::kMaxSegmentLength, "m");
    segment.inertia = parse_inertia(node.at("inertia"), segment.mass);
    if (const auto shape = node.find("shape")) segment.shape = parse_shape(*shape);

    model.segments.push_back(std::move(segment));
  }
  if (const auto strength = root.find("strength"))
    model.strength = parse_strength(*strength, model);
  return model;
}

BodyModel load_body_model(const std::string& path) {
  return parse_body_model(read_json_file(path), path);
}

nlohmann::json body_model_to_json(const BodyModel& model) {
  auto vector3 = [](const Eigen::Vector3d& v) {
    return nlohmann::json::array({v.x(), v.y(), v.z()});
  };
  auto shape_json = [&vector3](const SegmentShape& shape) {
    nlohmann::json out = {{"type", shape.type}, {"length", shape.length}, {"radius", shape.radius}};
    if (shape.parts.empty()) return out;  // files without parts stay as they were
    nlohmann::json parts = nlohmann::json::array();
    for (const ShapePart& p : shape.parts) {
      nlohmann::json part = {{"name", p.name}, {"type", p.type}, {"center", vector3(p.center)}};
      if (p.type == "capsule") {
        part["length"] = p.length;
        part["radius"] = p.radius;
      } else {
        part["radii"] = vector3(p.radii);
      }
      parts.push_back(std::move(part));
    }
    out["parts"] = std::move(parts);
    return out;
  };
  nlohmann::json segments = nlohmann::json::array();
  for (const Segment& s : model.segments) {
    nlohmann::json parent = nullptr;
    if (s.parent >= 0) parent = model.segments.at(static_cast<std::size_t>(s.parent)).name;
    const Eigen::Matrix3d& I = s.inertia;
    segments.push_back({
        {"name", s.name},
        {"parent", parent},
        {"joint", s.joint},
        {"joint_position", vector3(s.joint_position)},
        {"mass", s.mass},
        {"com", vector3(s.com)},
        {"inertia", {I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)}},
        {"shape", shape_json(s.shape)},
    });
  }
  return {{"format", kModelFormat},
          {"name", model.name},
          {"source", model.source},
          {"segments", std::move(segments)},
          {"strength", strength_to_json(model.strength)}};
}

const FileKind& model_file_kind() {
  static const FileKind kind = FileKind::json("body model");
  return kind;
}

void save_body_model_file(const std::string& path, const BodyModel& model) {
  write_output_file(path, body_model_to_json(model).dump(2) + "\n", model_file_kind());
}

nlohmann::json model_summary_to_json(const ModelSummary& summary) {
  auto vector3 = [](const Eigen::Vector3d& v) {
    return nlohmann::json::array({v.x(), v.y(), v.z()});
  };
  nlohmann::json segments = nlohmann::json::array();
  for (const SegmentSummary& s : summary.segments)
    segments.push_back({{"name", s.name},
                        {"label", s.label},
                        {"mass_kg", s.mass},
                        {"mass_percent", s.mass_percent},
                        {"length_m", s.length},
                        {"com_m", vector3(s.com)},
                        {"principal_moments_kgm2", vector3(s.principal_moments)}});
  const StandingBody& b = summary.standing;
  const Eigen::Matrix3d& I = b.body.inertia;
  return {{"format", "saltus-model-info/1"},
          {"name", summary.name},
          {"source", summary.source},
          {"total_mass_kg", summary.total_mass},
          {"standing_height_m", b.height()},
          {"com_m", vector3(b.body.com)},
          {"com_height_m", b.com_height()},
          {"com_height_percent", 100.0 * b.com_height() / b.height()},
          {"inertia_kgm2", {I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)}},
          {"principal_moments_kgm2", vector3(b.principal_moments)},
          {"segments", std::move(segments)}};
}

}  // namespace saltus
