// result.json (formats/result_json.h): every kind written and read back field for field (seeded),
// the keys of docs/formats.md, older files without later keys, bad documents naming the field; real
// result folders read back; and the figures agree with the trajectory.csv written beside them —
// J, RMS and peak root force recomputed here from the CSV's root wrench columns by the
// trapezoidal rule — and the simulation's result names its momentum and landing.

#include "saltus/formats/result_json.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <tuple>

#include "saltus/base/input_error.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/trajectory_csv.h"
#include "saltus/use_cases/result_folders.h"
#include "support/cli_runner.h"
#include "support/temp_path.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

std::string m1_path() {
  return std::string(SALTUS_EXAMPLES_DIR) + "/motions/M1-straight-back-somersault.motion.json";
}

/// A fresh folder private to the test process, removed afterwards.
struct TempDir {
  explicit TempDir(const std::string& name) : path(test::temp_path(name)) { fs::remove_all(path); }
  ~TempDir() { fs::remove_all(path); }
  fs::path path;
};

// Every field, compared exactly (JSON keeps doubles to the last bit).
auto fields(const ForceMetrics& m) {
  return std::tie(m.objective, m.avg_root_force, m.rms_force_N, m.rms_moment_Nm, m.max_force_N,
                  m.max_moment_Nm);
}
auto fields(const KeyframeErrors& e) {
  return std::tie(e.max_translation_error_m, e.max_quaternion_error, e.max_rotation_error_deg);
}
auto fields(const Tolerances& t) {
  return std::tie(t.translation_m, t.quaternion);
}
auto fields(const ResultJson::Simulation& s) {
  return std::tie(s.angular_momentum_source, s.angular_momentum_spread, s.landing_root_error_deg,
                  s.landing_joint_error_deg, s.landing_com_error_m, s.landing_root_vs_motion_deg);
}
auto fields(const ResultJson::ResidualCheck& c) {
  return std::tie(c.rule, c.points, c.halvings, c.converged, c.optimizer_agrees);
}
auto fields(const OptimizationResult::Level& l) {
  return std::tie(l.subdivisions, l.avg_root_force, l.landing_drift_deg, l.iterations, l.status,
                  l.root_moment_weight);
}
auto fields(const ResultJson::Optimization::Resolution& r) {
  std::vector<decltype(fields(r.levels.front()))> levels;
  for (const OptimizationResult::Level& l : r.levels)
    levels.push_back(fields(l));
  std::optional<
      std::tuple<double, double, double, int, int, double, double, double, double, double, bool,
                 bool, int, std::string, bool, std::optional<std::tuple<double, double, double>>>>
      polish;
  if (const auto& p = r.joint_load_polish)
    polish = std::make_tuple(
        p->weight, p->root_moment_weight, p->joint_bound, p->attempts, p->bounded_tries_skipped,
        p->avg_root_force_before, p->avg_root_force_after, p->landing_drift_before_deg,
        p->landing_drift_after_deg, p->joint_rise_before, p->bounds_tightened, p->knots_refined,
        p->iterations, p->status, p->kept,
        p->bounded_alternative
            ? std::optional(std::make_tuple(p->bounded_alternative->landing_drift_deg,
                                            p->bounded_alternative->avg_root_force,
                                            p->bounded_alternative->joint_rise))
            : std::nullopt);
  return std::make_tuple(r.automatic, r.subdivisions, r.knots, levels, polish, r.landing_drift_deg,
                         r.twist_guided_intervals);
}
auto fields(const ResultJson::Optimization& o) {
  return std::make_tuple(
      o.iterations, o.solve_seconds, o.variables, o.constraints, fields(o.after),
      o.optimizer_objective_before, o.optimizer_objective_after, o.keyframe_times_after,
      o.keyframe_time_spreads, o.keyframe_times_undetermined, o.ipopt_status, o.restarts,
      o.tolerances ? std::optional(fields(*o.tolerances)) : std::nullopt, o.largest_joint_turn_deg,
      o.resolution ? std::optional(fields(*o.resolution)) : std::nullopt);
}
auto fields(const ApparatusClearance& c) {
  return std::tie(c.kind, c.times, c.distance, c.from_s, c.min_distance_m, c.time_s, c.segment,
                  c.segment_end, c.point, c.edge_m, c.vertical_m, c.collision);
}
auto fields(const DiveEntry& e) {
  return std::tie(e.time_s, e.first_contact, e.com_height_m, e.angle_to_vertical_deg, e.head_first,
                  e.vertical);
}
// By joint name: the file's object keeps no order (nlohmann sorts its keys).
auto fields(const std::vector<ResultJson::JointStrength>& entries) {
  std::vector<std::tuple<std::string, std::string, std::string, std::string, double, double, double,
                         double, double, double, bool, std::string>>
      all;
  for (const ResultJson::JointStrength& e : entries)
    all.emplace_back(e.joint, e.coordinate, e.direction, e.words, e.share, e.time_s, e.moment_Nm,
                     e.capacity_Nm, e.angle_deg, e.shortening_speed_rad_s, e.extrapolated,
                     e.source);
  std::sort(all.begin(), all.end());
  return all;
}
template <typename T>
auto optional_fields(const std::optional<T>& x) {
  return x ? std::optional(fields(*x)) : std::nullopt;
}

void expect_same(const ResultJson& a, const ResultJson& b) {
  EXPECT_EQ(std::tie(a.kind, a.format, a.status, a.motion, a.motion_file, a.model),
            std::tie(b.kind, b.format, b.status, b.motion, b.motion_file, b.model));
  EXPECT_EQ(std::tie(a.knots_per_interval, a.flight_time_s, a.keyframes, a.options),
            std::tie(b.knots_per_interval, b.flight_time_s, b.keyframes, b.options));
  EXPECT_TRUE(fields(a.before) == fields(b.before));
  EXPECT_EQ(a.keyframe_times_before, b.keyframe_times_before);
  EXPECT_TRUE(optional_fields(a.residual_check) == optional_fields(b.residual_check));
  EXPECT_TRUE(optional_fields(a.keyframe_errors) == optional_fields(b.keyframe_errors));
  EXPECT_EQ(a.takeoff_angular_momentum, b.takeoff_angular_momentum);
  EXPECT_TRUE(optional_fields(a.simulation) == optional_fields(b.simulation));
  EXPECT_TRUE(optional_fields(a.clearance) == optional_fields(b.clearance));
  EXPECT_TRUE(optional_fields(a.entry) == optional_fields(b.entry));
  EXPECT_TRUE(optional_fields(a.optimization) == optional_fields(b.optimization));
  EXPECT_TRUE(fields(a.strength_before) == fields(b.strength_before));
  EXPECT_TRUE(fields(a.strength_after) == fields(b.strength_after));
  EXPECT_EQ(std::tie(a.strength_reference, a.strength_verdict_before, a.strength_verdict_after),
            std::tie(b.strength_reference, b.strength_verdict_before, b.strength_verdict_after));
  ASSERT_EQ(a.sparse_twist_intervals.size(), b.sparse_twist_intervals.size());
  for (std::size_t k = 0; k < a.sparse_twist_intervals.size(); ++k) {
    const SparseTwistInterval &x = a.sparse_twist_intervals[k], &y = b.sparse_twist_intervals[k];
    EXPECT_EQ(std::tie(x.first_keyframe, x.start_s, x.end_s, x.flight_twist_deg,
                       x.interpolation_twist_deg),
              std::tie(y.first_keyframe, y.start_s, y.end_s, y.flight_twist_deg,
                       y.interpolation_twist_deg));
  }
}

/// A result.json of `kind` with seeded values in every field the kind has.
ResultJson random_result(ResultJson::Kind kind, std::mt19937& rng) {
  std::uniform_real_distribution<double> any(-1e3, 1e3), positive(1e-9, 1e4);
  std::uniform_int_distribution<int> count(2, 12);
  auto metrics = [&] {
    ForceMetrics m;
    m.objective = positive(rng);
    m.avg_root_force = positive(rng);
    m.rms_force_N = positive(rng);
    m.rms_moment_Nm = positive(rng);
    m.max_force_N = positive(rng);
    m.max_moment_Nm = positive(rng);
    return m;
  };
  auto times = [&](int n) {
    std::vector<double> t{0.0};
    for (int i = 1; i < n; ++i)
      t.push_back(t.back() + positive(rng) / 1e4);
    return t;
  };
  ResultJson r;
  r.kind = kind;
  r.status = kind == ResultJson::Kind::kEvaluation   ? "evaluated"
             : kind == ResultJson::Kind::kSimulation ? "simulated"
                                                     : (rng() % 2 ? "solved" : "max_iterations");
  r.motion = "motion " + std::to_string(rng());
  r.motion_file = "dir/m" + std::to_string(rng()) + ".motion.json";
  r.model = "model-" + std::to_string(rng() % 100);
  r.knots_per_interval = 1 + static_cast<int>(rng() % 4);
  r.keyframes = count(rng);
  r.flight_time_s = positive(rng) / 1e3;
  // The options through the table, at seeded values.
  OptionValues values;
  values.set("samples", static_cast<int>(2 + rng() % 5000));
  if (rng() % 4 == 0)
    values.set("knots_per_interval", std::string("auto"));
  else
    values.set("knots_per_interval", static_cast<int>(1 + rng() % 50));
  values.set("formulation", std::string(rng() % 2 ? "strict" : "relaxed"));
  values.set("epsilon", positive(rng));
  values.set("optimize_timing", rng() % 2 == 0);
  values.set("max_joint_turn", std::uniform_real_distribution<double>(0, 360)(rng));
  r.options = recorded_options(values.optimize_options(), kind == ResultJson::Kind::kOptimization);
  r.before = metrics();
  r.keyframe_times_before = times(r.keyframes);
  if (kind != ResultJson::Kind::kSimulation) {
    r.keyframe_errors = KeyframeErrors{positive(rng), positive(rng), positive(rng)};
    r.residual_check =
        ResultJson::ResidualCheck{"rule " + std::to_string(rng()), static_cast<int>(rng() % 1000),
                                  std::nullopt, std::nullopt, std::nullopt};
    if (rng() % 2) {
      r.residual_check->halvings = static_cast<int>(rng() % 5);
      r.residual_check->converged = rng() % 2;
    }
    if (kind == ResultJson::Kind::kOptimization) r.residual_check->optimizer_agrees = rng() % 2;
    r.strength_reference = "reference " + std::to_string(rng());
    auto entries = [&] {
      std::vector<ResultJson::JointStrength> out;
      for (const char* joint : {"elbow_l", "hip_r", "knee_l", "lumbar"})
        out.push_back({joint, std::string(joint) + "_flexion", "flexion",
                       std::string("the ") + joint, positive(rng), positive(rng), positive(rng),
                       positive(rng), any(rng), any(rng), rng() % 2 == 0,
                       "source " + std::to_string(rng())});
      return out;
    };
    r.strength_before = entries();
    r.strength_verdict_before = "verdict " + std::to_string(rng());
    if (kind == ResultJson::Kind::kOptimization) {
      r.strength_after = entries();
      r.strength_verdict_after = "verdict " + std::to_string(rng());
    }
  }
  if (kind != ResultJson::Kind::kOptimization)
    r.takeoff_angular_momentum = Eigen::Vector3d(any(rng), any(rng), any(rng));
  if (kind != ResultJson::Kind::kOptimization) {
    // Either apparatus; a dive's entry only from a platform.
    ApparatusClearance c;
    c.kind = rng() % 2 ? ApparatusKind::kPlatform : ApparatusKind::kTrampoline;
    c.from_s = positive(rng) / 1e4;
    c.min_distance_m = any(rng) / 1e3;
    c.time_s = positive(rng) / 1e4;
    c.segment = rng() % 2 ? "foot_l" : "forearm_r";
    c.segment_end = rng() % 2;
    c.point = "point " + std::to_string(rng());
    c.edge_m = any(rng) / 1e2;
    c.vertical_m = any(rng) / 1e2;
    c.collision = c.min_distance_m < 0.0;
    r.clearance = c;
    if (c.kind == ApparatusKind::kPlatform) {
      DiveEntry e;
      e.time_s = positive(rng) / 1e4;
      e.first_contact = rng() % 2 ? "right hand" : "head";
      e.com_height_m = positive(rng) / 1e4;
      e.angle_to_vertical_deg = std::uniform_real_distribution<double>(0, 90)(rng);
      e.head_first = rng() % 2;
      e.vertical = e.angle_to_vertical_deg <= kVerticalEntryToleranceDeg;
      r.entry = e;
    }
  }
  if (kind != ResultJson::Kind::kSimulation)
    for (int k = rng() % 3; k > 0; --k) {
      SparseTwistInterval i;
      i.first_keyframe = static_cast<int>(rng() % 20);
      i.start_s = positive(rng) / 1e4;
      i.end_s = i.start_s + positive(rng) / 1e4;
      i.flight_twist_deg = any(rng);
      i.interpolation_twist_deg = any(rng);
      r.sparse_twist_intervals.push_back(i);
    }
  if (kind == ResultJson::Kind::kSimulation) {
    ResultJson::Simulation s;
    s.angular_momentum_source =
        rng() % 2 ? "motion file" : "best constant fit to the motion's L(t)";
    s.angular_momentum_spread = positive(rng);
    s.landing_root_vs_motion_deg = positive(rng);
    s.landing_root_error_deg = positive(rng);
    s.landing_com_error_m = positive(rng);
    for (const char* joint : {"root", "hip_l", "knee_r"})
      s.landing_joint_error_deg[joint] = positive(rng);
    r.simulation = s;
  }
  if (kind == ResultJson::Kind::kOptimization) {
    ResultJson::Optimization o;
    o.iterations = count(rng) * 10;
    o.solve_seconds = positive(rng);
    o.variables = count(rng) * 30;
    o.constraints = count(rng) * 7;
    o.after = metrics();
    o.optimizer_objective_before = positive(rng);
    o.optimizer_objective_after = positive(rng);
    o.keyframe_times_after = times(r.keyframes);
    o.keyframe_time_spreads.emplace();
    for (int i = 0; i < r.keyframes; ++i) {
      const bool end = i == 0 || i + 1 == r.keyframes;
      o.keyframe_time_spreads->push_back(end ? 0.0 : positive(rng) / 1e5);
      if (o.keyframe_time_spreads->back() > kDeterminedTimeSpread)
        o.keyframe_times_undetermined.push_back(i);
    }
    o.ipopt_status = "acceptable";
    o.restarts = static_cast<int>(rng() % 3);
    o.tolerances = Tolerances{positive(rng), positive(rng)};
    o.largest_joint_turn_deg = std::make_pair(positive(rng), positive(rng));
    ResultJson::Optimization::Resolution resolution;
    resolution.automatic = rng() % 2;
    for (int i = 1; i < r.keyframes; ++i)
      resolution.subdivisions.push_back(1 + static_cast<int>(rng() % 8));
    resolution.knots = times(count(rng) + 7);
    for (int level = 0; resolution.automatic && level < 1 + static_cast<int>(rng() % 3); ++level)
      resolution.levels.push_back({resolution.subdivisions, positive(rng), positive(rng),
                                   count(rng), rng() % 2 ? "solved" : "acceptable", positive(rng)});
    if (rng() % 2)
      resolution.joint_load_polish =
          JointLoadPolish{positive(rng), positive(rng), positive(rng),  count(rng),
                          count(rng),    positive(rng), positive(rng),  positive(rng),
                          positive(rng), positive(rng), rng() % 2 == 0, rng() % 2 == 0,
                          std::nullopt,  count(rng),    "solved",       rng() % 2 == 0};
    if (resolution.joint_load_polish && rng() % 2)
      resolution.joint_load_polish->bounded_alternative =
          JointLoadPolish::BoundedAlternative{positive(rng), positive(rng), positive(rng)};
    if (rng() % 2) resolution.landing_drift_deg = positive(rng);
    for (int k = rng() % 3; k > 0; --k)
      resolution.twist_guided_intervals.push_back(static_cast<int>(rng() % 20));
    o.resolution = resolution;
    r.optimization = o;
  }
  return r;
}

TEST(ResultJson, EveryKindReadsBackWhatWasWritten) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 30; ++trial) {
    for (auto kind : {ResultJson::Kind::kEvaluation, ResultJson::Kind::kSimulation,
                      ResultJson::Kind::kOptimization}) {
      const ResultJson written = random_result(kind, rng);
      // Through the text a file holds, as nlohmann writes and reads it.
      const std::string text = result_to_json(written).dump(2);
      const ResultJson read = parse_result_json(nlohmann::json::parse(text), "r.json");
      SCOPED_TRACE(text);
      expect_same(read, written);
      EXPECT_EQ(result_to_json(read).dump(2), text);
    }
  }
}

TEST(ResultJson, KeysAreThoseOfDesignSection6) {
  std::mt19937 rng(3);
  const nlohmann::json e = result_to_json(random_result(ResultJson::Kind::kEvaluation, rng));
  for (const char* key : {"format",
                          "status",
                          "motion",
                          "motion_file",
                          "model",
                          "samples",
                          "knots_per_interval",
                          "flight_time_s",
                          "keyframes",
                          "iterations",
                          "solve_seconds",
                          "variables",
                          "constraints",
                          "before",
                          "after",
                          "keyframe_times_before",
                          "keyframe_times_after",
                          "max_translation_error_m",
                          "max_quaternion_error",
                          "max_rotation_error_deg",
                          "takeoff_angular_momentum",
                          "residual_check",
                          "clearance",
                          "joint_strength",
                          "sparse_twist_intervals"})
    EXPECT_TRUE(e.contains(key)) << key;
  // "entry" for dives only.
  EXPECT_EQ(e.contains("entry"), e["clearance"]["apparatus"] == "platform");
  EXPECT_EQ(e.size(), 25u + e.contains("entry")) << e.dump();
  for (const char* key :
       {"coordinate", "direction", "words", "share", "time_s", "moment_Nm", "capacity_Nm",
        "angle_deg", "shortening_speed_rad_s", "extrapolated", "source"})
    EXPECT_TRUE(e["joint_strength"]["before"]["joints"]["knee_l"].contains(key)) << key;
  EXPECT_TRUE(e["joint_strength"]["before"]["verdict"].is_string());
  EXPECT_FALSE(e["joint_strength"].contains("after"));
  EXPECT_TRUE(e["after"].is_null());
  EXPECT_TRUE(e["iterations"].is_null());
  EXPECT_TRUE(e["samples"].is_number_integer());
  const nlohmann::json o = result_to_json(random_result(ResultJson::Kind::kOptimization, rng));
  for (const char* key :
       {"knots_per_interval_requested", "ipopt_status", "restarts", "formulation",
        "timing_optimized", "tolerances", "joint_turn_limit_deg", "largest_joint_turn_deg",
        "resolution", "keyframe_time_spread_s", "keyframe_times_undetermined", "joint_strength"})
    EXPECT_TRUE(o.contains(key)) << key;
  EXPECT_TRUE(o["joint_strength"]["after"]["verdict"].is_string());
  for (const char* key : {"automatic", "subdivisions", "knots", "levels"})
    EXPECT_TRUE(o["resolution"].contains(key)) << key;
  EXPECT_TRUE(o["resolution"]["automatic"].is_boolean());
  EXPECT_TRUE(o["resolution"]["levels"].is_array());
  EXPECT_FALSE(e.contains("resolution"));
  EXPECT_FALSE(o.contains("takeoff_angular_momentum"));
  EXPECT_TRUE(o["residual_check"].contains("optimizer_agrees"));
  for (const char* stage : {"before", "after"})
    EXPECT_EQ(o[stage]["optimizer_avg_root_force"].get<double>(),
              std::sqrt(o[stage]["optimizer_objective"].get<double>() / 6.0));
  const nlohmann::json s = result_to_json(random_result(ResultJson::Kind::kSimulation, rng));
  for (const char* key : {"takeoff_angular_momentum_source", "angular_momentum_spread", "landing"})
    EXPECT_TRUE(s.contains(key)) << key;
  EXPECT_TRUE(s["landing"].contains("root_vs_motion_deg"));
  EXPECT_FALSE(s.contains("residual_check"));
  EXPECT_EQ(o.contains("epsilon"), o["formulation"] == "strict");
  EXPECT_TRUE(o["iterations"].is_number_integer());
  EXPECT_TRUE(o["joint_turn_limit_deg"].is_number_float());
}

TEST(ResultJson, OlderOptimisationResultsWithoutTheLaterKeysStillRead) {
  std::mt19937 rng(5);
  nlohmann::json j = result_to_json(random_result(ResultJson::Kind::kOptimization, rng));
  for (const char* key : {"restarts", "tolerances", "largest_joint_turn_deg", "ipopt_status",
                          "joint_strength", "knots_per_interval_requested", "joint_turn_limit_deg",
                          "formulation", "timing_optimized", "epsilon", "residual_check",
                          "resolution", "keyframe_time_spread_s", "keyframe_times_undetermined"})
    j.erase(key);
  for (const char* stage : {"before", "after"})
    for (const char* key : {"optimizer_objective", "optimizer_avg_root_force"})
      j[stage].erase(key);
  const ResultJson r = parse_result_json(j, "old.json");
  EXPECT_EQ(r.kind, ResultJson::Kind::kOptimization);
  ASSERT_TRUE(r.optimization);
  EXPECT_FALSE(r.optimization->restarts);
  EXPECT_FALSE(r.optimization->tolerances);
  EXPECT_FALSE(r.optimization->optimizer_objective_after);
  EXPECT_FALSE(r.optimization->resolution);
  EXPECT_FALSE(r.optimization->keyframe_time_spreads);
  EXPECT_FALSE(r.residual_check);
  EXPECT_FALSE(r.option("formulation"));
  ASSERT_TRUE(r.option("samples"));
  EXPECT_EQ(result_to_json(r), j);
}

TEST(ResultJson, BadDocumentsNameTheField) {
  std::mt19937 rng(9);
  const nlohmann::json good = result_to_json(random_result(ResultJson::Kind::kOptimization, rng));
  auto expect_error = [](const nlohmann::json& j, const std::string& field) {
    try {
      parse_result_json(j, "bad.json");
      ADD_FAILURE() << "accepted, expected an error at " << field;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  nlohmann::json j = good;
  j["format"] = "saltus-study/1";
  expect_error(j, "/format");
  j = good;
  j["samples"] = 1;
  expect_error(j, "/samples");
  j = good;
  j["formulation"] = "loose";
  expect_error(j, "/formulation");
  j = good;
  j["timing_optimized"] = "yes";
  expect_error(j, "/timing_optimized");
  j = good;
  j["after"].erase("max_force_N");
  expect_error(j, "/after");
  j = good;
  j["after"] = nullptr;
  expect_error(j, "/after");
  j = good;
  j["keyframe_times_before"] = "0, 1";
  expect_error(j, "/keyframe_times_before");
  j = good;
  j["resolution"]["subdivisions"] = {1, 0, 2};
  expect_error(j, "/resolution/subdivisions/1");
  j = good;
  j["keyframe_times_undetermined"] = {1, -1};
  expect_error(j, "/keyframe_times_undetermined/1");
  j = good;
  j["resolution"]["automatic"] = "auto";
  expect_error(j, "/resolution/automatic");
  j = good;
  j["resolution"]["levels"] = {{{"subdivisions", {1}}, {"avg_root_force", 1.0}}};
  expect_error(j, "/resolution/levels/0");
  j = good;
  j["resolution"].erase("knots");
  expect_error(j, "/resolution");
  j = good;
  j["clearance"] = {{"apparatus", "springboard"}};
  expect_error(j, "/clearance/apparatus");
  j = good;
  j["entry"] = {{"time_s", 1.0}};
  expect_error(j, "/entry");
  expect_error(nlohmann::json::array(), "bad.json");
}

/// The motion's samples as the trajectory CSV holds them (rotations in one hemisphere).
void expect_trajectory(const TrajectoryCsv& csv, const std::vector<SampleRecord>& samples,
                       const BodyModel& model) {
  ASSERT_EQ(csv.samples.size(), samples.size());
  ASSERT_EQ(csv.segments.size(), static_cast<std::size_t>(model.size()));
  for (int s = 0; s < model.size(); ++s)
    EXPECT_EQ(csv.segments[s], model.segments[s].name);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    EXPECT_EQ(csv.samples[k].time, samples[k].time);
    EXPECT_EQ(csv.samples[k].root_wrench, samples[k].root_wrench);
    EXPECT_EQ(csv.samples[k].residual, samples[k].residual);
    EXPECT_EQ(csv.samples[k].com, samples[k].com);
    for (int s = 0; s < model.size(); ++s) {
      EXPECT_EQ(csv.samples[k].segment_position[s], samples[k].segment_position[s]);
      Eigen::Quaterniond q = samples[k].segment_rotation[s];
      if (q.w() < 0) q.coeffs() = -q.coeffs();
      EXPECT_EQ(csv.samples[k].segment_rotation[s].coeffs(), q.coeffs());
    }
  }
}

TEST(ResultFolder, EvaluationAndSimulationFoldersReadBack) {
  const MotionFile file = load_motion_file(m1_path());
  EvaluateOptions options;
  options.samples = 21;
  options.interpolation.knots_per_interval = 2;
  TempDir dir("saltus_result_json_test_eval");
  const MotionEvaluation e = evaluate_motion(file.motion, file.model, options);
  write_evaluation_outputs((dir.path / "e").string(), file, e, options);
  const ResultFolder f = read_result_folder((dir.path / "e/").string());
  EXPECT_EQ(f.name, "e");
  expect_same(f.result, evaluation_result(file, e, options));
  EXPECT_EQ(f.result.option("samples"), OptionValue(21));
  EXPECT_EQ(f.result.knots_per_interval, 2);
  EXPECT_FALSE(f.after);
  expect_trajectory(f.before, e.samples, file.model);

  const SimulationResult s = simulate_motion(file.motion, file.model, options);
  write_simulation_outputs((dir.path / "s").string(), file, s, options);
  const ResultFolder g = read_result_folder((dir.path / "s").string());
  EXPECT_EQ(g.result.kind, ResultJson::Kind::kSimulation);
  expect_same(g.result, simulation_result(file, s, options));
  expect_trajectory(g.before, s.samples, file.model);
}

TEST(ResultFolder, OptimisationFolderReadsBack) {
  const MotionFile file = load_motion_file(m1_path());
  OptionValues values;
  values.set("samples", 21);
  values.set("max_iterations", 2);
  values.set("formulation", std::string("strict"));
  const OptimizeOptions options = values.optimize_options();
  const OptimizationResult result = optimize_motion(file.motion, file.model, options);
  TempDir dir("saltus_result_json_test_opt");
  write_optimization_outputs(dir.path.string(), file, result, options);
  const ResultFolder f = read_result_folder(dir.path.string());
  expect_same(f.result, optimization_result(file, result, options));
  EXPECT_EQ(f.result.option("epsilon"), values.get("epsilon"));
  EXPECT_EQ(f.result.option("timing_optimized"), OptionValue(true));
  ASSERT_TRUE(f.after);
  expect_trajectory(f.before, result.before.samples, file.model);
  expect_trajectory(*f.after, result.after.samples, file.model);

  // The strict model has no automatic resolution: its knots are the uniform ones.
  ASSERT_TRUE(f.result.optimization->resolution);
  EXPECT_FALSE(f.result.optimization->resolution->automatic);
  EXPECT_EQ(f.result.optimization->resolution->knots,
            result.after.trajectory.rotations.front().knots());

  fs::remove(dir.path / "trajectory_after.csv");
  EXPECT_THROW(read_result_folder(dir.path.string()), InputError);
  EXPECT_THROW(read_result_folder((dir.path / "nothing").string()), InputError);
}

TEST(ResultFolder, ResolutionReadsBackAutomaticOrUniform) {
  const MotionFile file = load_motion_file(m1_path());
  const int intervals = static_cast<int>(file.motion.keyframes.size()) - 1;
  for (const std::string knots : {"auto", "2"}) {
    SCOPED_TRACE(knots);
    OptionValues values;
    values.set("samples", 21);
    values.set("max_iterations", 2);
    values.set_text("knots_per_interval", knots);
    const OptimizeOptions options = values.optimize_options();
    const OptimizationResult result = optimize_motion(file.motion, file.model, options);
    TempDir dir("saltus_result_json_test_resolution_" + knots);
    write_optimization_outputs(dir.path.string(), file, result, options);
    const ResultFolder f = read_result_folder(dir.path.string());
    expect_same(f.result, optimization_result(file, result, options));
    ASSERT_TRUE(f.result.optimization->resolution);
    const auto& r = *f.result.optimization->resolution;
    EXPECT_EQ(r.automatic, knots == "auto");
    ASSERT_EQ(r.subdivisions.size(), static_cast<std::size_t>(intervals));
    // The knots are those of the optimised motion, one clamped cubic over the spans.
    EXPECT_EQ(r.knots, result.after.trajectory.rotations.front().knots());
    int spans = 0;
    for (int s : r.subdivisions)
      spans += s;
    EXPECT_EQ(r.knots.size(), static_cast<std::size_t>(spans + 7));
    if (knots == "auto") {
      ASSERT_FALSE(r.levels.empty());
      EXPECT_EQ(r.levels.back().subdivisions.size(), r.subdivisions.size());
    } else {
      EXPECT_EQ(r.subdivisions, std::vector<int>(intervals, 2));
    }
    EXPECT_EQ(f.result.option("knots_per_interval_requested"),
              OptionValue(knots == "auto" ? 1 : 2));
  }
}

MotionFile pike_file() {
  MotionFile file;
  file.model = test::bundled_model();
  file.motion = test::pike_motion(file.model);
  file.path = "pike.motion.json";
  return file;
}

TEST(ResultJson, EvaluationFiguresAgreeWithTheTrajectoryCsv) {
  const MotionFile file = pike_file();
  EvaluateOptions options;
  options.samples = 57;
  const MotionEvaluation evaluation = evaluate_motion(file.motion, file.model, options);
  test::TempDir dir;
  const nlohmann::json written = write_evaluation_outputs(dir / "out", file, evaluation, options);
  const nlohmann::json result = nlohmann::json::parse(test::read_text(dir / "out/result.json"));
  EXPECT_EQ(result, written);
  EXPECT_EQ(result["format"], "saltus-result/1");
  EXPECT_EQ(result["samples"], 57);
  EXPECT_EQ(result["keyframes"], 4);
  EXPECT_EQ(result["motion_file"], "pike.motion.json");
  EXPECT_TRUE(result["after"].is_null());
  const CsvTable csv = read_csv_table(dir / "out/trajectory.csv");
  ASSERT_EQ(csv.rows.size(), 57u);
  const int t = csv.column("t"), f = csv.column("root_fx"), m = csv.column("root_mx");
  double force = 0, moment = 0, peak = 0;
  for (std::size_t k = 0; k < csv.rows.size(); ++k) {
    const auto& row = csv.rows[k];
    const double f2 = row[f] * row[f] + row[f + 1] * row[f + 1] + row[f + 2] * row[f + 2];
    const double m2 = row[m] * row[m] + row[m + 1] * row[m + 1] + row[m + 2] * row[m + 2];
    peak = std::max(peak, std::sqrt(f2));
    if (k == 0) continue;
    const auto& prev = csv.rows[k - 1];
    const double pf2 = prev[f] * prev[f] + prev[f + 1] * prev[f + 1] + prev[f + 2] * prev[f + 2];
    const double pm2 = prev[m] * prev[m] + prev[m + 1] * prev[m + 1] + prev[m + 2] * prev[m + 2];
    force += 0.5 * (row[t] - prev[t]) * (f2 + pf2);
    moment += 0.5 * (row[t] - prev[t]) * (m2 + pm2);
  }
  const double duration = csv.rows.back()[t];
  const nlohmann::json& before = result["before"];
  // The figures are the evaluation's dense check, written to the last digit; the CSV's 57
  // samples integrate the same wrench more coarsely, so agree to a few per cent.
  EXPECT_EQ(before["objective"].get<double>(), evaluation.metrics.objective);
  EXPECT_EQ(before["rms_force_N"].get<double>(), evaluation.metrics.rms_force_N);
  EXPECT_EQ(before["max_force_N"].get<double>(), evaluation.metrics.max_force_N);
  EXPECT_NEAR(before["objective"].get<double>(), (force + moment) / duration,
              0.03 * (force + moment) / duration);
  EXPECT_NEAR(before["rms_force_N"].get<double>(), std::sqrt(force / duration),
              0.03 * std::sqrt(force / duration));
  EXPECT_NEAR(before["max_force_N"].get<double>(), peak, 0.03 * peak);
  EXPECT_NEAR(before["avg_root_force"].get<double>(),
              std::sqrt(before["objective"].get<double>() / 6), 1e-12);
  std::vector<double> times;
  for (const Keyframe& k : file.motion.keyframes)
    times.push_back(k.time);
  EXPECT_EQ(result["keyframe_times_before"].get<std::vector<double>>(), times);
}

TEST(ResultJson, SimulationNamesItsMomentumAndLanding) {
  MotionFile file = pike_file();
  file.motion.takeoff.angular_momentum = Eigen::Vector3d(25, 0, 0);
  const SimulationResult simulation = simulate_motion(file.motion, file.model, {});
  test::TempDir dir;
  const nlohmann::json result = write_simulation_outputs(dir / "sim", file, simulation, {});
  EXPECT_EQ(result["takeoff_angular_momentum_source"], "motion file");
  EXPECT_EQ(result["takeoff_angular_momentum"], nlohmann::json::array({25.0, 0.0, 0.0}));
  EXPECT_EQ(result["landing"]["joint_error_deg"].size(),
            static_cast<std::size_t>(file.model.size()));
  EXPECT_EQ(result["landing"]["root_error_deg"].get<double>(), simulation.landing_root_error_deg);
  EXPECT_TRUE(result["max_quaternion_error"].is_null());
  EXPECT_EQ(read_csv_table(dir / "sim/trajectory.csv").rows.size(), simulation.samples.size());
}

}  // namespace
}  // namespace saltus
