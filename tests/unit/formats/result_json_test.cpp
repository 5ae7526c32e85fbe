// Result folders (formats/result_json.h): result.json's figures are the evaluation's and agree
// with the trajectory.csv written beside it — J, RMS and peak root force recomputed here from the
// CSV's root wrench columns by the trapezoidal rule, to the coarser grid's accuracy — and the
// simulation's result names its momentum and landing.

#include "saltus/formats/result_json.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "saltus/formats/trajectory_csv.h"
#include "support/cli_runner.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

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
