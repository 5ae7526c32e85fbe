#include "saltus/formats/study_case_file.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "saltus/base/json_reader.h"
#include "saltus/formats/output_folder.h"

namespace saltus {

namespace {

const char* kind_name(CaseKind kind) {
  switch (kind) {
    case CaseKind::kConvergence:
      return "convergence";
    case CaseKind::kOptimization:
      return "optimization";
    case CaseKind::kMassStudy:
      return "mass_study";
    case CaseKind::kAthlete:
      return "athlete";
  }
  return "";
}

/// Non-finite numbers become null (JSON has no NaN); read_number turns null back into NaN.
nlohmann::json number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

double read_number(const JsonNode& node, const std::string& key) {
  const JsonNode value = node.at(key);
  if (value.is_null()) return std::numeric_limits<double>::quiet_NaN();
  return value.as_double();
}

bool read_bool(const JsonNode& node, const std::string& key) {
  const JsonNode value = node.at(key);
  if (!value.value().is_boolean()) value.fail("expected true or false");
  return value.value().get<bool>();
}

std::string read_optional_string(const JsonNode& node, const std::string& key) {
  const std::optional<JsonNode> value = node.find(key);
  return value ? value->as_string() : std::string();
}

nlohmann::json optional_string(const std::string& text) {
  return text.empty() ? nlohmann::json(nullptr) : nlohmann::json(text);
}

nlohmann::json numbers(const std::vector<double>& values) {
  nlohmann::json out = nlohmann::json::array();
  for (double v : values)
    out.push_back(number(v));
  return out;
}

std::vector<double> read_numbers(const JsonNode& node, const std::string& key) {
  const JsonNode array = node.at(key);
  array.require_array();
  std::vector<double> out;
  for (std::size_t i = 0; i < array.size(); ++i) {
    const JsonNode value = array.at(i);
    out.push_back(value.is_null() ? std::numeric_limits<double>::quiet_NaN() : value.as_double());
  }
  return out;
}

nlohmann::json run_to_json(const RunSummary& r) {
  return {{"motion_name", r.motion_name},
          {"keyframes", r.keyframes},
          {"status", r.status},
          {"solved", r.solved},
          {"iterations", r.iterations},
          {"seconds", number(r.seconds)},
          {"variables", r.variables},
          {"constraints", r.constraints},
          {"knots_per_interval", r.knots_per_interval},
          {"restarts", r.restarts},
          {"objective_before", number(r.objective_before)},
          {"objective_after", number(r.objective_after)},
          {"avg_force_before_N", number(r.avg_force_before)},
          {"avg_force_after_N", number(r.avg_force_after)},
          {"max_force_after_N", number(r.max_force_after)},
          {"max_quaternion_error", number(r.max_quaternion_error)},
          {"keyframe_times_before", numbers(r.keyframe_times_before)},
          {"keyframe_times_after", numbers(r.keyframe_times_after)}};
}

RunSummary parse_run(const JsonNode& node) {
  node.require_object();
  RunSummary r;
  r.motion_name = node.at("motion_name").as_string();
  r.keyframes = node.at("keyframes").as_int();
  r.status = node.at("status").as_string();
  r.solved = read_bool(node, "solved");
  r.iterations = node.at("iterations").as_int();
  r.seconds = read_number(node, "seconds");
  r.variables = node.at("variables").as_int();
  r.constraints = node.at("constraints").as_int();
  r.knots_per_interval = node.at("knots_per_interval").as_int();
  r.restarts = node.at("restarts").as_int();
  r.objective_before = read_number(node, "objective_before");
  r.objective_after = read_number(node, "objective_after");
  r.avg_force_before = read_number(node, "avg_force_before_N");
  r.avg_force_after = read_number(node, "avg_force_after_N");
  r.max_force_after = read_number(node, "max_force_after_N");
  r.max_quaternion_error = read_number(node, "max_quaternion_error");
  r.keyframe_times_before = read_numbers(node, "keyframe_times_before");
  r.keyframe_times_after = read_numbers(node, "keyframe_times_after");
  return r;
}

nlohmann::json outcome_to_json(const StudyOutcome& o) {
  const StudyCase& c = o.study_case;
  nlohmann::json j = run_to_json(o);
  j["motion"] = c.motion;
  j["formulation"] = c.formulation == Formulation::kRelaxed ? "relaxed" : "strict";
  j["epsilon"] = number(c.epsilon);
  j["mass_segment"] = c.mass_segment;
  j["mass_error"] = number(c.mass_error);
  j["timing_error_s"] = number(c.timing_error_s);
  return j;
}

StudyOutcome parse_outcome(const JsonNode& node) {
  StudyOutcome o;
  static_cast<RunSummary&>(o) = parse_run(node);
  StudyCase& c = o.study_case;
  c.motion = node.at("motion").as_string();
  const std::string formulation = node.at("formulation").as_string();
  if (formulation != "relaxed" && formulation != "strict")
    node.at("formulation").fail("expected \"relaxed\" or \"strict\"");
  c.formulation = formulation == "relaxed" ? Formulation::kRelaxed : Formulation::kStrict;
  c.epsilon = read_number(node, "epsilon");
  c.mass_segment = node.at("mass_segment").as_string();
  c.mass_error = read_number(node, "mass_error");
  c.timing_error_s = read_number(node, "timing_error_s");
  return o;
}

nlohmann::json athlete_to_json(const AthleteOutcome& o) {
  return {{"athlete", o.athlete},
          {"takeoff", o.takeoff},
          {"mass_kg", number(o.mass_kg)},
          {"height_m", number(o.height_m)},
          {"takeoff_angular_momentum",
           numbers({o.takeoff_angular_momentum.x(), o.takeoff_angular_momentum.y(),
                    o.takeoff_angular_momentum.z()})},
          {"status", o.status},
          {"solved", o.solved},
          {"iterations", o.iterations},
          {"seconds", number(o.seconds)},
          {"avg_force_before_N", number(o.avg_root_force_before_N)},
          {"avg_force_after_N", number(o.avg_root_force_after_N)},
          {"max_force_after_N", number(o.max_root_force_after_N)},
          {"landing_error_before_deg", number(o.landing_error_before_deg)},
          {"landing_error_after_deg", number(o.landing_error_after_deg)},
          {"somersaults_before", number(o.somersaults_before)},
          {"twists_before", number(o.twists_before)},
          {"somersaults_after", number(o.somersaults_after)},
          {"twists_after", number(o.twists_after)},
          {"peak_moment_joint", o.peak_moment_joint},
          {"peak_moment_Nm", number(o.peak_moment_Nm)},
          {"peak_force_joint", o.peak_force_joint},
          {"peak_force_N", number(o.peak_force_N)},
          {"peak_force_pct_bw", number(o.peak_force_pct_bw)},
          {"joint_rise_joint", o.joint_rise_joint},
          {"joint_rise", number(o.joint_rise)}};
}

AthleteOutcome parse_athlete(const JsonNode& node) {
  node.require_object();
  AthleteOutcome o;
  o.athlete = node.at("athlete").as_string();
  o.takeoff = node.at("takeoff").as_string();
  o.mass_kg = read_number(node, "mass_kg");
  o.height_m = read_number(node, "height_m");
  const std::vector<double> l = read_numbers(node, "takeoff_angular_momentum");
  if (l.size() != 3) node.at("takeoff_angular_momentum").fail("expected 3 numbers");
  o.takeoff_angular_momentum = Eigen::Vector3d(l[0], l[1], l[2]);
  o.status = node.at("status").as_string();
  o.solved = read_bool(node, "solved");
  o.iterations = node.at("iterations").as_int();
  o.seconds = read_number(node, "seconds");
  o.avg_root_force_before_N = read_number(node, "avg_force_before_N");
  o.avg_root_force_after_N = read_number(node, "avg_force_after_N");
  o.max_root_force_after_N = read_number(node, "max_force_after_N");
  o.landing_error_before_deg = read_number(node, "landing_error_before_deg");
  o.landing_error_after_deg = read_number(node, "landing_error_after_deg");
  o.somersaults_before = read_number(node, "somersaults_before");
  o.twists_before = read_number(node, "twists_before");
  o.somersaults_after = read_number(node, "somersaults_after");
  o.twists_after = read_number(node, "twists_after");
  o.peak_moment_joint = node.at("peak_moment_joint").as_string();
  o.peak_moment_Nm = read_number(node, "peak_moment_Nm");
  o.peak_force_joint = node.at("peak_force_joint").as_string();
  o.peak_force_N = read_number(node, "peak_force_N");
  o.peak_force_pct_bw = read_number(node, "peak_force_pct_bw");
  // Case files written before the joint rise was recorded read as 0 (unknown).
  if (const auto joint = node.find("joint_rise_joint")) o.joint_rise_joint = joint->as_string();
  if (node.has("joint_rise")) o.joint_rise = read_number(node, "joint_rise");
  return o;
}

}  // namespace

bool CaseRecord::solved() const {
  if (!finished()) return false;
  switch (kind) {
    case CaseKind::kConvergence:
      return convergence.solved;
    case CaseKind::kOptimization:
      return run.solved;
    case CaseKind::kMassStudy:
      return true;
    case CaseKind::kAthlete:
      return athlete.solved;
  }
  return false;
}

nlohmann::json case_record_to_json(const CaseRecord& record) {
  nlohmann::json j;
  j["format"] = kStudyCaseFormat;
  j["index"] = record.index;
  j["case"] = record.name;
  j["kind"] = kind_name(record.kind);
  j["role"] = record.role;
  j["motion"] = record.motion;
  j["folder"] = optional_string(record.folder);
  j["failure"] = optional_string(record.failure);
  switch (record.kind) {
    case CaseKind::kConvergence:
      j["convergence"] = outcome_to_json(record.convergence);
      break;
    case CaseKind::kOptimization:
      j["run"] = run_to_json(record.run);
      break;
    case CaseKind::kMassStudy:
      j["mass_markdown"] = record.mass_markdown;
      break;
    case CaseKind::kAthlete:
      j["athlete"] = athlete_to_json(record.athlete);
      break;
  }
  return j;
}

CaseRecord parse_case_record(const nlohmann::json& document, const std::string& file) {
  const JsonNode root(document, file);
  root.require_object();
  if (root.at("format").as_string() != kStudyCaseFormat)
    root.at("format").fail(std::string("expected \"") + kStudyCaseFormat + "\"");
  CaseRecord r;
  r.index = root.at("index").as_int();
  if (r.index < 0) root.at("index").fail("must be >= 0");
  r.name = root.at("case").as_string();
  const std::string kind = root.at("kind").as_string();
  if (kind == kind_name(CaseKind::kConvergence))
    r.kind = CaseKind::kConvergence;
  else if (kind == kind_name(CaseKind::kOptimization))
    r.kind = CaseKind::kOptimization;
  else if (kind == kind_name(CaseKind::kMassStudy))
    r.kind = CaseKind::kMassStudy;
  else if (kind == kind_name(CaseKind::kAthlete))
    r.kind = CaseKind::kAthlete;
  else
    root.at("kind").fail(
        "expected \"convergence\", \"optimization\", \"mass_study\" or \"athlete\"");
  r.role = root.at("role").as_string();
  r.motion = root.at("motion").as_string();
  r.folder = read_optional_string(root, "folder");
  if (r.folder.find('/') != std::string::npos || r.folder == "." || r.folder == "..")
    root.at("folder").fail("must be a folder name, not a path");
  r.failure = read_optional_string(root, "failure");
  switch (r.kind) {
    case CaseKind::kConvergence:
      r.convergence = parse_outcome(root.at("convergence"));
      break;
    case CaseKind::kOptimization:
      r.run = parse_run(root.at("run"));
      break;
    case CaseKind::kMassStudy:
      r.mass_markdown = root.at("mass_markdown").as_string();
      break;
    case CaseKind::kAthlete:
      r.athlete = parse_athlete(root.at("athlete"));
      break;
  }
  return r;
}

void write_case_record(const std::string& path, const CaseRecord& record) {
  const std::string temporary = path + ".tmp-" + std::to_string(getpid());
  write_text(temporary, case_record_to_json(record).dump(2) + "\n");
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw std::runtime_error(path + ": cannot write the case record");
  }
}

CaseRecord read_case_record(const std::string& path) {
  return parse_case_record(read_json_file(path), path);
}

std::string case_record_name(int index) {
  char name[32];
  std::snprintf(name, sizeof name, "cases/%04d.json", index);
  return name;
}

}  // namespace saltus
