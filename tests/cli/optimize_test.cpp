// `saltus optimize` end to end: outputs as docs/formats.md, the residual reduced, the keyframe
// constraints held in the written trajectory (not only on the solver's word), and the optimised
// motion reloading to the same numbers through `saltus evaluate`.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include "saltus/base/constants.h"
#include "saltus/base/text_format.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/formats/trajectory_csv.h"
#include "saltus/optim/optimize.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

using test::read_json;
TEST(CliOptimize, ReducesTheResidualKeepsKeyframesAndReloads) {
  test::TempDir dir;
  const std::string out = dir / "opt";
  const auto run = test::run_cli("optimize " + test::m1_path() + " --out " + out +
                                 " --samples 61 --max-iter 25 --quiet");
  // 0 = converged, 3 = iteration limit reached; both write complete results.
  ASSERT_TRUE(run.status == 0 || run.status == 3) << run.output;
  for (const char* name : {"result.json", "trajectory_before.csv", "trajectory_after.csv",
                           "model.json", "optimized.motion.json"})
    EXPECT_TRUE(std::filesystem::exists(out + "/" + name)) << name;

  const auto result = read_json(out + "/result.json");
  EXPECT_EQ(result["status"] == "solved", run.status == 0);
  const double before = result["before"]["avg_root_force"];
  const double after = result["after"]["avg_root_force"];
  EXPECT_LT(after, before / 5) << "before " << before << " after " << after;
  EXPECT_GT(result["variables"].get<int>(), 0);
  EXPECT_GT(result["constraints"].get<int>(), 0);
  if (result["status"] == "solved") {
    // Checked on the written trajectory by `keyframe_errors`, not on Ipopt's word.
    EXPECT_LE(result["max_translation_error_m"].get<double>(), 0.25 + 1e-6);
    EXPECT_LE(result["max_quaternion_error"].get<double>(), 0.05 + 1e-4);
  } else {
    // An unfinished solve may end slightly outside the tolerances; it must say so.
    EXPECT_NE(result["status"], "solved");
    EXPECT_LE(result["max_quaternion_error"].get<double>(), 0.1);
  }

  // The reported figure is the motion's true residual: the trapezoidal rule over the written
  // trajectory (61 samples) comes within 10 % of it, and over a trajectory re-evaluated on 4001
  // samples (a dense grid the optimiser never saw) agrees with it closely.
  auto trapezoid_force = [](const CsvTable& csv) {
    double sum = 0;
    const int f0 = csv.column("root_fx");
    for (std::size_t k = 0; k + 1 < csv.rows.size(); ++k) {
      double a = 0, b = 0;
      for (int i = 0; i < 6; ++i) {
        a += csv.rows[k][f0 + i] * csv.rows[k][f0 + i];
        b += csv.rows[k + 1][f0 + i] * csv.rows[k + 1][f0 + i];
      }
      sum += 0.5 * (a + b) * (csv.rows[k + 1][0] - csv.rows[k][0]);
    }
    return std::sqrt(sum / csv.rows.back()[0] / 6);
  };
  const CsvTable after_csv = read_csv_table(out + "/trajectory_after.csv");
  ASSERT_EQ(after_csv.rows.size(), 61u);
  EXPECT_NEAR(trapezoid_force(after_csv), after, 0.1 * after);
  const auto dense = test::run_cli("evaluate " + out + "/optimized.motion.json --out " +
                                   (dir / "dense") + " --samples 4001 --quiet");
  ASSERT_EQ(dense.status, 0) << dense.output;
  EXPECT_NEAR(trapezoid_force(read_csv_table(dir / "dense/trajectory.csv")), after, 0.005 * after);
  // The optimiser's own integral says the same.
  EXPECT_NEAR(result["after"]["optimizer_avg_root_force"].get<double>(), after,
              0.02 * after + 0.02);
  EXPECT_TRUE(result["residual_check"]["optimizer_agrees"].get<bool>());

  // Reload: evaluate of the optimised motion reproduces the "after" numbers.
  const auto again = test::run_cli("evaluate " + out + "/optimized.motion.json --out " +
                                   (dir / "re") + " --samples 61 --quiet");
  ASSERT_EQ(again.status, 0) << again.output;
  const auto re = read_json(dir / "re/result.json");
  for (const char* key : {"objective", "avg_root_force", "max_force_N", "max_moment_Nm"})
    EXPECT_NEAR(re["before"][key].get<double>(), result["after"][key].get<double>(),
                1e-9 * (1 + std::abs(result["after"][key].get<double>())))
        << key;
  EXPECT_EQ(re["keyframe_times_before"], result["keyframe_times_after"]);

  // The knots result.json names are the ones the optimised motion's stored spline lives on,
  // and the spans per interval add up to them.
  const auto& resolution = result["resolution"];
  EXPECT_TRUE(resolution["automatic"].get<bool>());
  const auto stored = read_json(out + "/optimized.motion.json");
  EXPECT_EQ(resolution["knots"], stored["spline"]["knots"]);
  int spans = 0;
  for (const auto& s : resolution["subdivisions"])
    spans += s.get<int>();
  EXPECT_EQ(resolution["knots"].size(), static_cast<std::size_t>(spans + 7));
  EXPECT_EQ(resolution["subdivisions"].size(), stored["keyframes"].size() - 1);
  ASSERT_FALSE(resolution["levels"].empty());
  // Each keyframe time's spread: none for the fixed first and last, and the undetermined list
  // is exactly the times whose spread exceeds 0.02 s.
  const auto& spreads = result["keyframe_time_spread_s"];
  ASSERT_EQ(spreads.size(), stored["keyframes"].size());
  EXPECT_EQ(spreads.front().get<double>(), 0.0);
  EXPECT_EQ(spreads.back().get<double>(), 0.0);
  std::vector<int> wide;
  for (std::size_t i = 0; i < spreads.size(); ++i) {
    EXPECT_GE(spreads[i].get<double>(), 0.0);
    EXPECT_LE(spreads[i].get<double>(), 0.25 + 1e-12);  // --max-time-shift
    if (spreads[i].get<double>() > 0.02) wide.push_back(static_cast<int>(i));
  }
  EXPECT_EQ(result["keyframe_times_undetermined"].get<std::vector<int>>(), wide);
  // The level kept is the one the "after" figures describe, or the least-joint-effort polish
  // on its knots when that was kept.
  double kept = 1e300;
  for (const auto& level : resolution["levels"])
    if (level["subdivisions"] == resolution["subdivisions"])
      kept = level["avg_root_force"].get<double>();
  if (resolution.contains("joint_load_polish")) {
    const auto& polish = resolution["joint_load_polish"];
    EXPECT_NEAR(polish["avg_root_force_before"].get<double>(), kept, 1e-9 * kept);
    if (polish["kept"].get<bool>()) kept = polish["avg_root_force_after"].get<double>();
  }
  EXPECT_NEAR(kept, after, 1e-9 * after);
}

// M7 optimised used to report 0.1532 N where the same motion on a grid 20 times finer gave
// 0.1491 N: the residual the optimiser leaves is near zero at its quadrature nodes and swings
// between them faster than the dense check's first grid resolved. The reported figure must be
// the motion's, whatever grid checks it: here a trapezoid over 20001 samples of the written
// motion, computed in the test.
/// A run that misses 0.5 N says where the root force it left lives: the keyframe interval with the
/// largest share of ∫ΣF² dt (result.json residual_check.share_by_keyframe_interval), which the
/// optimised motion re-evaluated on 4001 samples and integrated by hand between its keyframe
/// times confirms.
TEST(CliOptimize, AMissNamesTheKeyframeIntervalWhereTheRootForceLives) {
  test::TempDir dir;
  const std::string out = dir / "miss";
  const auto run = test::run_cli("optimize " + test::m1_path() + " --out " + out +
                                 " --knots-per-interval 1 --max-iter 3");
  ASSERT_TRUE(run.status == 0 || run.status == 3) << run.output;
  const auto result = read_json(out + "/result.json");
  ASSERT_GT(result["after"]["avg_root_force"].get<double>(), kPolishMaxRootForce)
      << "three iterations at the paper's resolution leave more than the target";
  const std::vector<double> shares = result["residual_check"]["share_by_keyframe_interval"];
  const std::vector<double> times = result["keyframe_times_after"];
  ASSERT_EQ(shares.size() + 1, times.size());
  const std::size_t largest =
      static_cast<std::size_t>(std::max_element(shares.begin(), shares.end()) - shares.begin());
  EXPECT_NE(run.output.find(format_number("above %.3g N: the largest share of the root force left "
                                          "is between keyframes ",
                                          kPolishMaxRootForce) +
                            std::to_string(largest + 1) + " and " + std::to_string(largest + 2)),
            std::string::npos)
      << run.output;
  const auto dense = test::run_cli("evaluate " + out + "/optimized.motion.json --out " +
                                   (dir / "dense") + " --samples 4001 --quiet");
  ASSERT_EQ(dense.status, 0) << dense.output;
  const CsvTable csv = read_csv_table(dir / "dense/trajectory.csv");
  const int f0 = csv.column("root_fx");
  std::vector<double> by_hand(shares.size(), 0.0);
  double total = 0.0;
  for (std::size_t k = 0; k + 1 < csv.rows.size(); ++k) {
    double a = 0, b = 0;
    for (int i = 0; i < 6; ++i) {
      a += csv.rows[k][f0 + i] * csv.rows[k][f0 + i];
      b += csv.rows[k + 1][f0 + i] * csv.rows[k + 1][f0 + i];
    }
    const double middle = 0.5 * (csv.rows[k][0] + csv.rows[k + 1][0]);
    const std::size_t i = std::min<std::size_t>(
        std::upper_bound(times.begin(), times.end(), middle) - times.begin() - 1,
        by_hand.size() - 1);
    const double piece = 0.5 * (a + b) * (csv.rows[k + 1][0] - csv.rows[k][0]);
    by_hand[i] += piece;
    total += piece;
  }
  for (std::size_t i = 0; i < shares.size(); ++i)
    EXPECT_NEAR(shares[i], by_hand[i] / total, 0.01) << "interval " << i;
}

TEST(CliOptimize, ReportedResidualIsTheMotionsOnAFarFinerGrid) {
  test::TempDir dir;
  const std::string out = dir / "opt";
  const auto run = test::run_cli("optimize " + std::string(SALTUS_EXAMPLES_DIR) +
                                 "/motions/M7-double-front-one-and-a-half-twists.motion.json" +
                                 " --out " + out + " --quiet");
  ASSERT_EQ(run.status, 0) << run.output;
  const auto result = read_json(out + "/result.json");
  EXPECT_TRUE(result["residual_check"]["converged"].get<bool>());
  const double after = result["after"]["avg_root_force"];
  const auto dense = test::run_cli("evaluate " + out + "/optimized.motion.json --out " +
                                   (dir / "dense") + " --samples 20001 --quiet");
  ASSERT_EQ(dense.status, 0) << dense.output;
  const CsvTable csv = read_csv_table(dir / "dense/trajectory.csv");
  ASSERT_EQ(csv.rows.size(), 20001u);
  const int f0 = csv.column("root_fx");
  double sum = 0;
  for (std::size_t k = 0; k + 1 < csv.rows.size(); ++k) {
    double a = 0, b = 0;
    for (int i = 0; i < 6; ++i) {
      a += csv.rows[k][f0 + i] * csv.rows[k][f0 + i];
      b += csv.rows[k + 1][f0 + i] * csv.rows[k + 1][f0 + i];
    }
    sum += 0.5 * (a + b) * (csv.rows[k + 1][0] - csv.rows[k][0]);
  }
  const double fine = std::sqrt(sum / csv.rows.back()[0] / 6);
  EXPECT_NEAR(after, fine, 0.003 * fine);
}

// Issue 24's joint loads: the optimised M2 used to put 142 N·m on the left hip at take-off,
// where the interpolated input needed 18 N·m at most (7.8x). The default polish (least joint
// effort, each joint's moment and force bounded by 1.3x its input peak) holds M1, M2, M6 and the
// dive within the 1.5x at every joint (measured 1.31x, 1.30x, 1.27x, 1.28x; 3.13x, 2.48x,
// 1.36x, 7.0x with the effort term alone). The dive needs the third try of the ladder (its first
// two land 3-6 deg off): result.json must name a bounded try whose weights are the ladder's.
// Without the polish (--joint-load-weight 0) M2's kick is back, so the polish is what removes it.
// Peaks are the dense check's, read from result.json; ratios floored as joint_loads.h does.
TEST(CliOptimize, JointLoadsStayNearTheInputsWithLeastJointEffort) {
  test::TempDir dir;
  const std::string motions = std::string(SALTUS_EXAMPLES_DIR) + "/motions/";
  // The bar, 1.5x at every joint, moment and force, on the dense check's points: the
  // polish bounds them at 1.3x on its nodes.
  for (const char* name :
       {"M1-straight-back-somersault", "M2-tucked-back-somersault",
        "M6-half-twist-into-one-and-a-half-front", "dive-5m-front-one-and-a-half-twists"}) {
    SCOPED_TRACE(name);
    const std::string out = dir / name;
    const auto with = test::run_cli("optimize " + motions + name + ".motion.json --out " + out);
    ASSERT_EQ(with.status, 0) << with.output;
    EXPECT_NE(with.output.find("joint loads: every joint within 1."), std::string::npos)
        << with.output;
    const auto result = read_json(out + "/result.json");
    const auto& polish = result["resolution"]["joint_load_polish"];
    EXPECT_TRUE(polish["kept"].get<bool>());
    EXPECT_EQ(polish["joint_bound"].get<double>(), kPolishJointBound);
    const int attempts = polish["attempts"].get<int>();
    ASSERT_GE(attempts, 1);
    ASSERT_LE(attempts, kPolishAttempts);
    const PolishTry& last = kPolishTries[attempts - 1];
    EXPECT_TRUE(last.joints_bounded);
    EXPECT_EQ(polish["root_moment_weight"].get<double>(), last.root_moment_weight);
    EXPECT_LE(result["after"]["avg_root_force"].get<double>(), 0.5);
    EXPECT_LE(test::largest_joint_rise(result), 1.5);
  }
  const auto without =
      test::run_cli("optimize " + motions + "M2-tucked-back-somersault.motion.json --out " +
                    (dir / "without") + " --joint-load-weight 0");
  ASSERT_EQ(without.status, 0) << without.output;
  const auto bare = read_json(dir / "without/result.json");
  EXPECT_FALSE(bare["resolution"].contains("joint_load_polish"));
  EXPECT_GE(test::largest_joint_rise(bare), 5.0);
  // The CLI names the joint and says what such a rise means.
  EXPECT_NE(without.output.find("(more than 1.5x): the optimiser made it pay for the root force"),
            std::string::npos)
      << without.output;
}

// Issue 24's landing drift: the optimised motion, flown by `saltus simulate` from its own
// take-off state, lands where it shows (within 3°), and result.json's landing_drift_deg is what
// simulate reports. M7's polish used to be kept at 0.34 N with its free flight 70° off; now a
// polish that drifts is refused, and tried again at half the weight.
TEST(CliOptimize, TheOptimisedMotionFliesAsShown) {
  test::TempDir dir;
  for (const char* name : {"M2-tucked-back-somersault", "M7-double-front-one-and-a-half-twists"}) {
    SCOPED_TRACE(name);
    const std::string motion =
        std::string(SALTUS_EXAMPLES_DIR) + "/motions/" + name + ".motion.json";
    const std::string out = dir / (std::string(name) + "-opt");
    const auto run = test::run_cli("optimize " + motion + " --out " + out + " --quiet");
    ASSERT_EQ(run.status, 0) << run.output;
    const auto result = read_json(out + "/result.json");
    const double drift = result["resolution"]["landing_drift_deg"].get<double>();
    const std::string flown = dir / (std::string(name) + "-sim");
    const auto simulate =
        test::run_cli("simulate " + out + "/optimized.motion.json --out " + flown + " --quiet");
    ASSERT_EQ(simulate.status, 0) << simulate.output;
    EXPECT_NEAR(read_json(flown + "/result.json")["landing"]["root_vs_motion_deg"].get<double>(),
                drift, 0.05);
    EXPECT_LE(drift, 3.0);
    const auto& polish = result["resolution"]["joint_load_polish"];
    EXPECT_EQ(polish["kept"].get<bool>(),
              polish["landing_drift_after_deg"].get<double>() <= 3.0 ||
                  polish["landing_drift_after_deg"] <= polish["landing_drift_before_deg"]);
  }
}

/// `optimize` of M6 on a 1.29 m, 37 kg girl made by `model new` in `dir`, with `options`.
test::CliRun optimise_m6_on_a_light_girl(const test::TempDir& dir, const std::string& options) {
  const std::string model = dir / "girl.model.json";
  const test::CliRun made =
      test::run_cli("model new --height 1.29 --mass 37 --sex female --name girl --out " + model);
  if (made.status != 0) return made;
  return test::run_cli("optimize " + std::string(SALTUS_EXAMPLES_DIR) +
                       "/motions/M6-half-twist-into-one-and-a-half-front.motion.json --model " +
                       model + " " + options);
}

/// A twist that flies off on a light athlete (M6 on a 1.29 m, 37 kg girl: the levels land
/// 84-106° from their motion) is made again with the root moment weighed: the printed levels say
/// so, result.json records each level's weight, and the motion written lands within 3° when
/// `simulate` flies it. Least joint effort is left out (only the levels are under test).
TEST(CliOptimize, ATwistThatFliesOffOnALightAthleteIsMadeAgainWeighingTheRootMoment) {
  test::TempDir dir;
  const std::string out = dir / "opt";
  const test::CliRun run = optimise_m6_on_a_light_girl(dir, "--joint-load-weight 0 --out " + out);
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("(root moment weighed 100x)"), std::string::npos) << run.output;
  const auto result = read_json(out + "/result.json");
  int first = 0, weighed = 0;
  for (const auto& level : result["resolution"]["levels"]) {
    const double weight = level["root_moment_weight"].get<double>();
    first += weight == 1.0;
    weighed += weight == 100.0;
    if (weight == 1.0) {
      EXPECT_GT(level["landing_drift_deg"].get<double>(), 3.0);
    }
  }
  EXPECT_GT(first, 0);
  EXPECT_GT(weighed, 0);
  const double drift = result["resolution"]["landing_drift_deg"].get<double>();
  const std::string flown = dir / "sim";
  const auto simulate =
      test::run_cli("simulate " + out + "/optimized.motion.json --out " + flown + " --quiet");
  ASSERT_EQ(simulate.status, 0) << simulate.output;
  const double simulated =
      read_json(flown + "/result.json")["landing"]["root_vs_motion_deg"].get<double>();
  EXPECT_NEAR(simulated, drift, 0.05);
  EXPECT_LE(simulated, 3.0);
  EXPECT_LE(result["after"]["avg_root_force"].get<double>(), 0.5);
}

/// The same girl with the defaults: the joints pay (the polish keeps no bounded try, every one
/// landing far from its own free flight), and the CLI says what human joints would have cost,
/// with the figures result.json records.
TEST(CliOptimize, SaysWhatHumanJointsWouldHaveCostOnALightAthlete) {
  test::TempDir dir;
  const std::string out = dir / "opt";
  const test::CliRun run = optimise_m6_on_a_light_girl(dir, "--out " + out);
  ASSERT_EQ(run.status, 0) << run.output;
  const auto result = read_json(out + "/result.json");
  EXPECT_GT(test::largest_joint_rise(result), 1.5);
  const auto& alternative = result["resolution"]["joint_load_polish"]["bounded_alternative"];
  ASSERT_TRUE(alternative.is_object()) << result["resolution"].dump(2);
  const double drift = alternative["landing_drift_deg"].get<double>();
  EXPECT_GT(drift, 3.0);
  EXPECT_LE(alternative["joint_rise"].get<double>(), 1.5);
  const std::string line = "with human joints instead";
  ASSERT_NE(run.output.find(line), std::string::npos) << run.output;
  const std::string said = run.output.substr(run.output.find(line));
  EXPECT_NE(said.find(saltus::format_number("lands %.0f deg from it", drift)), std::string::npos)
      << said;
}

TEST(CliOptimize, BadOptionsExitWithTwo) {
  test::TempDir dir;
  EXPECT_EQ(test::run_cli("optimize " + test::m1_path() + " --out " + (dir / "o") +
                          " --formulation sloppy")
                .status,
            2);
  EXPECT_EQ(test::run_cli("optimize " + test::m1_path() + " --out " + (dir / "o") + " --epsilon -1")
                .status,
            2);
  EXPECT_EQ(test::run_cli("optimize " + test::m1_path() + " --out " + (dir / "o") +
                          " --max-joint-turn 400")
                .status,
            2);
  EXPECT_FALSE(std::filesystem::exists(dir / "o"));
}

TEST(CliOptimize, WritesNoMotionItsOwnReaderRefuses) {
  // A take-off CoM exactly at the 10 km bound: the optimised motion's own take-off state and
  // root targets come back a hair past it, and optimized.motion.json would not read back.
  const test::TempDir dir;
  nlohmann::json motion = read_json(test::m1_path());
  motion["takeoff"]["com_position"][0] = 10000.0;
  motion["model"] = "zatsiorsky-66kg";
  test::write_text(dir / "far.motion.json", motion.dump());
  const auto run = test::run_cli("optimize " + (dir / "far.motion.json") + " --max-iter 0 --out " +
                                 (dir / "out"));
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("far.motion.json: its optimised motion would be refused"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(test::names_in(dir.path()), std::set<std::string>{"far.motion.json"});
}

TEST(CliOptimize, MaxJointTurnKeepsLimbsFromSpinningBetweenControlPoints) {
  // M3 at the paper's resolution: without the limit the optimum turns light limbs by more than
  // 300° between two control points; with the default 180° they stay near it (a soft limit).
  test::TempDir dir;
  const std::string m3 =
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/M3-tucked-double-back.motion.json";
  const auto limited_run = test::run_cli("optimize " + m3 + " --out " + (dir / "limited") +
                                         " --quiet --knots-per-interval 1");
  ASSERT_EQ(limited_run.status, 0) << limited_run.output;
  const auto limited = read_json(dir / "limited/result.json");
  EXPECT_EQ(limited["joint_turn_limit_deg"].get<double>(), 180.0);
  const double before = limited["largest_joint_turn_deg"]["before"];
  EXPECT_LE(limited["largest_joint_turn_deg"]["after"].get<double>(),
            std::max(180.0, before) + 6.0);
  // Without it a limb may turn so far (360° on this machine) that the stored spline is one
  // Saltus's own reader refuses (at most 342° between controls): then nothing is written and
  // the run says why (exit 2), instead of leaving a motion file that cannot be read.
  const auto free = test::run_cli("optimize " + m3 + " --out " + (dir / "free") +
                                  " --quiet --knots-per-interval 1 --max-joint-turn 0");
  if (free.status == 2) {
    EXPECT_NE(free.output.find("would be refused by Saltus's own reader"), std::string::npos)
        << free.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "free"));
  } else {
    EXPECT_TRUE(free.status == 0 || free.status == 3) << free.output;
    const auto written = read_json(dir / "free/result.json");
    EXPECT_EQ(written["joint_turn_limit_deg"].get<double>(), 0.0);
    EXPECT_GT(written["largest_joint_turn_deg"]["after"].get<double>(), 270.0);
  }
}

}  // namespace
}  // namespace saltus
