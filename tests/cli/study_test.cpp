// `saltus study convergence`, `saltus study mass` and `saltus paper` end to end on small
// settings: the files the issue asks for exist and hold one row per case or sample, and the
// numbers are the physics' (checked against an independent run where it is cheap).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "saltus/formats/trajectory_csv.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

using test::m1_path;
using test::run_cli;
using test::TempDir;

TEST(CliStudy, ConvergenceWritesOneRowPerCaseAndTheRelaxedModelSolves) {
  TempDir dir;
  const auto run = run_cli(
      "study convergence " + m1_path() + " --out " + (dir / "c") +
      " --epsilons 1 --mass-errors -10,0 --timing-errors 0,0.05 --samples 41 --max-iter 100 "
      "--quiet");
  ASSERT_EQ(run.status, 0) << run.output;
  const auto result = nlohmann::json::parse(test::read_text(dir / "c/result.json"));
  // relaxed + strict ε=1, 2 mass errors, 2 timing errors.
  ASSERT_EQ(result["cases"].size(), 8u);
  int relaxed_solved = 0, strict_solved = 0;
  for (const auto& c : result["cases"])
    (c["formulation"] == "relaxed" ? relaxed_solved : strict_solved) += c["solved"].get<bool>();
  EXPECT_EQ(relaxed_solved, 4);
  // |F_i| <= 1 N at every sample is beyond this motion at K = 1 (its relaxed optimum peaks near
  // 3 N): the strict model must not report success.
  EXPECT_EQ(strict_solved, 0);
  const std::string csv = test::read_text(dir / "c/convergence.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 9);  // header + 8 cases
  const std::string md = test::read_text(dir / "c/convergence.md");
  EXPECT_NE(md.find("| relaxed | 4 | 4 (100 %)"), std::string::npos) << md;
}

TEST(CliStudy, MassWritesTheJointLoadsOfBothModelsOverTime) {
  TempDir dir;
  const auto run =
      run_cli("study mass " + m1_path() + " --out " + (dir / "m") + " --samples 41 --quiet");
  ASSERT_EQ(run.status, 0) << run.output;
  const CsvTable csv = read_csv_table(dir / "m/mass.csv");
  ASSERT_EQ(csv.rows.size(), 41u);
  const int given = csv.column("given.thigh_r.force_N");
  const int scaled = csv.column("scaled.thigh_r.force_N");
  const int fx = csv.column("given.thigh_r.fx"), fy = csv.column("given.thigh_r.fy"),
            fz = csv.column("given.thigh_r.fz");
  double ratio_sum = 0;
  for (const auto& row : csv.rows) {
    const double f = row[given];
    EXPECT_NEAR(f, std::hypot(row[fx], row[fy], row[fz]), 1e-6 * (1 + f));
    ratio_sum += row[scaled] / std::max(f, 1e-9);
  }
  // Heavier thighs need larger forces at the hip to be moved the same way.
  EXPECT_GT(ratio_sum / csv.rows.size(), 1.1);
  const auto result = nlohmann::json::parse(test::read_text(dir / "m/result.json"));
  EXPECT_EQ(result["runs"].size(), 2u);
  EXPECT_TRUE(std::filesystem::exists(dir / "m/model_scaled.json"));
}

TEST(CliStudy, BadStudyInputExitsWithTwo) {
  TempDir dir;
  EXPECT_EQ(run_cli("study convergence " + m1_path() + " --out " + (dir / "x") +
                    " --mass-segments elbow_x --quiet")
                .status,
            2);
  EXPECT_FALSE(std::filesystem::exists(dir / "x"));
  EXPECT_EQ(
      run_cli("study mass " + m1_path() + " --out " + (dir / "y") + " --loads nope --quiet").status,
      2);
  EXPECT_FALSE(std::filesystem::exists(dir / "y"));
  EXPECT_EQ(run_cli("paper " + (dir / "missing") + " --out " + (dir / "z") + " --quiet").status, 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "z"));
}

}  // namespace
}  // namespace saltus
