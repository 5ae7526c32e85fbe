// The flight page's data (use_cases/flight_page.h), checked against what it was made from by
// other paths: the optimiser's samples in memory (the page reads the written CSVs), result.json
// parsed here, the take-off parabola by its closed form, the model's shapes; the page of an
// optimised M7 stays under 3 MB; bad sources name the file. A motion that came from `import`
// carries the capture: its poses and |F|, |M| read here from the import folder's trajectory.csv
// and result.json by a reader of this test's own.

#include "saltus/use_cases/flight_page.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/evaluation/apparatus.h"
#include "saltus/formats/finite_check.h"
#include "saltus/formats/flight_page.h"
#include "saltus/formats/motion_file.h"
#include "saltus/use_cases/captures.h"
#include "saltus/use_cases/result_folders.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

std::string bundled_motion(const std::string& name) {
  return std::string(SALTUS_EXAMPLES_DIR) + "/motions/" + name + ".motion.json";
}

/// An optimise folder of `name` after a few iterations (the page does not care how far).
OptimizationResult optimised_folder(const std::string& name, const std::string& dir, int samples,
                                    int iterations) {
  const MotionFile file = load_motion_file(bundled_motion(name));
  OptimizeOptions options;
  options.nlp.samples = samples;
  options.solver.max_iterations = iterations;
  OptimizationResult result = optimize_motion(file.motion, file.model, options);
  write_optimization_outputs(dir, file, result, options);
  return result;
}

TEST(FlightPageData, AnOptimiseFolderGivesBothStagesAsComputed) {
  test::TempDir tmp;
  const std::string dir = tmp / "m7";
  const OptimizationResult run =
      optimised_folder("M7-double-front-one-and-a-half-twists", dir, 101, 3);
  const nlohmann::json data = flight_page_data(dir, "2026-11-26");
  EXPECT_EQ(data["format"], kFlightPageFormat);
  EXPECT_EQ(data["kind"], "optimize");
  EXPECT_EQ(data["date"], "2026-11-26");
  EXPECT_NO_THROW(require_finite(data, dir));

  const nlohmann::json result = test::read_json(dir + "/result.json");
  EXPECT_EQ(data["residual"]["before"], result["before"]);
  EXPECT_EQ(data["residual"]["after"], result["after"]);
  EXPECT_EQ(data["settings"]["formulation"], result["formulation"]);
  EXPECT_EQ(data["body_weight_N"], result["body_weight_N"]);

  ASSERT_EQ(data["stages"].size(), 2u);
  const int segments = static_cast<int>(run.after.samples[0].segment_position.size());
  for (int stage = 0; stage < 2; ++stage) {
    const nlohmann::json& s = data["stages"][stage];
    const std::vector<SampleRecord>& samples = stage ? run.after.samples : run.before.samples;
    ASSERT_EQ(s["t"].size(), samples.size());
    ASSERT_EQ(s["pos"].size(), samples.size() * segments * 3);
    ASSERT_EQ(s["quat"].size(), samples.size() * segments * 4);
    for (std::size_t i = 0; i < samples.size(); i += 10) {
      EXPECT_NEAR(s["t"][i].get<double>(), samples[i].time, 1e-12);
      for (int k = 0; k < segments; ++k) {
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(s["pos"][(i * segments + k) * 3 + c].get<double>(),
                      samples[i].segment_position[k][c], 1e-5);
        // The page's (w, x, y, z) is the sample's rotation, up to the sign the CSV normalises.
        const Eigen::Quaterniond& q = samples[i].segment_rotation[k];
        const double dot = s["quat"][(i * segments + k) * 4].get<double>() * q.w() +
                           s["quat"][(i * segments + k) * 4 + 1].get<double>() * q.x() +
                           s["quat"][(i * segments + k) * 4 + 2].get<double>() * q.y() +
                           s["quat"][(i * segments + k) * 4 + 3].get<double>() * q.z();
        EXPECT_NEAR(std::abs(dot), 1.0, 1e-5);
      }
      EXPECT_NEAR(s["force_N"][i].get<double>(), samples[i].root_wrench.head<3>().norm(),
                  1e-5 * (1 + samples[i].root_wrench.head<3>().norm()));
    }
  }
  EXPECT_EQ(data["stages"][1]["keyframes"], result["keyframe_times_after"]);

  // The parabola by its closed form from the optimised motion's take-off.
  const Takeoff takeoff = run.optimized_motion.takeoff;
  const double duration = data["duration_s"].get<double>();
  const nlohmann::json& p = data["parabola"];
  const std::size_t last = p.size() - 3;
  EXPECT_NEAR(p[1].get<double>(), takeoff.com_position.y(), 1e-5);
  EXPECT_NEAR(p[last + 1].get<double>(),
              takeoff.com_position.y() + takeoff.com_velocity.y() * duration -
                  0.5 * 9.81 * duration * duration,
              1e-4);
  EXPECT_EQ(data["apparatus"]["kind"], "trampoline");

  // The model's shapes: parts as in the model file, one capsule for a segment without parts.
  const nlohmann::json model_file = test::read_json(dir + "/model.json");
  ASSERT_EQ(data["model"]["segments"].size(), model_file["segments"].size());
  for (std::size_t i = 0; i < model_file["segments"].size(); ++i) {
    const nlohmann::json& shape = model_file["segments"][i]["shape"];
    const std::size_t parts = shape.contains("parts") ? shape["parts"].size() : 1;
    EXPECT_EQ(data["model"]["segments"][i]["parts"].size(), parts) << i;
  }
  const double height = data["model"]["standing_height_m"].get<double>();
  EXPECT_GT(height, 1.5);
  EXPECT_LT(height, 2.0);

  // The whole page: within the bound the issue sets, and exactly what was written.
  const std::string page = tmp / "m7.html";
  const FlightPageSummary summary = export_flight_page(dir, page);
  EXPECT_TRUE(summary.optimised);
  EXPECT_EQ(summary.frames, 101);
  EXPECT_EQ(summary.bytes, fs::file_size(page));
  EXPECT_LE(summary.bytes, 3000000u);
  EXPECT_EQ(read_flight_page_data(page)["residual"], data["residual"]);
}

TEST(FlightPageData, AMotionFileIsEvaluatedAndADiveHasItsPlatform) {
  const nlohmann::json data =
      flight_page_data(bundled_motion("dive-5m-front-one-and-a-half-twists"), "2026-11-26");
  EXPECT_EQ(data["kind"], "motion");
  EXPECT_EQ(data["stages"].size(), 1u);
  EXPECT_TRUE(data["residual"]["after"].is_null());
  EXPECT_GT(data["residual"]["before"]["avg_root_force"].get<double>(), 0.0);
  EXPECT_EQ(data["apparatus"]["kind"], "platform");
  EXPECT_GT(data["apparatus"]["takeoff_height_m"].get<double>() -
                data["apparatus"]["landing_height_m"].get<double>(),
            2.0);
  // The page draws the sizes the app draws and the clearances use (evaluation/apparatus.h).
  const nlohmann::json& sizes = data["apparatus"]["sizes"];
  EXPECT_EQ(sizes["platform_edge_ahead"], kPlatformEdgeAhead);
  EXPECT_EQ(sizes["platform_width"], kPlatformWidth);
  EXPECT_EQ(sizes["frame_width"], kFrameWidth);
  EXPECT_EQ(sizes["bed_length"], kBedLength);
  EXPECT_EQ(sizes.size(), 12u);
  EXPECT_EQ(data["stages"][0]["t"].size(), 101u) << "the default samples";
}

TEST(FlightPageData, ALongTrajectoryIsThinnedKeepingItsEnds) {
  test::TempDir tmp;
  const std::string dir = tmp / "m1";
  optimised_folder("M1-straight-back-somersault", dir, 1501, 0);
  const nlohmann::json data = flight_page_data(dir, "2026-11-26");
  const nlohmann::json& t = data["stages"][1]["t"];
  ASSERT_EQ(t.size(), static_cast<std::size_t>(kFlightPageMaxFrames));
  EXPECT_EQ(t[0].get<double>(), 0.0);
  EXPECT_NEAR(t[t.size() - 1].get<double>(), data["duration_s"].get<double>(), 1e-12);
}

std::string deepmimic_capture() {
  return std::string(SALTUS_EXAMPLES_DIR) + "/captures/deepmimic-backflip.bvh";
}

/// trajectory.csv as columns by name, read with nothing of Saltus's.
std::map<std::string, std::vector<double>> csv_columns(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');)
    names.push_back(name);
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string cell;
    for (std::size_t i = 0; i < names.size() && std::getline(row, cell, ','); ++i)
      columns[names[i]].push_back(std::stod(cell));
  }
  return columns;
}

/// The page's capture against the import folder's trajectory.csv and result.json: every pose
/// and every |F|, |M| (the CSV has at most 1001 rows here, so nothing is thinned).
void expect_capture_of_folder(const nlohmann::json& capture, const std::string& import_dir,
                              const BodyModel& model) {
  const auto csv = csv_columns(import_dir + "/trajectory.csv");
  const std::size_t rows = csv.at("t").size();
  ASSERT_GE(rows, 101u);
  ASSERT_EQ(capture["t"].size(), rows);
  const std::size_t segments = model.segments.size();
  ASSERT_EQ(capture["pos"].size(), rows * segments * 3);
  ASSERT_EQ(capture["quat"].size(), rows * segments * 4);
  for (std::size_t i = 0; i < rows; ++i) {
    EXPECT_NEAR(capture["t"][i].get<double>(), csv.at("t")[i], 1e-12);
    for (std::size_t k = 0; k < segments; ++k) {
      const std::string& name = model.segments[k].name;
      int c = 0;
      for (const char* axis : {".x", ".y", ".z"})
        EXPECT_NEAR(capture["pos"][(i * segments + k) * 3 + c++].get<double>(),
                    csv.at(name + axis)[i], 1e-5 * (1 + std::abs(csv.at(name + axis)[i])))
            << name << axis << " row " << i;
      c = 0;
      for (const char* axis : {".qw", ".qx", ".qy", ".qz"})
        EXPECT_NEAR(capture["quat"][(i * segments + k) * 4 + c++].get<double>(),
                    csv.at(name + axis)[i], 2e-6)
            << name << axis << " row " << i;
    }
    const double force =
        std::hypot(csv.at("root_fx")[i], csv.at("root_fy")[i], csv.at("root_fz")[i]);
    const double moment =
        std::hypot(csv.at("root_mx")[i], csv.at("root_my")[i], csv.at("root_mz")[i]);
    EXPECT_NEAR(capture["force_N"][i].get<double>(), force, 1e-5 * (1 + force)) << i;
    EXPECT_NEAR(capture["moment_Nm"][i].get<double>(), moment, 1e-5 * (1 + moment)) << i;
  }
  EXPECT_EQ(capture["residual"],
            test::read_json(import_dir + "/result.json")["capture"]["residual"]);
}

TEST(FlightPageData, AnImportFolderShowsItsKeyframesWithTheCaptureBeside) {
  test::TempDir tmp;
  const std::string dir = tmp / "bf";
  write_capture_outputs(dir, import_capture_file(deepmimic_capture()));
  const nlohmann::json data = flight_page_data(dir, "2026-11-26");
  EXPECT_NO_THROW(require_finite(data, dir));
  EXPECT_EQ(data["kind"], "motion");
  const nlohmann::json keyframes = test::read_json(dir + "/keyframes.motion.json");
  EXPECT_EQ(data["stages"][0]["keyframes"].size(), keyframes["keyframes"].size())
      << "the athlete is the picked keyframes, as the app shows an imported capture";
  ASSERT_TRUE(data.contains("capture"));
  EXPECT_EQ(data["capture"]["source"], dir);
  const MotionFile file = load_motion_file(dir + "/keyframes.motion.json");
  expect_capture_of_folder(data["capture"], dir, file.model);

  // A motion file of the folder finds it too; a motion elsewhere has none unless given.
  EXPECT_EQ(flight_page_data(dir + "/keyframes.motion.json", "")["capture"]["source"], dir);
  const std::string m1 = bundled_motion("M1-straight-back-somersault");
  EXPECT_FALSE(flight_page_data(m1, "").contains("capture"));
  EXPECT_EQ(flight_page_data(m1, "", dir)["capture"]["source"], dir);
  try {
    flight_page_data(m1, "", tmp.path().string());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--capture"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("is not a folder saltus import wrote"), std::string::npos)
        << e.what();
  }
}

TEST(FlightPageData, AnOptimiseFolderOfAnImportedMotionFindsItsCapture) {
  test::TempDir tmp;
  const std::string import_dir = tmp / "bf";
  write_capture_outputs(import_dir, import_capture_file(deepmimic_capture()));
  const MotionFile file = load_motion_file(import_dir + "/keyframes.motion.json");
  OptimizeOptions options;
  options.solver.max_iterations = 2;
  const OptimizationResult result = optimize_motion(file.motion, file.model, options);
  const std::string dir = tmp / "bf-opt";
  write_optimization_outputs(dir, file, result, options);
  const nlohmann::json data = flight_page_data(dir, "2026-11-26");
  EXPECT_EQ(data["kind"], "optimize");
  ASSERT_TRUE(data.contains("capture")) << "result.json's motion_file lies in the import folder";
  EXPECT_EQ(data["capture"]["source"], import_dir);
  expect_capture_of_folder(data["capture"], import_dir, file.model);

  const std::string page = tmp / "bf.html";
  const FlightPageSummary summary = export_flight_page(dir, page);
  EXPECT_EQ(summary.capture, import_dir);
  EXPECT_EQ(read_flight_page_data(page)["capture"], data["capture"]);
}

TEST(FlightPageData, ACaptureFileIsItsKeyframesWithTheCaptureBeside) {
  const CaptureFile capture = import_capture_file(deepmimic_capture());
  const nlohmann::json data = flight_page_data(deepmimic_capture(), "");
  ASSERT_TRUE(data.contains("capture"));
  EXPECT_EQ(data["capture"]["source"], deepmimic_capture());
  ASSERT_EQ(data["capture"]["t"].size(), capture.import.samples.size());
  const std::size_t last = capture.import.samples.size() - 1;
  const double force = capture.import.samples[last].root_wrench.head<3>().norm();
  EXPECT_NEAR(data["capture"]["force_N"][last].get<double>(), force, 1e-5 * force)
      << "6 significant digits";
  EXPECT_EQ(data["capture"]["residual"]["avg_root_force"].get<double>(),
            capture.import.metrics.avg_root_force);
  EXPECT_EQ(data["stages"][0]["keyframes"].size(), capture.import.keyframes.keyframes.size());
}

TEST(FlightPageData, BadSourcesNameTheFile) {
  test::TempDir tmp;
  try {
    flight_page_data(tmp / "absent.motion.json", "");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("absent.motion.json"), std::string::npos) << e.what();
  }
  fs::create_directories(tmp / "empty");
  EXPECT_THROW(flight_page_data(tmp / "empty", ""), InputError);
}

}  // namespace
}  // namespace saltus
