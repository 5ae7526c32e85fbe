#include "saltus/formats/result_json.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <variant>

#include "saltus/base/constants.h"
#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/base/text_format.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/formats/finite_check.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/output_folder.h"
#include "saltus/formats/trajectory_csv.h"

namespace saltus {

namespace {

/// The keys of a before/after block (docs/formats.md) and the figures they hold.
const std::pair<const char*, double ForceMetrics::*> kForceMetricKeys[6] = {
    {"objective", &ForceMetrics::objective},     {"avg_root_force", &ForceMetrics::avg_root_force},
    {"rms_force_N", &ForceMetrics::rms_force_N}, {"rms_moment_Nm", &ForceMetrics::rms_moment_Nm},
    {"max_force_N", &ForceMetrics::max_force_N}, {"max_moment_Nm", &ForceMetrics::max_moment_Nm}};

}  // namespace

nlohmann::json force_metrics_to_json(const ForceMetrics& m) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [key, field] : kForceMetricKeys)
    j[key] = m.*field;
  return j;
}

namespace {

nlohmann::json vector_json(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

/// The body weight and every joint's peak load (the root left out) from the dense checks.
void set_joint_loads(ResultJson& r, const BodyModel& model, const DenseCheck& before,
                     const DenseCheck* after) {
  r.body_weight_N = body_weight_N(model);
  for (int k = 1; k < model.size(); ++k) {
    if (k >= static_cast<int>(before.joint_peaks.size())) break;
    ResultJson::JointLoad l;
    l.joint = model.segments[k].joint;
    l.before = before.joint_peaks[k];
    if (after && k < static_cast<int>(after->joint_peaks.size())) l.after = after->joint_peaks[k];
    r.joint_loads.push_back(std::move(l));
  }
  const AthleteStrength strength = athlete_strength(model);
  auto entries = [&](const DenseCheck& check) {
    std::vector<ResultJson::JointStrength> out;
    for (int k = 1; k < model.size() && k < static_cast<int>(check.strength_peaks.size()); ++k) {
      const JointStrengthPeak& p = check.strength_peaks[k];
      if (p.coordinate < 0) continue;
      const JointCoordinate& c = strength.coordinates[k].coordinates[p.coordinate];
      const StrengthCurve& curve = p.positive ? *strength.joints[k][p.coordinate].positive
                                              : *strength.joints[k][p.coordinate].negative;
      out.push_back({model.segments[k].joint, c.name, p.positive ? c.positive : c.negative,
                     strength_direction_words(model, k, p), p.share, p.time_s, p.moment_Nm,
                     p.capacity_Nm, p.angle_rad * 180.0 / 3.14159265358979323846,
                     p.shortening_speed, p.extrapolated, curve.source});
    }
    return out;
  };
  r.strength_reference = strength_reference_words(model.strength);
  r.strength_before = entries(before);
  r.strength_verdict_before = strength_verdict_words(model, before.strength_peaks);
  if (after) {
    r.strength_after = entries(*after);
    r.strength_verdict_after = strength_verdict_words(model, after->strength_peaks);
  }
}

/// The closest pass to the apparatus and a dive's entry, from the flight's samples.
void set_clearance(ResultJson& r, const MotionFile& file,
                   const std::vector<SampleRecord>& samples) {
  const Apparatus apparatus = apparatus_for(file.model, file.motion.takeoff, samples);
  r.clearance = apparatus_clearance(file.model, apparatus, samples);
  r.clearance->times.clear();
  r.clearance->distance.clear();
  r.entry = dive_entry(file.model, apparatus, samples);
}

/// The fields every result shares.
ResultJson common_result(const MotionFile& file, ResultJson::Kind kind, const std::string& status,
                         int knots_per_interval) {
  ResultJson r;
  r.kind = kind;
  r.status = status;
  r.motion = file.motion.name;
  r.motion_file = file.path;
  r.model = file.model.name;
  r.knots_per_interval = knots_per_interval;
  r.flight_time_s = file.motion.flight_time();
  r.keyframes = static_cast<int>(file.motion.keyframes.size());
  r.takeoff_adaptation = file.takeoff_adaptation;
  return r;
}

/// The same for an evaluation or a simulation, with the options it records.
ResultJson common_result(const MotionFile& file, ResultJson::Kind kind, const std::string& status,
                         const EvaluateOptions& options) {
  ResultJson r = common_result(file, kind, status, options.interpolation.knots_per_interval);
  r.options = recorded_options(with_evaluation_options(options), false);
  return r;
}

/// How the reported residual figures were computed (docs/formats.md).
ResultJson::ResidualCheck residual_check(const DenseCheck& check,
                                         const std::vector<double>& keyframe_times) {
  ResultJson::ResidualCheck c;
  c.rule = "Simpson's rule on every knot span, " + std::to_string(kCheckPointsPerSpan) +
           " or more intervals per span, " + format_number("%g", kCheckMaxSpacing) +
           " s apart or closer, and at least the samples over the flight; every spacing halved "
           "until the objective changes by at most " +
           format_number("%g", 100 * kCheckRelativeChange) + " % (" +
           std::to_string(kCheckMaxHalvings) + " halvings at most)";
  c.points = check.points;
  c.halvings = check.halvings;
  c.converged = check.converged;
  c.share_by_keyframe_interval = residual_shares(check, keyframe_times);
  return c;
}

/// A before/after block with the optimiser's own objective beside the dense check's figures.
nlohmann::json metrics_json(const ForceMetrics& metrics, const std::optional<double>& optimizer) {
  nlohmann::json j = force_metrics_to_json(metrics);
  if (optimizer) {
    j["optimizer_objective"] = *optimizer;
    j["optimizer_avg_root_force"] = std::sqrt(*optimizer / 6.0);
  }
  return j;
}

nlohmann::json resolution_json(const ResultJson::Optimization::Resolution& resolution) {
  nlohmann::json levels = nlohmann::json::array();
  for (const OptimizationResult::Level& level : resolution.levels)
    levels.push_back({{"subdivisions", level.subdivisions},
                      {"avg_root_force", level.avg_root_force},
                      {"landing_drift_deg", level.landing_drift_deg},
                      {"iterations", level.iterations},
                      {"status", level.status},
                      {"root_moment_weight", level.root_moment_weight}});
  nlohmann::json j = {{"automatic", resolution.automatic},
                      {"subdivisions", resolution.subdivisions},
                      {"knots", resolution.knots},
                      {"levels", levels}};
  if (resolution.landing_drift_deg) j["landing_drift_deg"] = *resolution.landing_drift_deg;
  j["twist_guided_intervals"] = resolution.twist_guided_intervals;
  if (const auto& p = resolution.joint_load_polish) {
    j["joint_load_polish"] = {{"weight", p->weight},
                              {"root_moment_weight", p->root_moment_weight},
                              {"joint_bound", p->joint_bound},
                              {"attempts", p->attempts},
                              {"bounded_tries_skipped", p->bounded_tries_skipped},
                              {"avg_root_force_before", p->avg_root_force_before},
                              {"avg_root_force_after", p->avg_root_force_after},
                              {"landing_drift_before_deg", p->landing_drift_before_deg},
                              {"landing_drift_after_deg", p->landing_drift_after_deg},
                              {"joint_rise_before", p->joint_rise_before},
                              {"bounds_tightened", p->bounds_tightened},
                              {"knots_refined", p->knots_refined},
                              {"iterations", p->iterations},
                              {"status", p->status},
                              {"kept", p->kept}};
    if (const auto& b = p->bounded_alternative)
      j["joint_load_polish"]["bounded_alternative"] = {{"landing_drift_deg", b->landing_drift_deg},
                                                       {"avg_root_force", b->avg_root_force},
                                                       {"joint_rise", b->joint_rise}};
  }
  return j;
}

}  // namespace

nlohmann::json joint_peak_json(const JointLoadPeak& p, double body_weight) {
  return {{"peak_force_N", p.force_N},
          {"peak_force_pct_bw", 100.0 * p.force_N / body_weight},
          {"peak_force_time_s", p.force_time_s},
          {"peak_moment_Nm", p.moment_Nm},
          {"peak_moment_time_s", p.moment_time_s}};
}

nlohmann::json rotation_json(const YeadonSummary& s) {
  return {{"somersaults", s.somersaults},
          {"twists", s.twists},
          {"description", s.description},
          {"max_tilt_deg", s.max_tilt_deg},
          {"peak_twist_rate_rev_s", s.peak_twist_rate_rev_s},
          {"peak_twist_rate_time_s", s.peak_twist_rate_time_s}};
}

namespace {

/// "clearance": the edge and height keys name what they measure on each apparatus.
nlohmann::json clearance_json(const ApparatusClearance& c) {
  const bool platform = c.kind == ApparatusKind::kPlatform;
  nlohmann::json j = {{"apparatus", platform ? "platform" : "trampoline"},
                      {"from_s", c.from_s},
                      {"min_distance_m", c.min_distance_m},
                      {"time_s", c.time_s},
                      {"segment", c.segment},
                      {"segment_end", c.segment_end},
                      {"point", c.point},
                      {"collision", c.collision}};
  if (platform) {
    j["behind_edge_m"] = c.edge_m;
    j["below_top_m"] = c.vertical_m;
  } else {
    j["inside_bed_edge_m"] = c.edge_m;
    j["above_frame_m"] = c.vertical_m;
  }
  return j;
}

nlohmann::json entry_json(const DiveEntry& e) {
  return {{"time_s", e.time_s},
          {"first_contact", e.first_contact},
          {"com_height_m", e.com_height_m},
          {"angle_to_vertical_deg", e.angle_to_vertical_deg},
          {"head_first", e.head_first},
          {"vertical", e.vertical}};
}

YeadonSummary read_rotation(const JsonNode& node) {
  node.require_object();
  YeadonSummary s;
  s.somersaults = node.at("somersaults").as_double();
  s.twists = node.at("twists").as_double();
  s.description = node.at("description").as_string();
  s.max_tilt_deg = node.at("max_tilt_deg").as_double();
  s.peak_twist_rate_rev_s = node.at("peak_twist_rate_rev_s").as_double();
  s.peak_twist_rate_time_s = node.at("peak_twist_rate_time_s").as_double();
  return s;
}

bool read_bool(const JsonNode& node) {
  if (!node.value().is_boolean()) node.fail("expected true or false");
  return node.value().get<bool>();
}

ApparatusClearance read_clearance(const JsonNode& node) {
  node.require_object();
  ApparatusClearance c;
  const JsonNode apparatus = node.at("apparatus");
  const std::string kind = apparatus.as_string();
  if (kind != "platform" && kind != "trampoline")
    apparatus.fail("expected \"platform\" or \"trampoline\", found \"" + kind + "\"");
  const bool platform = kind == "platform";
  c.kind = platform ? ApparatusKind::kPlatform : ApparatusKind::kTrampoline;
  c.from_s = node.at("from_s").as_double();
  c.min_distance_m = node.at("min_distance_m").as_double();
  c.time_s = node.at("time_s").as_double();
  c.segment = node.at("segment").as_string();
  c.segment_end = read_bool(node.at("segment_end"));
  c.point = node.at("point").as_string();
  c.collision = read_bool(node.at("collision"));
  c.edge_m = node.at(platform ? "behind_edge_m" : "inside_bed_edge_m").as_double();
  c.vertical_m = node.at(platform ? "below_top_m" : "above_frame_m").as_double();
  return c;
}

DiveEntry read_entry(const JsonNode& node) {
  node.require_object();
  DiveEntry e;
  e.time_s = node.at("time_s").as_double();
  e.first_contact = node.at("first_contact").as_string();
  e.com_height_m = node.at("com_height_m").as_double();
  e.angle_to_vertical_deg = node.at("angle_to_vertical_deg").as_double();
  e.head_first = read_bool(node.at("head_first"));
  e.vertical = read_bool(node.at("vertical"));
  return e;
}

ForceMetrics read_force_metrics(const JsonNode& node) {
  node.require_object();
  ForceMetrics m;
  for (const auto& [key, field] : kForceMetricKeys)
    m.*field = node.at(key).as_double();
  return m;
}

/// The JSON value of a recorded option, as the option's kind reads it.
OptionValue read_option(const OptionSpec& spec, const JsonNode& node) {
  const nlohmann::json& v = node.value();
  OptionValue value;
  if (spec.kind == OptionKind::kSwitch)
    value = read_bool(node);
  else if (v.is_string())
    value = v.get<std::string>();
  else if (spec.kind == OptionKind::kInteger)
    value = node.as_int();
  else if (spec.kind == OptionKind::kReal)
    value = node.as_double();
  else
    node.fail("expected one of " + option_range_text(spec));
  try {
    return checked_option_value(spec, value);
  } catch (const OptionValueError& e) {
    node.fail(e.problem());
  }
}

/// An array of whole numbers, each at least `min` ("subdivisions": spans per interval).
std::vector<int> read_int_array(const JsonNode& node, int min) {
  node.require_array();
  std::vector<int> out;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const JsonNode item = node.at(i);
    out.push_back(item.as_int());
    if (out.back() < min) item.fail("expected a whole number of at least " + std::to_string(min));
  }
  return out;
}

ResultJson::Optimization::Resolution read_resolution(const JsonNode& node) {
  node.require_object();
  ResultJson::Optimization::Resolution r;
  r.automatic = read_bool(node.at("automatic"));
  r.subdivisions = read_int_array(node.at("subdivisions"), 1);
  r.knots = node.at("knots").as_double_array();
  if (const auto drift = node.find("landing_drift_deg")) r.landing_drift_deg = drift->as_double();
  if (const auto guided = node.find("twist_guided_intervals"))
    r.twist_guided_intervals = read_int_array(*guided, 0);
  const JsonNode levels = node.at("levels");
  levels.require_array();
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const JsonNode level = levels.at(i);
    level.require_object();
    OptimizationResult::Level l;
    l.subdivisions = read_int_array(level.at("subdivisions"), 1);
    l.avg_root_force = level.at("avg_root_force").as_double();
    if (const auto drift = level.find("landing_drift_deg"))
      l.landing_drift_deg = drift->as_double();
    l.iterations = level.at("iterations").as_int();
    l.status = level.at("status").as_string();
    if (const auto weight = level.find("root_moment_weight"))
      l.root_moment_weight = weight->as_double();
    r.levels.push_back(std::move(l));
  }
  if (const auto polish = node.find("joint_load_polish")) {
    polish->require_object();
    JointLoadPolish& p = r.joint_load_polish.emplace();
    if (const auto w = polish->find("weight")) p.weight = w->as_double();
    if (const auto m = polish->find("root_moment_weight")) p.root_moment_weight = m->as_double();
    if (const auto b = polish->find("joint_bound")) p.joint_bound = b->as_double();
    if (const auto a = polish->find("attempts")) p.attempts = a->as_int();
    if (const auto s = polish->find("bounded_tries_skipped")) p.bounded_tries_skipped = s->as_int();
    p.avg_root_force_before = polish->at("avg_root_force_before").as_double();
    p.avg_root_force_after = polish->at("avg_root_force_after").as_double();
    if (const auto d = polish->find("landing_drift_before_deg"))
      p.landing_drift_before_deg = d->as_double();
    if (const auto d = polish->find("landing_drift_after_deg"))
      p.landing_drift_after_deg = d->as_double();
    if (const auto j = polish->find("joint_rise_before")) p.joint_rise_before = j->as_double();
    if (const auto t = polish->find("bounds_tightened")) p.bounds_tightened = read_bool(*t);
    if (const auto k = polish->find("knots_refined")) p.knots_refined = read_bool(*k);
    if (const auto b = polish->find("bounded_alternative")) {
      b->require_object();
      p.bounded_alternative = JointLoadPolish::BoundedAlternative{
          b->at("landing_drift_deg").as_double(), b->at("avg_root_force").as_double(),
          b->at("joint_rise").as_double()};
    }
    p.iterations = polish->at("iterations").as_int();
    p.status = polish->at("status").as_string();
    p.kept = read_bool(polish->at("kept"));
  }
  return r;
}

bool records(const OptionSpec& spec, ResultJson::Kind kind) {
  return spec.recorded == ResultRecord::kEveryResult ||
         (spec.recorded == ResultRecord::kOptimization && kind == ResultJson::Kind::kOptimization);
}

}  // namespace

std::optional<OptionValue> ResultJson::option(const std::string& result_key) const {
  for (const auto& [key, value] : options)
    if (key == result_key) return value;
  return std::nullopt;
}

nlohmann::json result_to_json(const ResultJson& r) {
  nlohmann::json j;
  j["format"] = r.format;
  j["status"] = r.status;
  j["motion"] = r.motion;
  j["motion_file"] = r.motion_file;
  j["model"] = r.model;
  j["knots_per_interval"] = r.knots_per_interval;
  j["flight_time_s"] = r.flight_time_s;
  j["keyframes"] = r.keyframes;
  for (const auto& [key, value] : r.options)
    j[key] = option_value_json(value);
  const auto& o = r.optimization;
  j["before"] = metrics_json(r.before, o ? o->optimizer_objective_before : std::nullopt);
  j["keyframe_times_before"] = r.keyframe_times_before;
  if (const auto& c = r.residual_check) {
    j["residual_check"] = {{"rule", c->rule}, {"points", c->points}};
    if (c->halvings) j["residual_check"]["halvings"] = *c->halvings;
    if (c->converged) j["residual_check"]["converged"] = *c->converged;
    if (c->optimizer_agrees) j["residual_check"]["optimizer_agrees"] = *c->optimizer_agrees;
    if (!c->share_by_keyframe_interval.empty())
      j["residual_check"]["share_by_keyframe_interval"] = c->share_by_keyframe_interval;
  }
  const KeyframeErrors* e = r.keyframe_errors ? &*r.keyframe_errors : nullptr;
  j["max_translation_error_m"] = e ? nlohmann::json(e->max_translation_error_m) : nullptr;
  j["max_quaternion_error"] = e ? nlohmann::json(e->max_quaternion_error) : nullptr;
  j["max_rotation_error_deg"] = e ? nlohmann::json(e->max_rotation_error_deg) : nullptr;
  if (r.takeoff_angular_momentum)
    j["takeoff_angular_momentum"] = vector_json(*r.takeoff_angular_momentum);
  if (const auto& a = r.takeoff_adaptation)
    j["takeoff_adaptation"] = {{"rule", a->rule},
                               {"own_model", a->own_model},
                               {"own_angular_momentum", vector_json(a->own_angular_momentum)},
                               {"angular_momentum", vector_json(a->angular_momentum)}};
  if (r.body_weight_N) j["body_weight_N"] = *r.body_weight_N;
  if (!r.joint_loads.empty() && r.body_weight_N) {
    nlohmann::json loads = nlohmann::json::object();
    for (const ResultJson::JointLoad& l : r.joint_loads) {
      loads[l.joint]["before"] = joint_peak_json(l.before, *r.body_weight_N);
      if (l.after) loads[l.joint]["after"] = joint_peak_json(*l.after, *r.body_weight_N);
    }
    j["joint_loads"] = loads;
  }
  if (!r.strength_before.empty()) {
    auto block = [](const std::vector<ResultJson::JointStrength>& entries,
                    const std::string& verdict) {
      nlohmann::json joints = nlohmann::json::object();
      for (const ResultJson::JointStrength& peak : entries)
        joints[peak.joint] = {{"coordinate", peak.coordinate},
                              {"direction", peak.direction},
                              {"words", peak.words},
                              {"share", peak.share},
                              {"time_s", peak.time_s},
                              {"moment_Nm", peak.moment_Nm},
                              {"capacity_Nm", peak.capacity_Nm},
                              {"angle_deg", peak.angle_deg},
                              {"shortening_speed_rad_s", peak.shortening_speed_rad_s},
                              {"extrapolated", peak.extrapolated},
                              {"source", peak.source}};
      return nlohmann::json{{"joints", joints}, {"verdict", verdict}};
    };
    j["joint_strength"] = {{"reference", r.strength_reference},
                           {"before", block(r.strength_before, r.strength_verdict_before)}};
    if (!r.strength_after.empty())
      j["joint_strength"]["after"] = block(r.strength_after, r.strength_verdict_after);
  }
  if (r.rotation_before) {
    j["rotation"]["before"] = rotation_json(*r.rotation_before);
    if (r.rotation_after) j["rotation"]["after"] = rotation_json(*r.rotation_after);
  }
  if (r.kind != ResultJson::Kind::kSimulation) {
    nlohmann::json intervals = nlohmann::json::array();
    for (const SparseTwistInterval& i : r.sparse_twist_intervals)
      intervals.push_back({{"first_keyframe", i.first_keyframe},
                           {"start_s", i.start_s},
                           {"end_s", i.end_s},
                           {"flight_twist_deg", i.flight_twist_deg},
                           {"interpolation_twist_deg", i.interpolation_twist_deg},
                           {"words", sparse_twist_words(i)}});
    j["sparse_twist_intervals"] = intervals;
  }
  if (r.clearance) j["clearance"] = clearance_json(*r.clearance);
  if (r.entry) j["entry"] = entry_json(*r.entry);
  if (const auto& s = r.simulation) {
    j["takeoff_angular_momentum_source"] = s->angular_momentum_source;
    nlohmann::json joints = nlohmann::json::object();
    for (const auto& [name, deg] : s->landing_joint_error_deg)
      joints[name] = deg;
    j["landing"] = {{"root_error_deg", s->landing_root_error_deg},
                    {"joint_error_deg", joints},
                    {"com_error_m", s->landing_com_error_m}};
    if (s->landing_root_vs_motion_deg)
      j["landing"]["root_vs_motion_deg"] = *s->landing_root_vs_motion_deg;
    if (s->angular_momentum_spread) j["angular_momentum_spread"] = *s->angular_momentum_spread;
  }
  // Evaluations and simulations keep the optimiser's fields (docs/formats.md), as null.
  j["iterations"] = o ? nlohmann::json(o->iterations) : nullptr;
  j["solve_seconds"] = o ? nlohmann::json(o->solve_seconds) : nullptr;
  j["variables"] = o ? nlohmann::json(o->variables) : nullptr;
  j["constraints"] = o ? nlohmann::json(o->constraints) : nullptr;
  j["after"] = o ? metrics_json(o->after, o->optimizer_objective_after) : nullptr;
  j["keyframe_times_after"] = o ? nlohmann::json(o->keyframe_times_after) : nullptr;
  if (o && o->keyframe_time_spreads) {
    j["keyframe_time_spread_s"] = *o->keyframe_time_spreads;
    j["keyframe_times_undetermined"] = o->keyframe_times_undetermined;
  }
  if (o && o->ipopt_status) j["ipopt_status"] = *o->ipopt_status;
  if (o && o->restarts) j["restarts"] = *o->restarts;
  if (o && o->tolerances)
    j["tolerances"] = {{"translation_m", o->tolerances->translation_m},
                       {"quaternion", o->tolerances->quaternion}};
  if (o && o->resolution) j["resolution"] = resolution_json(*o->resolution);
  if (o && o->largest_joint_turn_deg)
    j["largest_joint_turn_deg"] = {{"before", o->largest_joint_turn_deg->first},
                                   {"after", o->largest_joint_turn_deg->second}};
  return j;
}

ResultJson parse_result_json(const nlohmann::json& document, const std::string& file) {
  const JsonNode root(document, file);
  root.require_object();
  ResultJson r;
  const JsonNode format = root.at("format");
  r.format = format.as_string();
  if (r.format != kResultFormatTag)
    format.fail("expected \"" + std::string(kResultFormatTag) + "\", found \"" + r.format +
                "\" (not a saltus evaluate, simulate or optimize result)");
  r.status = root.at("status").as_string();
  if (r.status == "evaluated")
    r.kind = ResultJson::Kind::kEvaluation;
  else if (root.find("landing"))
    r.kind = ResultJson::Kind::kSimulation;
  else if (root.find("after"))
    r.kind = ResultJson::Kind::kOptimization;
  else
    root.at("after").fail("null or missing in a result that was neither evaluated nor simulated");
  r.motion = root.at("motion").as_string();
  r.motion_file = root.at("motion_file").as_string();
  r.model = root.at("model").as_string();
  r.knots_per_interval = root.at("knots_per_interval").as_int();
  r.flight_time_s = root.at("flight_time_s").as_double();
  r.keyframes = root.at("keyframes").as_int();
  for (const OptionSpec& spec : option_table())
    if (records(spec, r.kind))
      if (const auto node = root.find(spec.result_key))
        r.options.emplace_back(spec.result_key, read_option(spec, *node));
  r.before = read_force_metrics(root.at("before"));
  r.keyframe_times_before = root.at("keyframe_times_before").as_double_array();
  if (const auto check = root.find("residual_check")) {
    ResultJson::ResidualCheck c;
    c.rule = check->at("rule").as_string();
    c.points = check->at("points").as_int();
    if (const auto halvings = check->find("halvings")) c.halvings = halvings->as_int();
    if (const auto converged = check->find("converged")) c.converged = read_bool(*converged);
    if (const auto agrees = check->find("optimizer_agrees"))
      c.optimizer_agrees = read_bool(*agrees);
    if (const auto shares = check->find("share_by_keyframe_interval"))
      c.share_by_keyframe_interval = shares->as_double_array();
    r.residual_check = c;
  }
  if (const auto translation = root.find("max_translation_error_m")) {
    KeyframeErrors e;
    e.max_translation_error_m = translation->as_double();
    e.max_quaternion_error = root.at("max_quaternion_error").as_double();
    e.max_rotation_error_deg = root.at("max_rotation_error_deg").as_double();
    r.keyframe_errors = e;
  }
  if (const auto momentum = root.find("takeoff_angular_momentum"))
    r.takeoff_angular_momentum = momentum->as_vector3();
  if (const auto adaptation = root.find("takeoff_adaptation")) {
    TakeoffAdaptation a;
    a.rule = adaptation->at("rule").as_string();
    a.own_model = adaptation->at("own_model").as_string();
    a.own_angular_momentum = adaptation->at("own_angular_momentum").as_vector3();
    a.angular_momentum = adaptation->at("angular_momentum").as_vector3();
    r.takeoff_adaptation = a;
  }
  if (const auto weight = root.find("body_weight_N")) r.body_weight_N = weight->as_double();
  if (const auto rotation = root.find("rotation")) {
    rotation->require_object();
    r.rotation_before = read_rotation(rotation->at("before"));
    if (const auto after = rotation->find("after")) r.rotation_after = read_rotation(*after);
  }
  if (const auto intervals = root.find("sparse_twist_intervals")) {
    intervals->require_array();
    for (std::size_t k = 0; k < intervals->size(); ++k) {
      const JsonNode node = intervals->at(k);
      node.require_object();
      SparseTwistInterval i;
      i.first_keyframe = node.at("first_keyframe").as_int();
      i.start_s = node.at("start_s").as_double();
      i.end_s = node.at("end_s").as_double();
      i.flight_twist_deg = node.at("flight_twist_deg").as_double();
      i.interpolation_twist_deg = node.at("interpolation_twist_deg").as_double();
      r.sparse_twist_intervals.push_back(i);
    }
  }
  if (const auto clearance = root.find("clearance")) r.clearance = read_clearance(*clearance);
  if (const auto entry = root.find("entry")) r.entry = read_entry(*entry);
  if (const auto loads = root.find("joint_loads")) {
    loads->require_object();
    const auto peak = [](const JsonNode& node) {
      node.require_object();
      JointLoadPeak p;
      p.force_N = node.at("peak_force_N").as_double();
      p.force_time_s = node.at("peak_force_time_s").as_double();
      p.moment_Nm = node.at("peak_moment_Nm").as_double();
      p.moment_time_s = node.at("peak_moment_time_s").as_double();
      return p;
    };
    for (const auto& [name, node] : loads->members()) {
      ResultJson::JointLoad l;
      l.joint = name;
      l.before = peak(node.at("before"));
      if (const auto after = node.find("after")) l.after = peak(*after);
      r.joint_loads.push_back(std::move(l));
    }
  }
  if (const auto strength = root.find("joint_strength")) {
    strength->require_object();
    r.strength_reference = strength->at("reference").as_string();
    auto read_block = [](const JsonNode& block, std::vector<ResultJson::JointStrength>& entries,
                         std::string& verdict) {
      block.require_object();
      verdict = block.at("verdict").as_string();
      const JsonNode joints = block.at("joints");
      joints.require_object();
      for (const auto& [name, node] : joints.members()) {
        node.require_object();
        ResultJson::JointStrength e;
        e.joint = name;
        e.coordinate = node.at("coordinate").as_string();
        e.direction = node.at("direction").as_string();
        e.words = node.at("words").as_string();
        e.share = node.at("share").as_double();
        e.time_s = node.at("time_s").as_double();
        e.moment_Nm = node.at("moment_Nm").as_double();
        e.capacity_Nm = node.at("capacity_Nm").as_double();
        e.angle_deg = node.at("angle_deg").as_double();
        e.shortening_speed_rad_s = node.at("shortening_speed_rad_s").as_double();
        e.extrapolated = read_bool(node.at("extrapolated"));
        e.source = node.at("source").as_string();
        entries.push_back(std::move(e));
      }
    };
    read_block(strength->at("before"), r.strength_before, r.strength_verdict_before);
    if (const auto after = strength->find("after"))
      read_block(*after, r.strength_after, r.strength_verdict_after);
  }
  if (r.kind == ResultJson::Kind::kSimulation) {
    ResultJson::Simulation s;
    s.angular_momentum_source = root.at("takeoff_angular_momentum_source").as_string();
    const JsonNode landing = root.at("landing");
    landing.require_object();
    s.landing_root_error_deg = landing.at("root_error_deg").as_double();
    s.landing_com_error_m = landing.at("com_error_m").as_double();
    const JsonNode joints = landing.at("joint_error_deg");
    joints.require_object();
    for (const auto& [name, node] : joints.members())
      s.landing_joint_error_deg[name] = node.as_double();
    if (const auto vs_motion = landing.find("root_vs_motion_deg"))
      s.landing_root_vs_motion_deg = vs_motion->as_double();
    if (const auto spread = root.find("angular_momentum_spread"))
      s.angular_momentum_spread = spread->as_double();
    r.simulation = std::move(s);
  }
  if (r.kind == ResultJson::Kind::kOptimization) {
    ResultJson::Optimization o;
    o.iterations = root.at("iterations").as_int();
    o.solve_seconds = root.at("solve_seconds").as_double();
    o.variables = root.at("variables").as_int();
    o.constraints = root.at("constraints").as_int();
    o.after = read_force_metrics(root.at("after"));
    if (const auto objective = root.at("before").find("optimizer_objective"))
      o.optimizer_objective_before = objective->as_double();
    if (const auto objective = root.at("after").find("optimizer_objective"))
      o.optimizer_objective_after = objective->as_double();
    o.keyframe_times_after = root.at("keyframe_times_after").as_double_array();
    if (const auto spreads = root.find("keyframe_time_spread_s")) {
      o.keyframe_time_spreads = spreads->as_double_array();
      o.keyframe_times_undetermined = read_int_array(root.at("keyframe_times_undetermined"), 0);
    }
    if (const auto status = root.find("ipopt_status")) o.ipopt_status = status->as_string();
    if (const auto restarts = root.find("restarts")) o.restarts = restarts->as_int();
    if (const auto tolerances = root.find("tolerances")) {
      Tolerances t;
      t.translation_m = tolerances->at("translation_m").as_double();
      t.quaternion = tolerances->at("quaternion").as_double();
      o.tolerances = t;
    }
    if (const auto resolution = root.find("resolution"))
      o.resolution = read_resolution(*resolution);
    if (const auto turn = root.find("largest_joint_turn_deg"))
      o.largest_joint_turn_deg =
          std::make_pair(turn->at("before").as_double(), turn->at("after").as_double());
    r.optimization = std::move(o);
  }
  return r;
}

ResultJson read_result_json(const std::string& path) {
  return parse_result_json(read_json_file(path), path);
}

ResultJson evaluation_result(const MotionFile& file, const MotionEvaluation& e,
                             const EvaluateOptions& options) {
  ResultJson r = common_result(file, ResultJson::Kind::kEvaluation, "evaluated", options);
  r.before = e.metrics;
  r.keyframe_times_before = e.keyframe_times;
  r.residual_check = residual_check(e.check, e.keyframe_times);
  r.keyframe_errors = e.keyframe_errors;
  r.takeoff_angular_momentum = e.samples.front().angular_momentum;
  set_joint_loads(r, file.model, e.check, nullptr);
  r.rotation_before = yeadon_summary(e.trajectory, options.samples);
  r.sparse_twist_intervals = sparse_twist_intervals(file.motion, file.model);
  set_clearance(r, file, e.samples);
  return r;
}

ResultJson simulation_result(const MotionFile& file, const SimulationResult& s,
                             const EvaluateOptions& options) {
  ResultJson r = common_result(file, ResultJson::Kind::kSimulation, "simulated", options);
  r.before = s.metrics;
  for (const Keyframe& k : file.motion.keyframes)
    r.keyframe_times_before.push_back(k.time);
  r.takeoff_angular_momentum = s.angular_momentum;
  std::vector<Eigen::Quaterniond> roots;
  for (const SampleRecord& sample : s.samples)
    roots.push_back(sample.segment_rotation.at(0));
  r.rotation_before = yeadon_summary(roots);
  ResultJson::Simulation sim;
  sim.angular_momentum_source =
      s.angular_momentum_from_file ? "motion file" : "best constant fit to the motion's L(t)";
  sim.angular_momentum_spread = s.angular_momentum_spread;
  sim.landing_root_vs_motion_deg = s.landing_vs_motion_deg;
  sim.landing_root_error_deg = s.landing_root_error_deg;
  sim.landing_joint_error_deg = s.landing_joint_error_deg;
  sim.landing_com_error_m = s.landing_com_error_m;
  r.simulation = std::move(sim);
  set_clearance(r, file, s.samples);
  return r;
}

ResultJson optimization_result(const MotionFile& file, const OptimizationResult& result,
                               const OptimizeOptions& options) {
  // knots_per_interval is the K used; the one asked for is an option (option table).
  ResultJson r = common_result(file, ResultJson::Kind::kOptimization, result.solve.status,
                               result.knots_per_interval);
  r.options = recorded_options(options, true);
  r.before = result.before.metrics;
  r.keyframe_times_before = result.before.keyframe_times;
  r.residual_check = residual_check(result.after.check, result.after.keyframe_times);
  r.residual_check->optimizer_agrees = optimizer_agrees_with_check(result);
  r.keyframe_errors = result.after.keyframe_errors;
  set_joint_loads(r, file.model, result.before.check, &result.after.check);
  r.rotation_before = yeadon_summary(result.before.trajectory, options.nlp.samples);
  r.rotation_after = yeadon_summary(result.after.trajectory, options.nlp.samples);
  r.sparse_twist_intervals = result.sparse_twist_intervals;
  ResultJson::Optimization o;
  o.optimizer_objective_before = result.optimizer_objective_before;
  o.optimizer_objective_after = result.optimizer_objective_after;
  o.iterations = result.solve.iterations;
  o.solve_seconds = result.solve.seconds;
  o.variables = result.variables;
  o.constraints = result.constraints;
  o.after = result.after.metrics;
  o.keyframe_times_after = result.after.keyframe_times;
  // How far each optimised time could move with the residual within kTimeSpreadForceRise:
  // times beyond kDeterminedTimeSpread are not recovered, only chosen.
  o.keyframe_time_spreads = result.keyframe_time_spreads;
  for (std::size_t i = 0; i < result.keyframe_time_spreads.size(); ++i)
    if (result.keyframe_time_spreads[i] > kDeterminedTimeSpread)
      o.keyframe_times_undetermined.push_back(static_cast<int>(i));
  o.ipopt_status = result.solve.ipopt_status;
  o.restarts = result.solve.restarts;
  o.tolerances = file.motion.tolerances;
  ResultJson::Optimization::Resolution resolution;
  resolution.automatic = options.resolution_is_automatic();
  resolution.subdivisions = result.subdivisions;
  if (!result.after.trajectory.rotations.empty())
    resolution.knots = result.after.trajectory.rotations.front().knots();
  resolution.levels = result.levels;
  resolution.joint_load_polish = result.joint_load_polish;
  resolution.landing_drift_deg = result.landing_drift_deg;
  resolution.twist_guided_intervals = result.twist_guided_intervals;
  o.resolution = std::move(resolution);
  o.largest_joint_turn_deg =
      std::make_pair(largest_control_turn(result.before.trajectory, 1) * kDegreesPerRadian,
                     largest_control_turn(result.after.trajectory, 1) * kDegreesPerRadian);
  r.optimization = std::move(o);
  return r;
}

nlohmann::json evaluation_result_json(const MotionFile& file, const MotionEvaluation& e,
                                      const EvaluateOptions& options) {
  return result_to_json(evaluation_result(file, e, options));
}

nlohmann::json simulation_result_json(const MotionFile& file, const SimulationResult& s,
                                      const EvaluateOptions& options) {
  return result_to_json(simulation_result(file, s, options));
}

nlohmann::json optimization_result_json(const MotionFile& file, const OptimizationResult& result,
                                        const OptimizeOptions& options) {
  return result_to_json(optimization_result(file, result, options));
}

std::string folder_name(const std::string& dir) {
  const std::filesystem::path folder(dir);
  return folder.filename().empty() ? folder.parent_path().filename().string()
                                   : folder.filename().string();
}

std::string output_file(const std::string& dir, const std::string& name, const std::string& what) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(dir)) throw InputError(dir, "", "not a folder (expected " + what + ")");
  const std::string path = (fs::path(dir) / name).string();
  if (!fs::exists(path)) throw InputError(path, "", "missing (not " + what + ")");
  return path;
}

bool result_json_says(const std::string& dir, const std::string& key, const std::string& value) {
  const std::filesystem::path result = std::filesystem::path(dir) / "result.json";
  if (!std::filesystem::is_regular_file(result)) return false;
  try {
    const nlohmann::json document = read_json_file(result.string());
    return document.is_object() && document.value(key, std::string()) == value;
  } catch (const std::exception&) {
    return false;
  }
}

ResultFolder read_result_folder(const std::string& dir) {
  const std::string what = "a complete saltus evaluate, simulate or optimize folder";
  ResultFolder out;
  out.path = dir;
  out.name = folder_name(dir);
  out.result = read_result_json(output_file(dir, "result.json", what));
  if (out.result.kind == ResultJson::Kind::kOptimization) {
    out.before = read_trajectory_csv(output_file(dir, "trajectory_before.csv", what));
    out.after = read_trajectory_csv(output_file(dir, "trajectory_after.csv", what));
  } else {
    out.before = read_trajectory_csv(output_file(dir, "trajectory.csv", what));
  }
  return out;
}

}  // namespace saltus
