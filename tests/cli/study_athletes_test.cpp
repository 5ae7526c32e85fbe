// `saltus study athletes` as a program: M1 on the junior (1.45 m, 38 kg, female) and
// senior (1.85 m, 85 kg, male). Every number of the table is checked against the verbs run
// separately on each athlete (`simulate` and `optimize --model`, `model info`), the take-off
// angular momenta against dimensional analysis, and bad input exits 2 writing nothing.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.h"

namespace saltus {
namespace {

/// athletes.csv as rows of named text fields.
std::vector<std::map<std::string, std::string>> athletes_csv_rows(const std::string& path) {
  std::istringstream in(test::read_text(path));
  std::string line;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  auto split = [](const std::string& text) {
    std::vector<std::string> fields;
    std::string field;
    std::istringstream s(text);
    while (std::getline(s, field, ','))
      fields.push_back(field);
    if (!text.empty() && text.back() == ',') fields.push_back("");
    return fields;
  };
  std::getline(in, line);
  header = split(line);
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = split(line);
    EXPECT_EQ(fields.size(), header.size()) << line;
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i)
      row[header[i]] = fields[i];
    rows.push_back(row);
  }
  return rows;
}

double number_of(const std::map<std::string, std::string>& row, const std::string& column) {
  return std::stod(row.at(column));
}

/// The largest peak over the joints of an optimize result.json (`what`: "peak_moment_Nm", ...).
std::pair<std::string, double> largest_joint_peak(const nlohmann::json& result,
                                                  const std::string& what) {
  std::pair<std::string, double> largest{"", -1.0};
  for (const auto& [joint, loads] : result.at("joint_loads").items())
    if (loads.at("after").at(what).get<double>() > largest.second)
      largest = {joint, loads.at("after").at(what).get<double>()};
  return largest;
}

/// The joint whose peak after over its peak before (force or moment, each at least 10 N / 1 N·m,
/// as the CLI counts it) is largest in an optimize result.json, and that ratio.
std::pair<std::string, double> largest_joint_rise(const nlohmann::json& result) {
  std::pair<std::string, double> largest{"", -1.0};
  for (const auto& item : result.at("joint_loads").items()) {
    const nlohmann::json& loads = item.value();  // not a structured binding: lambdas capture it
    const auto ratio = [&](const char* key, double floor) {
      return std::max(loads.at("after").at(key).get<double>(), floor) /
             std::max(loads.at("before").at(key).get<double>(), floor);
    };
    const double rise = std::max(ratio("peak_force_N", 10.0), ratio("peak_moment_Nm", 1.0));
    if (rise > largest.second) largest = {item.key(), rise};
  }
  return largest;
}

TEST(CliStudyAthletes, TheTableIsWhatTheVerbsGiveOnEachAthlete) {
  test::TempDir dir;
  const std::string junior = dir / "junior.model.json", senior = dir / "senior.model.json";
  ASSERT_EQ(test::run_cli("model new --height 1.45 --mass 38 --sex female --name junior --out " +
                          junior + " -q")
                .status,
            0);
  ASSERT_EQ(test::run_cli("model new --height 1.85 --mass 85 --sex male --name senior --out " +
                          senior + " -q")
                .status,
            0);
  const std::string out = dir / "study";
  const auto study = test::run_cli("study athletes " + test::m1_path() + " --models " + junior +
                                   " " + senior + " --out " + out + " --jobs 2");
  ASSERT_EQ(study.status, 0) << study.output;
  EXPECT_NE(study.output.find("| junior |"), std::string::npos) << study.output;
  for (const char* name : {"athletes.md", "athletes.csv", "result.json", "study.json", "cases"})
    EXPECT_TRUE(std::filesystem::exists(out + "/" + name)) << name;
  const nlohmann::json result = test::read_json(out + "/result.json");
  EXPECT_EQ(result["study"], "athletes");
  EXPECT_EQ(result["failed"], 0);
  ASSERT_EQ(result["cases"].size(), 3u);

  const auto rows = athletes_csv_rows(out + "/athletes.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].at("athlete"), "zatsiorsky-66kg");  // the motion's own model first
  EXPECT_EQ(rows[0].at("takeoff"), "own model");
  std::map<std::string, double> momentum;
  for (const auto& row : rows) {
    const std::string athlete = row.at("athlete");
    SCOPED_TRACE(athlete);
    const std::string model = athlete == "junior"   ? junior
                              : athlete == "senior" ? senior
                                                    : std::string("zatsiorsky-66kg");
    const std::string model_flag = athlete == "zatsiorsky-66kg" ? "" : " --model " + model;
    const auto info = test::run_cli("model info " + model + " --json");
    ASSERT_EQ(info.status, 0) << info.output;
    const nlohmann::json size = nlohmann::json::parse(info.output);
    EXPECT_NEAR(number_of(row, "mass_kg"), size["total_mass_kg"].get<double>(), 1e-8);
    EXPECT_NEAR(number_of(row, "height_m"), size["standing_height_m"].get<double>(), 1e-8);

    // The motion as given: `saltus simulate` on this athlete.
    const std::string sim = dir / ("sim-" + athlete);
    ASSERT_EQ(
        test::run_cli("simulate " + test::m1_path() + model_flag + " --out " + sim + " -q").status,
        0);
    const nlohmann::json flown = test::read_json(sim + "/result.json");
    const nlohmann::json& l = flown["takeoff_angular_momentum"];
    EXPECT_NEAR(number_of(row, "takeoff_L_x"), l[0].get<double>(), 1e-6);
    EXPECT_NEAR(number_of(row, "takeoff_L_y"), l[1].get<double>(), 1e-6);
    EXPECT_NEAR(number_of(row, "takeoff_L_z"), l[2].get<double>(), 1e-6);
    momentum[athlete] = std::hypot(l[0].get<double>(), l[1].get<double>(), l[2].get<double>());
    EXPECT_NEAR(number_of(row, "landing_error_before_deg"),
                flown["landing"]["root_error_deg"].get<double>(), 1e-6);
    EXPECT_NEAR(number_of(row, "somersaults_before"),
                flown["rotation"]["before"]["somersaults"].get<double>(), 1e-8);
    EXPECT_NEAR(number_of(row, "twists_before"),
                flown["rotation"]["before"]["twists"].get<double>(), 1e-8);

    // Optimised: `saltus optimize --model` on this athlete, then its optimised motion flown.
    const std::string opt = dir / ("opt-" + athlete);
    ASSERT_EQ(
        test::run_cli("optimize " + test::m1_path() + model_flag + " --out " + opt + " -q").status,
        0);
    const nlohmann::json optimized = test::read_json(opt + "/result.json");
    const double before = optimized["before"]["avg_root_force"].get<double>();
    const double after = optimized["after"]["avg_root_force"].get<double>();
    EXPECT_NEAR(number_of(row, "avg_force_before_N"), before, 1e-6 * before);
    EXPECT_NEAR(number_of(row, "avg_force_after_N"), after, 1e-3 * after + 1e-4);
    EXPECT_EQ(row.at("status"), optimized["status"].get<std::string>());
    EXPECT_LT(after, 0.5) << "M1 made physical on " << athlete;
    EXPECT_GT(before, 10.0 * after);
    const auto moment = largest_joint_peak(optimized, "peak_moment_Nm");
    const auto force = largest_joint_peak(optimized, "peak_force_pct_bw");
    EXPECT_EQ(row.at("peak_moment_joint"), moment.first);
    EXPECT_NEAR(number_of(row, "peak_moment_Nm"), moment.second, 1e-3 * moment.second);
    EXPECT_EQ(row.at("peak_force_joint"), force.first);
    EXPECT_NEAR(number_of(row, "peak_force_pct_bw"), force.second, 1e-3 * force.second);
    const auto rise = largest_joint_rise(optimized);
    EXPECT_EQ(row.at("joint_rise_joint"), rise.first);
    EXPECT_NEAR(number_of(row, "joint_rise"), rise.second, 1e-3 * rise.second);

    const std::string landed = dir / ("sim-opt-" + athlete);
    ASSERT_EQ(
        test::run_cli("simulate " + opt + "/optimized.motion.json --out " + landed + " -q").status,
        0);
    const nlohmann::json flight = test::read_json(landed + "/result.json");
    EXPECT_EQ(flight["model"], athlete);
    EXPECT_NEAR(number_of(row, "landing_error_after_deg"),
                flight["landing"]["root_error_deg"].get<double>(), 1e-3);
    EXPECT_NEAR(number_of(row, "somersaults_after"),
                flight["rotation"]["before"]["somersaults"].get<double>(), 1e-4);
    EXPECT_NEAR(number_of(row, "twists_after"),
                flight["rotation"]["before"]["twists"].get<double>(), 1e-4);
    // The optimised M1 is one back somersault on every athlete, and so is its free flight (which
    // may pick up some twist: docs/studies.md, "Athletes").
    EXPECT_NEAR(optimized["rotation"]["after"]["somersaults"].get<double>(), -1.0, 0.02);
    EXPECT_NEAR(optimized["rotation"]["after"]["twists"].get<double>(), 0.0, 0.02);
    EXPECT_NEAR(number_of(row, "somersaults_after"), -1.0, 0.05);
  }
  // Same spin: L = I·ω with ω the same, and I of a body ~ m·h² (dimensional analysis; de Leva's
  // women and men differ in proportions, hence the tolerance).
  const double expected = (85.0 * 1.85 * 1.85) / (38.0 * 1.45 * 1.45);
  EXPECT_NEAR(momentum["senior"] / momentum["junior"], expected, 0.2 * expected);

  // Complete: --resume runs nothing; the records alone rebuild the same table.
  const auto again = test::run_cli("study athletes " + test::m1_path() + " --models " + junior +
                                   " " + senior + " --out " + out + " --resume");
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("nothing to run"), std::string::npos) << again.output;
  // Another study into the same folder replaces it (Saltus wrote it).
  const auto other = test::run_cli("study athletes " + test::m1_path() + " --models " + junior +
                                   " --out " + out + " -q --takeoff keep-momentum");
  EXPECT_EQ(other.status, 0) << other.output;
  EXPECT_EQ(test::read_json(out + "/result.json")["cases"].size(), 2u);
  EXPECT_EQ(test::read_json(out + "/result.json")["takeoff"], "keep-momentum");
}

TEST(CliStudyAthletes, BadAthletesExitWithTwoAndWriteNothing) {
  test::TempDir dir;
  const std::string out = dir / "study";
  const auto missing =
      test::run_cli("study athletes " + test::m1_path() + " --models no-such-athlete --out " + out);
  EXPECT_EQ(missing.status, 2) << missing.output;
  EXPECT_NE(missing.output.find("no-such-athlete"), std::string::npos) << missing.output;
  const auto twice =
      test::run_cli("study athletes " + test::m1_path() + " --models zatsiorsky-66kg --out " + out);
  EXPECT_EQ(twice.status, 2) << twice.output;
  EXPECT_NE(twice.output.find("--models"), std::string::npos) << twice.output;
  const auto rule = test::run_cli("study athletes " + test::m1_path() +
                                  " --models zatsiorsky-66kg --takeoff same --out " + out);
  EXPECT_EQ(rule.status, 2) << rule.output;
  EXPECT_NE(rule.output.find("--takeoff"), std::string::npos) << rule.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(out + ".partial"));
}

}  // namespace
}  // namespace saltus
