#include "saltus/formats/motion_file.h"

#include "saltus/formats/output_folder.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/base/json_reader.h"
#include "saltus/base/resources.h"
#include "saltus/base/text_format.h"
#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/plausible_ranges.h"
#include "saltus/math/quaternion.h"
#include "saltus/math/quaternion_spline.h"

namespace saltus {

namespace {

namespace fs = std::filesystem;

constexpr const char* kMotionFormat = kMotionFormatTag;
/// docs/method.md, "Conventions": files may be off unit norm by rounding; worse than this is a
/// mistake, not noise.
constexpr double kQuaternionNormTolerance = 1e-3;
/// The first keyframe time must be 0; allow only printing noise so "0.0" and "1e-15" both work.
constexpr double kFirstTimeTolerance = 1e-12;
/// A cubic spline needs at least 4 control points, i.e. 8 knots.
constexpr std::size_t kMinSplineKnots = 8;

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
    node.require_keys_within({"euler_deg", "order"});
    const Eigen::Vector3d angles =
        node.at("euler_deg").as_vector3_within(plausible::kMaxEulerAngleDeg, "deg");
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
    if (model.joint_index(key) >= 0) continue;
    std::vector<std::string> joints;
    for (const auto& segment : model.segments)
      joints.push_back(segment.joint);
    const std::string suggestion = nearest_name(key, joints);
    child.fail("unknown joint \"" + printable(key) + "\"" +
               (suggestion.empty() ? std::string() : " (did you mean \"" + suggestion + "\"?)") +
               "; model \"" + model.name + "\" has joints: " + joint_list(model));
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
  node.require_keys_within({"com_position", "com_velocity", "angular_momentum"});
  Takeoff takeoff;
  takeoff.com_position = node.at("com_position").as_vector3_within(plausible::kMaxPosition, "m");
  const JsonNode velocity = node.at("com_velocity");
  takeoff.com_velocity = velocity.as_vector3_within(plausible::kMaxTakeoffSpeed, "m/s");
  if (!(takeoff.com_velocity.norm() <= plausible::kMaxTakeoffSpeed))
    velocity.fail("take-off speed " + message_number(takeoff.com_velocity.norm()) +
                  " m/s is beyond the plausible " + message_number(plausible::kMaxTakeoffSpeed) +
                  " m/s");
  // Checked against the body's inertia once the keyframes are read (check_angular_momentum).
  if (auto h = node.find("angular_momentum"))
    takeoff.angular_momentum = h->as_vector3_within(plausible::kMaxAngularMomentum, "kg·m²/s");
  return takeoff;
}

/// The whole body's inertia about its CoM (world frame, kg·m²) in the keyframe's pose.
Eigen::Matrix3d inertia_about_com(const BodyModel& model, const Keyframe& keyframe) {
  BodyState<double> state(model.size());
  for (int i = 0; i < model.size(); ++i)
    state.joints[static_cast<std::size_t>(i)].q = keyframe.rotations[static_cast<std::size_t>(i)];
  DynamicsData<double> data(model);
  inverse_dynamics(model, data, state);
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (int i = 0; i < model.size(); ++i) {
    const Segment& segment = model.segments[static_cast<std::size_t>(i)];
    const Eigen::Matrix3d& r = data.world_rotation[static_cast<std::size_t>(i)];
    const Eigen::Vector3d d =
        data.world_position[static_cast<std::size_t>(i)] + r * segment.com - data.com;
    inertia += r * segment.inertia * r.transpose() +
               segment.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  return inertia;
}

}  // namespace

void check_takeoff_spin(const Motion& motion, const BodyModel& model, const std::string& file,
                        const std::string& whose) {
  if (!motion.takeoff.angular_momentum || motion.keyframes.empty()) return;
  const Eigen::Vector3d omega = inertia_about_com(model, motion.keyframes.front())
                                    .ldlt()
                                    .solve(*motion.takeoff.angular_momentum);
  const double rate = omega.norm();
  if (!(rate <= plausible::kMaxBodyAngularVelocity))
    throw InputError(file, "/takeoff/angular_momentum",
                     whose + " turns the body (model \"" + model.name +
                         "\", first keyframe's pose) at " + message_number(rate) +
                         " rad/s, beyond the plausible " +
                         message_number(plausible::kMaxBodyAngularVelocity) + " rad/s");
}

namespace {

double parse_positive(const JsonNode& node, const std::string& what) {
  const double v = node.as_double();
  if (!(v > 0.0)) node.fail(what + " must be > 0, found " + message_number(v));
  return v;
}

Tolerances parse_tolerances(const JsonNode& node) {
  node.require_keys_within({"translation_m", "quaternion"});
  Tolerances tolerances;
  if (auto t = node.find("translation_m")) {
    tolerances.translation_m = parse_positive(*t, "translation_m");
    t->as_double_within(0.0, plausible::kMaxTranslationTolerance, "m");
  }
  if (auto q = node.find("quaternion")) {
    tolerances.quaternion = parse_positive(*q, "quaternion");
    q->as_double_within(0.0, plausible::kMaxQuaternionTolerance, "");
  }
  return tolerances;
}

Keyframe parse_keyframe(const JsonNode& node, const BodyModel& model) {
  node.require_keys_within({"time", "rotations", "root_position"});
  Keyframe keyframe;
  keyframe.time = node.at("time").as_double();
  const std::vector<JsonNode> rotations = joint_members(node.at("rotations"), model);
  keyframe.rotations.reserve(rotations.size());
  for (const auto& rotation : rotations)
    keyframe.rotations.push_back(parse_rotation(rotation));
  if (auto p = node.find("root_position"))
    keyframe.root_position = p->as_vector3_within(plausible::kMaxPosition, "m");
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
    } else if (!(keyframe.time - keyframes.back().time >=
                 plausible::kMinKeyframeGap - plausible::kKeyframeGapRounding)) {
      item.at("time").fail("keyframe " + std::to_string(i) + " is only " +
                           message_number(keyframe.time - keyframes.back().time) +
                           " s after keyframe " + std::to_string(i - 1) +
                           "; keyframes must be at least " +
                           message_number(plausible::kMinKeyframeGap) + " s apart");
    } else if (!(keyframe.time <= plausible::kMaxFlightTime)) {
      item.at("time").fail("keyframe time " + message_number(keyframe.time) +
                           " s is beyond the longest plausible flight, " +
                           message_number(plausible::kMaxFlightTime) + " s");
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

/// Knots of a stored spline: the clamped cubic layout of bspline_basis.h on [0, T] (T the last
/// keyframe time), breakpoints strictly increasing at least kMinKnotGap apart (less a rounding,
/// kKeyframeGapRounding).
void check_stored_knots(const JsonNode& knots, const std::vector<double>& k, double flight_time) {
  const std::size_t n = k.size() - 4;  // control points; breakpoints are k[3..n]
  const double slack = 1e-9 * std::max(1.0, flight_time);
  for (std::size_t i = 0; i < 4; ++i) {
    if (!(std::abs(k[i]) <= slack))
      knots.at(i).fail(
          "the first four knots must be 0 (the take-off; the spline is clamped), "
          "found " +
          message_number(k[i]));
    if (!(std::abs(k[n + i] - flight_time) <= slack))
      knots.at(n + i).fail("the last four knots must be the flight time " +
                           message_number(flight_time) +
                           " s (the last keyframe's time; the spline is clamped), found " +
                           message_number(k[n + i]));
  }
  for (std::size_t i = 4; i <= n; ++i) {
    if (!(k[i] - k[i - 1] >= plausible::kMinKnotGap - plausible::kKeyframeGapRounding))
      knots.at(i).fail("knot " + message_number(k[i]) + " is only " +
                       message_number(k[i] - k[i - 1]) + " s after the previous one " +
                       message_number(k[i - 1]) + "; interior knots must increase by at least " +
                       message_number(plausible::kMinKnotGap) + " s");
  }
}

/// 2‖log(a⁻¹b)‖: how far a cumulative spline turns from control a to control b (rad, [0, 2π]).
double control_turn(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const Eigen::Quaterniond relative = a.conjugate() * b;
  return 2.0 * std::atan2(relative.vec().norm(), relative.w());
}

/// The largest distance between the curve and its keyframes at the keyframe times in
/// [t0, t1], sign-aligned (‖q − q̄‖ for the nearer of ±q̄).
double keyframe_distance(const std::vector<double>& knots,
                         const std::vector<Eigen::Quaterniond>& control,
                         const std::vector<Keyframe>& keyframes, std::size_t segment, double t0,
                         double t1) {
  double largest = 0.0;
  for (const Keyframe& keyframe : keyframes) {
    if (keyframe.time < t0 || keyframe.time > t1) continue;
    const SpanBasis<double> basis = cubic_basis(knots, keyframe.time);
    const auto f = static_cast<std::size_t>(basis.first_control());
    const Eigen::Quaterniond q =
        evaluate_quaternion_span(control[f], control[f + 1], control[f + 2], control[f + 3], basis)
            .q;
    const Eigen::Quaterniond& target = keyframe.rotations[segment];
    const double sign = q.coeffs().dot(target.coeffs()) < 0.0 ? -1.0 : 1.0;
    largest = std::max(largest, (q.coeffs() - sign * target.coeffs()).norm());
  }
  return largest;
}

/// Sign consistency of one joint's stored control quaternions. q and −q are the same rotation
/// but not the same curve: the turn to a sign-flipped control goes the long way round, up to
/// the log map's branch point at 2π (where the curve's derivatives are NaN). The fit and the
/// optimiser take the long way only where the keyframes need it, so a control is refused when
/// (a) it turns more than kMaxStoredControlTurn from its predecessor, or (b) its negation would
/// turn the curve less in all and pass the keyframes it influences as closely: then the sign
/// serves no keyframe and only makes the joint spin.
void check_stored_joint_curve(const JsonNode& node, const std::vector<double>& knots,
                              const std::vector<Eigen::Quaterniond>& control,
                              const std::vector<Keyframe>& keyframes, std::size_t segment,
                              const std::string& joint) {
  const std::size_t n = control.size();
  std::vector<double> turn(n, 0.0);  // turn[i]: from control i − 1 to i
  for (std::size_t i = 1; i < n; ++i) {
    turn[i] = control_turn(control[i - 1], control[i]);
    if (!(turn[i] <= plausible::kMaxStoredControlTurn))
      node.at(i).fail("joint \"" + joint + "\" turns " +
                      message_number(turn[i] * kDegreesPerRadian) + "° from control " +
                      std::to_string(i - 1) + " to control " + std::to_string(i) +
                      " (a sign-flipped quaternion?); consecutive controls of a stored spline "
                      "turn at most " +
                      message_number(plausible::kMaxStoredControlTurn * kDegreesPerRadian) + "°");
  }
  constexpr double kTwoPi = 2.0 * kPi;
  for (std::size_t j = 0; j < n; ++j) {
    const double before = j > 0 ? turn[j] : 0.0;
    const double after = j + 1 < n ? turn[j + 1] : 0.0;
    const double flipped = (j > 0 ? kTwoPi - before : 0.0) + (j + 1 < n ? kTwoPi - after : 0.0);
    if (!(flipped < before + after)) continue;
    // Control j acts on the spans [knots[j], knots[j + 4]].
    const double t0 = knots[j];
    const double t1 = knots[j + 4];
    std::vector<Eigen::Quaterniond> negated = control;
    negated[j].coeffs() = -negated[j].coeffs();
    const double as_stored = keyframe_distance(knots, control, keyframes, segment, t0, t1);
    const double as_negated = keyframe_distance(knots, negated, keyframes, segment, t0, t1);
    if (as_negated <= as_stored + 1e-9)
      node.at(j).fail("control " + std::to_string(j) + " of joint \"" + joint +
                      "\" has the wrong sign: its negation (the same rotation) passes the "
                      "keyframes as closely and turns the curve " +
                      message_number((before + after - flipped) * kDegreesPerRadian) +
                      "° less; a stored spline's controls take the long way round only where "
                      "the keyframes need it");
  }
}

StoredSpline parse_spline(const JsonNode& node, const BodyModel& model,
                          const std::vector<Keyframe>& keyframes) {
  node.require_keys_within({"knots", "root_translation", "joints"});
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
  check_stored_knots(knots, spline.knots, keyframes.back().time);
  const std::size_t count = spline.knots.size() - 4;

  const JsonNode translation = node.at("root_translation");
  require_control_count(translation, count);
  spline.root_translation.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
    spline.root_translation.push_back(
        translation.at(i).as_vector3_within(plausible::kMaxTrajectoryPosition, "m"));

  const std::vector<JsonNode> joints = joint_members(node.at("joints"), model);
  spline.joint_control.reserve(joints.size());
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const JsonNode& joint = joints[j];
    require_control_count(joint, count);
    std::vector<Eigen::Quaterniond> control;
    control.reserve(count);
    for (std::size_t i = 0; i < count; ++i)
      control.push_back(parse_wxyz(joint.at(i)));
    check_stored_joint_curve(joint, spline.knots, control, keyframes, j, model.segments[j].joint);
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

/// Linux allows 255 bytes per path component; a longer model reference is a mistake.
constexpr std::size_t kMaxNameBytes = 255;
constexpr std::size_t kMaxModelReferenceBytes = 1024;

/// True when canonical path `p` is `folder` or inside it.
bool is_within(const fs::path& folder, const fs::path& p) {
  auto f = folder.begin();
  auto q = p.begin();
  for (; f != folder.end(); ++f, ++q) {
    if (f->empty()) continue;  // the trailing "" of "/a/b/"
    if (q == p.end() || *f != *q) return false;
  }
  return true;
}

/// The model file a motion file's "model" field names: a name under resources/models/, or a
/// relative path that stays inside the motion file's folder (symbolic links resolved). Motion
/// files travel between people, so one must not make Saltus read an arbitrary local file
/// ("../../../../etc/passwd"); any other model is given on the command line (--model) or in
/// the app (File > Open model).
std::string model_file_from_field(const JsonNode& field, const std::string& motion_file) {
  const std::string reference = field.as_string();
  if (reference.empty()) field.fail("the model name is empty");
  if (reference.size() > kMaxModelReferenceBytes)
    field.fail("the model reference is " + std::to_string(reference.size()) +
               " bytes long; at most " + std::to_string(kMaxModelReferenceBytes));
  if (reference.find('\0') != std::string::npos) field.fail("the model reference contains NUL");
  const fs::path relative(reference);
  for (const fs::path& part : relative)
    if (part.string().size() > kMaxNameBytes)
      field.fail("a name in the model reference is longer than " + std::to_string(kMaxNameBytes) +
                 " bytes");
  const fs::path folder = fs::path(motion_file).parent_path();
  const fs::path beside = folder / relative;
  std::error_code ec;
  const bool looks_like_path =
      reference.find('/') != std::string::npos || relative.extension() == ".json";
  if (looks_like_path || fs::exists(beside, ec)) {
    const std::string where =
        "; a motion file may name a model under resources/models/ or a file in its own folder "
        "or below it. To use another model, give it on the command line (--model PATH) or in "
        "the app (File > Open model)";
    if (relative.is_absolute())
      field.fail("the model path \"" + reference + "\" is absolute" + where);
    if (!fs::is_regular_file(beside, ec))
      field.fail("model \"" + reference + "\" not found (looked for " + beside.string() + ")");
    const fs::path canonical_folder = fs::canonical(folder.empty() ? fs::path(".") : folder, ec);
    const fs::path canonical_model = fs::canonical(beside, ec);
    if (ec || !is_within(canonical_folder, canonical_model))
      field.fail("model \"" + reference + "\" is " + canonical_model.string() +
                 ", outside the motion file's folder " + canonical_folder.string() + where);
    return beside.string();
  }
  for (const auto& dir : resource_directories()) {
    const fs::path candidate = fs::path(dir) / "models" / (reference + ".json");
    if (fs::is_regular_file(candidate, ec)) return candidate.string();
  }
  field.fail("model \"" + reference + "\" not found (looked in " +
             model_search_description(reference, motion_file) + ")");
}

}  // namespace

ModelReference model_reference_for(const std::string& model_file, const std::string& motion_file) {
  std::error_code ec;
  const fs::path model = fs::weakly_canonical(model_file, ec);
  for (const auto& dir : resource_directories()) {
    const fs::path bundled = fs::weakly_canonical(fs::path(dir) / "models", ec);
    if (!ec && model.parent_path() == bundled && model.extension() == ".json")
      return {model.stem().string(), true};
  }
  const fs::path parent = fs::path(motion_file).parent_path();
  const fs::path folder = fs::weakly_canonical(parent.empty() ? fs::path(".") : parent, ec);
  ModelReference reference;
  reference.field = model.lexically_relative(folder).string();
  if (reference.field.empty()) reference.field = model.string();
  reference.loads_by_itself = is_within(folder, model);
  return reference;
}

Motion parse_motion(const nlohmann::json& document, const std::string& file, const BodyModel& model,
                    SpinCheck spin) {
  // A motion file Saltus wrote on its own carries its mark (motion_file_kind()): read past it.
  if (has_json_mark(document)) return parse_motion(without_json_mark(document), file, model, spin);
  const JsonNode root(document, file);
  check_format_tag(root);
  root.require_keys_within(
      {"format", "name", "description", "model", "takeoff", "tolerances", "keyframes", "spline"});
  Motion motion;
  motion.name = default_name(file);
  if (auto name = root.find("name")) motion.name = name->as_string();
  if (auto description = root.find("description")) motion.description = description->as_string();
  // Optional here so a caller that supplies the model (load_motion_file's override) may omit it.
  motion.model = model.name;
  if (auto field = root.find("model")) motion.model = field->as_string();
  motion.takeoff = parse_takeoff(root.at("takeoff"));
  if (auto tolerances = root.find("tolerances")) motion.tolerances = parse_tolerances(*tolerances);
  motion.keyframes = parse_keyframes(root.at("keyframes"), model);
  // L = [1e4, 1e4, 1e4] made the free-flight simulation diverge.
  if (spin == SpinCheck::kOnLoad) check_takeoff_spin(motion, model, file, "this angular momentum");
  if (auto spline = root.find("spline"))
    motion.spline = parse_spline(*spline, model, motion.keyframes);
  return motion;
}

const FileKind& motion_file_kind() {
  static const FileKind kind = FileKind::json("motion");
  return kind;
}

void save_motion_file(const std::string& path, const Motion& motion, const BodyModel& model) {
  write_output_file(path, motion_to_json(motion, model).dump(2) + "\n", motion_file_kind());
}

std::string read_motion_model_field(const nlohmann::json& document, const std::string& file) {
  const JsonNode root(document, file);
  check_format_tag(root);
  const JsonNode field = root.at("model");
  std::string model = field.as_string();
  if (model.empty()) field.fail("the model name is empty");
  return model;
}

MotionFile load_motion_file(const std::string& path, const std::string& model_override,
                            SpinCheck spin) {
  const nlohmann::json document = read_json_file(path);
  std::string model_path;
  std::string model_name;
  if (model_override.empty()) {
    model_name = read_motion_model_field(document, path);
    model_path = model_file_from_field(JsonNode(document, path).at("model"), path);
  } else {
    // An override comes from the command line, so a path relative to the working directory is
    // what the user means; otherwise it resolves like the file's field.
    model_name = model_override;
    if (model_override.size() > kMaxModelReferenceBytes)
      throw InputError(model_override.substr(0, 64) + "…", "",
                       "--model: the model path is too long");
    std::error_code ec;
    const bool exists = fs::exists(model_override, ec);  // the reader says if it is no file
    model_path = exists ? model_override : resolve_model_path(model_override, path);
    if (model_path.empty())
      throw InputError(path, "",
                       "model \"" + model_override + "\" (given instead of the file's) not found " +
                           "(looked in " + model_override + ", " +
                           model_search_description(model_override, path) + ")");
  }
  MotionFile result;
  result.path = path;
  result.model = load_body_model(model_path);
  result.motion = parse_motion(document, path, result.model, spin);
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
  if (!motion.description.empty()) out["description"] = motion.description;
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
