// `saltus export --format opensim` read back by an independent reader (OpenSim is not packaged
// for Debian): tests/support/opensim_pose.py, Python with xml.etree and numpy and nothing of
// Saltus's, reads model.osim, coordinates.mot and inverse_dynamics.sto as OpenSim 4 defines them,
// takes each coordinate's motion type as OpenSim 4.0 does (slope +1 or not a rotation), rebuilds
// every body's pose at every row and finds it where `saltus evaluate` puts the segment
// (its trajectory.csv at the same times) to 1 mm and 0.1°, every mass, CoM and inertia equal to
// model.json's, and the root's six generalised forces equal to the CSV's root wrench. A tucked
// somersault reads as a biomechanist expects: hips and knees flexed past 90°. The folder is
// replaced only when Saltus wrote it.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.h"

namespace saltus::test {
namespace {

namespace fs = std::filesystem;

std::string example(const std::string& name) {
  return std::string(SALTUS_EXAMPLES_DIR) + "/motions/" + name + ".motion.json";
}

/// What opensim_pose.py found for the export of `motion` against `saltus evaluate` of it.
nlohmann::json independent_reading(const std::string& motion, const TempDir& dir) {
  const std::string out = dir / "opensim";
  CliRun run = run_cli("export " + motion + " --format opensim --quiet --out " + out);
  EXPECT_EQ(run.status, 0) << run.output;
  const int frames = read_json(out + "/result.json")["frames"];
  run = run_cli("evaluate " + motion + " --quiet --samples " + std::to_string(frames) + " --out " +
                (dir / "evaluate"));
  EXPECT_EQ(run.status, 0) << run.output;
  const std::string script =
      (fs::path(SALTUS_TEST_DATA_DIR).parent_path() / "support/opensim_pose.py").string();
  run = run_command("timeout 120 /usr/bin/python3 " + script + " " + out + " " +
                    (dir / "evaluate/trajectory.csv") + " " + (dir / "evaluate/model.json"));
  EXPECT_EQ(run.status, 0) << run.output;
  const nlohmann::json found = nlohmann::json::parse(run.output, nullptr, false);
  EXPECT_TRUE(found.is_object()) << run.output;
  EXPECT_EQ(found["matched_rows"], frames) << "every row of the .mot at a time of the CSV";
  return found;
}

void expect_saltus_poses(const nlohmann::json& found) {
  SCOPED_TRACE(found.dump());
  EXPECT_LT(found["worst_position_m"].get<double>(), 1e-3);
  EXPECT_LT(found["worst_rotation_deg"].get<double>(), 0.1);
  EXPECT_LT(found["worst_mass_property_error"].get<double>(), 1e-12);
  EXPECT_LT(found["worst_root_force_error"].get<double>(),
            1e-6 * found["largest_root_force"].get<double>());
  EXPECT_EQ(found["bodies"].size(), 13u);
  // OpenSim 4.0 takes a coordinate as a rotation (its .mot degrees converted, its force named
  // _moment) only when its axis's function has slope +1: every angle here, and the three
  // translations as translations.
  EXPECT_EQ(found["motion_types"], nlohmann::json({{"Rotational", 39}, {"Translational", 3}}));
  EXPECT_EQ(found["misnamed_forces"], nlohmann::json::array());
  std::printf(
      "OpenSim files read back: bodies within %.2g m and %.2g deg, root forces within %.2g "
      "N\n",
      found["worst_position_m"].get<double>(), found["worst_rotation_deg"].get<double>(),
      found["worst_root_force_error"].get<double>());
}

TEST(ExportOpensim, AnIndependentReaderRebuildsSaltussPosesOnM7) {
  TempDir dir;
  const nlohmann::json found =
      independent_reading(example("M7-double-front-one-and-a-half-twists"), dir);
  expect_saltus_poses(found);
  const std::vector<std::string> names = found["coordinates"];
  for (const char* name :
       {"somersault", "tilt", "twist", "root_tx", "root_ty", "root_tz", "hip_flexion_r",
        "hip_adduction_l", "hip_rotation_r", "knee_flexion_l", "ankle_dorsiflexion_r",
        "lumbar_extension", "thoracic_rotation", "shoulder_flexion_l", "shoulder_adduction_r",
        "elbow_flexion_r", "elbow_pronation_l"})
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  EXPECT_EQ(names.size(), 42u) << "six for the root, three for each of the 12 joints";
}

TEST(ExportOpensim, AnIndependentReaderRebuildsSaltussPosesOnTheDive) {
  TempDir dir;
  expect_saltus_poses(independent_reading(example("dive-5m-front-one-and-a-half-twists"), dir));
}

/// The .mot's columns, read here: name → values over the rows.
std::map<std::string, std::vector<double>> mot_columns(const std::string& path) {
  std::istringstream in(read_text(path));
  std::string line;
  while (std::getline(in, line) && line != "endheader") {
  }
  std::vector<std::string> names;
  std::getline(in, line);
  std::istringstream header(line);
  for (std::string name; std::getline(header, name, '\t');)
    names.push_back(name);
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string value;
    for (std::size_t i = 0; i < names.size() && std::getline(row, value, '\t'); ++i)
      columns[names[i]].push_back(std::stod(value));
  }
  return columns;
}

TEST(ExportOpensim, ATuckReadsAsFlexedHipsAndKneesAndTheFolderIsSaltuss) {
  TempDir dir;
  const std::string out = dir / "m2";
  CliRun run =
      run_cli("export " + example("M2-tucked-back-somersault") + " --format opensim --out " + out);
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("42 coordinates"), std::string::npos) << run.output;
  const auto columns = mot_columns(out + "/coordinates.mot");
  for (const char* side : {"_l", "_r"}) {
    for (const char* joint : {"hip_flexion", "knee_flexion"}) {
      const std::vector<double>& v = columns.at(std::string(joint) + side);
      EXPECT_GT(*std::max_element(v.begin(), v.end()), 90.0) << joint << side << ", degrees";
    }
  }
  // A back somersault turns the root about its left axis backwards: one turn, −360° or so.
  const std::vector<double>& somersault = columns.at("somersault");
  EXPECT_LT(somersault.back() - somersault.front(), -300.0) << "continuous: counts the turn";
  for (std::size_t k = 1; k < somersault.size(); ++k)
    EXPECT_LT(std::abs(somersault[k] - somersault[k - 1]), 30.0) << "no jump of a turn";

  run = run_cli("export " + example("M2-tucked-back-somersault") + " --format opensim --quiet " +
                "--out " + out);
  EXPECT_EQ(run.status, 0) << "its own folder is replaced: " << run.output;
  const std::string mine = dir / "mine";
  fs::create_directories(mine);
  write_text(mine + "/subject01.osim", "<OpenSimDocument/>");
  run =
      run_cli("export " + example("M2-tucked-back-somersault") + " --format opensim --out " + mine);
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("subject01.osim"), std::string::npos) << run.output;
  EXPECT_EQ(names_in(mine), (std::set<std::string>{"subject01.osim"}));
}

}  // namespace
}  // namespace saltus::test
