// The command-line contract (docs/formats.md, issue "physics core"): outputs on success; on bad
// input exit status 2, one message naming the file and the field, and nothing left behind.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "saltus/evaluation/apparatus.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/output_kind.h"
#include "saltus/formats/trajectory_csv.h"
#include "saltus/studies/exact_flights.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;
using test::read_json;
using test::run_cli;
using test::TempDir;

nlohmann::json m1_json() {
  return read_json(test::m1_path());
}

/// Only the given names exist in the folder: no temporary folders or partial files.
void expect_folder_holds_only(const fs::path& folder, std::set<std::string> names) {
  std::set<std::string> found;
  for (const auto& entry : fs::directory_iterator(folder))
    found.insert(entry.path().filename().string());
  EXPECT_EQ(found, names);
}

TEST(Cli, HelpOnEveryVerb) {
  for (const char* verb : {"evaluate", "simulate"}) {
    const auto run = run_cli(std::string(verb) + " --help");
    EXPECT_EQ(run.status, 0) << verb;
    EXPECT_NE(run.output.find("--out"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("--samples"), std::string::npos) << run.output;
  }
  const auto top = run_cli("--help");
  EXPECT_EQ(top.status, 0);
  EXPECT_NE(top.output.find("evaluate"), std::string::npos);
  EXPECT_NE(top.output.find("simulate"), std::string::npos);
}

TEST(Cli, UsageErrorsExitWithTwo) {
  EXPECT_EQ(run_cli("").status, 2);
  EXPECT_EQ(run_cli("frobnicate").status, 2);
  EXPECT_EQ(run_cli("evaluate " + test::m1_path()).status, 2);  // --out missing
  TempDir dir;
  const auto run =
      run_cli("evaluate " + test::m1_path() + " --out " + (dir / "out") + " --samples 1");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("--samples"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(Cli, EvaluateWritesTheDocumentedOutputs) {
  TempDir dir;
  const auto run =
      run_cli("evaluate " + test::m1_path() + " --out " + (dir / "out") + " --samples 101");
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("average root force"), std::string::npos) << run.output;
  expect_folder_holds_only(dir.path(), {"out"});
  expect_folder_holds_only(dir.path() / "out",
                           {"result.json", "trajectory.csv", "model.json", kFolderRecordName});
  const auto result = read_json(dir / "out/result.json");
  for (const char* key :
       {"status", "iterations", "solve_seconds", "variables", "constraints", "before", "after",
        "keyframe_times_before", "keyframe_times_after", "max_translation_error_m",
        "max_quaternion_error", "max_rotation_error_deg"})
    EXPECT_TRUE(result.contains(key)) << key;
  for (const char* key : {"objective", "avg_root_force", "rms_force_N", "rms_moment_Nm",
                          "max_force_N", "max_moment_Nm"})
    EXPECT_TRUE(result["before"][key].is_number()) << key;
  const double j = result["before"]["objective"];
  EXPECT_NEAR(result["before"]["avg_root_force"].get<double>(), std::sqrt(j / 6), 1e-12);
  EXPECT_EQ(result["keyframe_times_before"].size(), 5u);

  std::ifstream csv(dir / "out/trajectory.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("t,abdomen.x,abdomen.y,abdomen.z,abdomen.qw", 0), 0u) << header;
  EXPECT_NE(
      header.find(",com_x,com_y,com_z,root_fx,root_fy,root_fz,root_mx,root_my,root_mz,"
                  "res_fx,res_fy,res_fz,res_mx,res_my,res_mz,somersault_deg,tilt_deg,twist_deg"),
      std::string::npos);
  int rows = 0;
  for (std::string line; std::getline(csv, line);)
    ++rows;
  EXPECT_EQ(rows, 101);
  EXPECT_EQ(read_json(dir / "out/model.json")["name"], "zatsiorsky-66kg");
}

// The strength the CLI prints is result.json's: the verdict line, then one line per joint beyond
// the athlete's strength, largest first, each the share of result.json's entry for that joint;
// and every share is its moment over its capacity. M5's interpolated input needs more than the
// bundled athlete has at its elbow and shoulder; a junior made with `model new` has less still.
// The verdict "can this athlete land it?" is then amber or red, never green.
TEST(Cli, EvaluatePrintsTheJointsBeyondTheAthletesStrength) {
  TempDir dir;
  const std::string m5 = std::string(SALTUS_EXAMPLES_DIR) +
                         "/motions/M5-front-somersault-one-and-a-half-twists.motion.json";
  ASSERT_EQ(run_cli("model new --height 1.45 --mass 38 --sex female --age 13 --out " +
                    (dir / "junior.model.json") + " -q")
                .status,
            0);
  for (const std::string model : {std::string(), " --model " + (dir / "junior.model.json")}) {
    SCOPED_TRACE(model);
    const auto run = run_cli("evaluate " + m5 + model + " --out " + (dir / "out"));
    ASSERT_EQ(run.status, 0) << run.output;
    const auto strength = read_json(dir / "out/result.json")["joint_strength"];
    const auto& before = strength["before"];
    EXPECT_NE(run.output.find("  strength: " + before["verdict"].get<std::string>() + "\n"),
              std::string::npos)
        << run.output;
    int over = 0;
    for (const auto& [joint, e] : before["joints"].items()) {
      SCOPED_TRACE(joint);
      EXPECT_NEAR(e["share"].get<double>(),
                  e["moment_Nm"].get<double>() / e["capacity_Nm"].get<double>(), 1e-12);
      if (e["share"].get<double>() <= 1.0) continue;
      ++over;
      const std::string line = "    " + e["words"].get<std::string>() + " would need " +
                               std::to_string(std::lround(100 * e["share"].get<double>())) + " %";
      EXPECT_NE(run.output.find(line), std::string::npos) << line << "\n" << run.output;
    }
    EXPECT_GE(over, 1);
    EXPECT_NE(before["verdict"].get<std::string>().find(std::to_string(over) + " joint"),
              std::string::npos);
    // The one verdict the app shows too: with a joint beyond the athlete's strength never green,
    // and when it lands, it says which joints in the strength line's words.
    const std::size_t said = run.output.find("  can this athlete land it? ");
    ASSERT_NE(said, std::string::npos) << run.output;
    const std::string line = run.output.substr(said, run.output.find('\n', said) - said);
    EXPECT_EQ(line.find("? green:"), std::string::npos) << line;
    if (line.find("? amber: Lands it") != std::string::npos)
      EXPECT_NE(line.find(", but " + before["verdict"].get<std::string>()), std::string::npos)
          << line;
    else
      EXPECT_NE(line.find("? red: Does not land it"), std::string::npos) << line;
    std::filesystem::remove_all(dir / "out");
  }
}

// Keyframes too far apart for the twist (evaluation/keyframe_spacing.h): a hard twisting exact
// flight (2 twists on 7 keyframes) evaluated from its file has the interval in result.json and
// the CLI prints result.json's words; M1 has none.
TEST(Cli, EvaluateNamesTheKeyframesTooFarApartForTheTwist) {
  TempDir dir;
  const BodyModel model =
      load_body_model(std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json");
  save_motion_file(dir / "hard.motion.json", make_hard_twisting_flight(model, 12).motion, model);
  const auto run = run_cli("evaluate " + (dir / "hard.motion.json") + " --out " + (dir / "hard"));
  ASSERT_EQ(run.status, 0) << run.output;
  const auto intervals = read_json(dir / "hard/result.json")["sparse_twist_intervals"];
  ASSERT_FALSE(intervals.empty());
  for (const auto& interval : intervals) {
    EXPECT_GT(std::abs(interval["flight_twist_deg"].get<double>() -
                       interval["interpolation_twist_deg"].get<double>()),
              180.0);
    EXPECT_NE(run.output.find("  " + interval["words"].get<std::string>() + "\n"),
              std::string::npos)
        << run.output;
  }
  ASSERT_EQ(run_cli("evaluate " + test::m1_path() + " --out " + (dir / "m1")).status, 0);
  EXPECT_TRUE(read_json(dir / "m1/result.json")["sparse_twist_intervals"].empty());
}

TEST(Cli, SimulateReportsTheLanding) {
  TempDir dir;
  const auto run = run_cli("simulate " + test::m1_path() + " --out " + (dir / "sim"));
  ASSERT_EQ(run.status, 0) << run.output;
  const auto result = read_json(dir / "sim/result.json");
  ASSERT_TRUE(result.contains("landing"));
  EXPECT_EQ(result["landing"]["joint_error_deg"].size(), 13u);
  EXPECT_TRUE(result["landing"]["root_error_deg"].is_number());
  // A free flight needs no root force (up to integration error).
  EXPECT_LT(result["before"]["avg_root_force"].get<double>(), 1e-6);
}

/// The dive's closest pass to the platform, by brute force over the written trajectory.csv and
/// model.json: every segment origin and shape end against the platform's space (behind its front
/// edge, below its top, across its width), the platform placed as the app draws it, from the
/// CoM's highest row on.
double written_platform_clearance(const fs::path& folder, const nlohmann::json& motion) {
  const BodyModel model = load_body_model((folder / "model.json").string());
  const TrajectoryCsv csv = read_trajectory_csv((folder / "trajectory.csv").string());
  const auto points = [&](const SampleRecord& s) {
    std::vector<Eigen::Vector3d> out;
    for (std::size_t i = 0; i < model.segments.size(); ++i) {
      out.push_back(s.segment_position[i]);
      out.push_back(s.segment_position[i] +
                    s.segment_rotation[i] * Eigen::Vector3d(0, model.segments[i].shape.length, 0));
    }
    return out;
  };
  const auto lowest = [&](const SampleRecord& s) {
    double y = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& p : points(s))
      y = std::min(y, p.y());
    return y;
  };
  const double top = lowest(csv.samples.front()), water = lowest(csv.samples.back());
  const auto& takeoff = motion["takeoff"];
  const Eigen::Vector3d com(takeoff["com_position"][0], 0.0, takeoff["com_position"][2]);
  const Eigen::Vector3d ahead =
      Eigen::Vector3d(takeoff["com_velocity"][0], 0.0, takeoff["com_velocity"][2]).normalized();
  const Eigen::Vector3d side = Eigen::Vector3d::UnitY().cross(ahead);
  std::size_t apex = 0;
  for (std::size_t k = 0; k < csv.samples.size(); ++k)
    if (csv.samples[k].com.y() > csv.samples[apex].com.y()) apex = k;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = apex; k < csv.samples.size(); ++k)
    for (const Eigen::Vector3d& p : points(csv.samples[k])) {
      const double forward = (p - com).dot(ahead) - kPlatformEdgeAhead;  // > 0: ahead of the edge
      const double up = p.y() - top;
      const double across = std::abs((p - com).dot(side)) - 0.5 * kPlatformWidth;
      const double outside =
          std::sqrt(std::pow(std::max(forward, 0.0), 2) + std::pow(std::max(up, 0.0), 2) +
                    std::pow(std::max(across, 0.0), 2));
      best = std::min(best,
                      outside > 0.0 ? outside : -std::min({-forward, -up, -across, p.y() - water}));
    }
  return best;
}

TEST(Cli, EvaluateAndSimulateReportTheDivesClearanceAndEntry) {
  const std::string dive =
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/dive-5m-front-one-and-a-half-twists.motion.json";
  TempDir dir;
  std::string evaluate_output;
  for (const char* verb : {"evaluate", "simulate"}) {
    const auto run = run_cli(std::string(verb) + " " + dive + " --out " + (dir / verb));
    ASSERT_EQ(run.status, 0) << run.output;
    if (std::string(verb) == "evaluate") evaluate_output = run.output;
    EXPECT_NE(run.output.find("  closest to the platform: "), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("  entry: "), std::string::npos) << run.output;
    const auto result = read_json(dir / (std::string(verb) + "/result.json"));
    ASSERT_TRUE(result.contains("clearance")) << verb;
    ASSERT_TRUE(result.contains("entry")) << verb;
    const auto& c = result["clearance"];
    EXPECT_EQ(c["apparatus"], "platform");
    for (const char* key : {"from_s", "min_distance_m", "time_s", "behind_edge_m", "below_top_m"})
      EXPECT_TRUE(c[key].is_number()) << key;
    for (const char* key : {"segment", "point"})
      EXPECT_TRUE(c[key].is_string()) << key;
    EXPECT_EQ(c["collision"].get<bool>(), c["min_distance_m"].get<double>() < 0.0);
    // The same figure from the written trajectory, up to the CSV's printed digits.
    EXPECT_NEAR(c["min_distance_m"].get<double>(),
                written_platform_clearance(dir.path() / verb, read_json(dive)), 1e-5)
        << verb;
    const auto& e = result["entry"];
    for (const char* key : {"time_s", "com_height_m", "angle_to_vertical_deg"})
      EXPECT_TRUE(e[key].is_number()) << key;
    EXPECT_EQ(e["vertical"].get<bool>(), e["angle_to_vertical_deg"].get<double>() <= 10.0);
  }
  // The evaluated dive (its keyframes as they are) passes through the platform's space.
  const auto evaluated = read_json(dir / "evaluate/result.json");
  EXPECT_TRUE(evaluated["clearance"]["collision"].get<bool>());
  EXPECT_NE(evaluate_output.find("the body would strike the platform"), std::string::npos)
      << evaluate_output;
  // A trampoline skill reports the frame and no entry.
  const auto m1 = run_cli("evaluate " + test::m1_path() + " --out " + (dir / "m1"));
  ASSERT_EQ(m1.status, 0) << m1.output;
  EXPECT_NE(m1.output.find("  closest to the trampoline frame: clear by "), std::string::npos)
      << m1.output;
  EXPECT_EQ(m1.output.find("  entry: "), std::string::npos) << m1.output;
  const auto r = read_json(dir / "m1/result.json");
  EXPECT_EQ(r["clearance"]["apparatus"], "trampoline");
  EXPECT_TRUE(r["clearance"]["inside_bed_edge_m"].is_number());
  EXPECT_TRUE(r["clearance"]["above_frame_m"].is_number());
  EXPECT_FALSE(r.contains("entry"));
}

TEST(Cli, ReplacesAnEarlierResultButNotOtherFolders) {
  TempDir dir;
  const std::string out = dir / "out";
  ASSERT_EQ(run_cli("evaluate " + test::m1_path() + " --out " + out + " --samples 50").status, 0);
  ASSERT_EQ(run_cli("evaluate " + test::m1_path() + " --out " + out + " --samples 60").status, 0);
  EXPECT_EQ(read_json(out + "/result.json")["samples"], 60);

  const std::string precious = dir / "precious";
  fs::create_directories(precious);
  test::write_text(precious + "/thesis.txt", "do not delete");
  const auto run = run_cli("evaluate " + test::m1_path() + " --out " + precious);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("not overwriting"), std::string::npos) << run.output;
  expect_folder_holds_only(precious, {"thesis.txt"});
}

/// A malformed-input case: how to spoil the M1 document, and what the message must name.
struct BadInput {
  const char* name;
  std::function<void(nlohmann::json& motion, nlohmann::json& model)> spoil;
  std::vector<std::string> message_parts;
  bool raw_text = false;  ///< write `raw` instead of the JSON
  const char* raw = "";
};

void PrintTo(const BadInput& input, std::ostream* os) {
  *os << input.name;
}

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, ExitsWithTwoNamesFileAndFieldLeavesNothing) {
  TempDir dir;
  nlohmann::json motion = m1_json();
  nlohmann::json model =
      read_json(std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json");
  motion["model"] = "my-model.json";  // relative to the motion file
  GetParam().spoil(motion, model);
  const std::string motion_path = dir / "bad.motion.json";
  if (GetParam().raw_text)
    test::write_text(motion_path, GetParam().raw);
  else
    test::write_text(motion_path, motion.dump(2));
  test::write_text(dir / "my-model.json", model.dump(2));

  for (const char* verb : {"evaluate", "simulate"}) {
    const auto run = run_cli(std::string(verb) + " " + motion_path + " --out " + (dir / "out"));
    EXPECT_EQ(run.status, 2) << verb << ": " << run.output;
    for (const auto& part : GetParam().message_parts)
      EXPECT_NE(run.output.find(part), std::string::npos)
          << verb << ": expected \"" << part << "\" in: " << run.output;
    // One clear message, not a crash dump.
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    expect_folder_holds_only(dir.path(), {"bad.motion.json", "my-model.json"});
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliBadInput,
    ::testing::Values(
        BadInput{"syntax",
                 [](auto&, auto&) {},
                 {"bad.motion.json", "invalid JSON", "line"},
                 true,
                 "{ \"format\": \"saltus-motion/1\", \"keyframes\": [ }"},
        BadInput{
            "nan_literal",
            [](auto&, auto&) {},
            {"bad.motion.json", "invalid JSON"},
            true,
            "{ \"format\": \"saltus-motion/1\", \"takeoff\": { \"com_position\": [NaN, 1, 0] } }"},
        BadInput{"wrong_type",
                 [](auto& m, auto&) { m["takeoff"]["com_velocity"][1] = "fast"; },
                 {"bad.motion.json", "/takeoff/com_velocity/1", "number"}},
        BadInput{"unsorted_times",
                 [](auto& m, auto&) { m["keyframes"][2]["time"] = 0.3; },
                 {"bad.motion.json", "/keyframes/2/time"}},
        BadInput{"missing_joint",
                 [](auto& m, auto&) { m["keyframes"][1]["rotations"].erase("knee_l"); },
                 {"bad.motion.json", "/keyframes/1/rotations", "knee_l"}},
        BadInput{"unknown_joint",
                 [](auto& m, auto&) {
                   m["keyframes"][3]["rotations"]["tail"] = {1, 0, 0, 0};
                 },
                 {"bad.motion.json", "/keyframes/3/rotations", "tail"}},
        BadInput{"non_unit_quaternion",
                 [](auto& m, auto&) {
                   m["keyframes"][0]["rotations"]["hip_r"] = {1.2, 0, 0, 0};
                 },
                 {"bad.motion.json", "/keyframes/0/rotations/hip_r", "norm"}},
        BadInput{"negative_mass",
                 [](auto&, auto& model) { model["segments"][4]["mass"] = -1.1; },
                 {"my-model.json", "/segments/4/mass"}},
        BadInput{"unknown_parent",
                 [](auto&, auto& model) { model["segments"][5]["parent"] = "tail"; },
                 {"my-model.json", "/segments/5/parent", "tail"}},
        BadInput{"missing_model",
                 [](auto& m, auto&) { m["model"] = "no-such-model"; },
                 {"bad.motion.json", "/model", "no-such-model"}}),
    [](const ::testing::TestParamInfo<BadInput>& param_info) {
      return std::string(param_info.param.name);
    });

TEST(Cli, MissingMotionFileIsNamed) {
  TempDir dir;
  const auto run = run_cli("evaluate " + (dir / "nope.motion.json") + " --out " + (dir / "out"));
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("nope.motion.json"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace saltus
