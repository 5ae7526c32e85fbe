// The optimisation panel's settings map onto the library's options like the CLI's flags; the
// result table and the figures read from a real `saltus optimize`-style output folder.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "core/optimize_settings.h"
#include "core/result_folder.h"
#include "gui_core/test_motion.h"
#include "saltus/base/input_error.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/result_json.h"
#include "saltus/use_cases/result_folders.h"
#include "support/temp_path.h"

namespace saltus::gui {
namespace {

namespace fs = std::filesystem;

TEST(OptimizeSettings, MapOntoTheLibraryOptions) {
  // Untouched, the panel's values are `saltus optimize`'s defaults, which are the library's.
  const OptimizeOptions standard = to_optimize_options(OptimizeSettings{});
  EXPECT_EQ(standard.nlp.formulation, Formulation::kRelaxed);
  EXPECT_EQ(standard.nlp.samples, kDefaultSamples);
  EXPECT_EQ(standard.nlp.joint_turn_limit, MotionNlpOptions{}.joint_turn_limit);
  EXPECT_EQ(standard.solver.max_iterations, SolverOptions{}.max_iterations);
  EXPECT_EQ(standard.solver.tolerance, SolverOptions{}.tolerance);
  // Set in the panel's units (degrees), given to the library in its own (radians).
  OptimizeSettings s;
  s.set("max_joint_turn", 90.0);
  s.set("formulation", std::string("strict"));
  const OptimizeOptions o = to_optimize_options(s);
  EXPECT_NEAR(o.nlp.joint_turn_limit, M_PI / 2, 1e-15);
  EXPECT_EQ(o.nlp.formulation, Formulation::kStrict);
}

TEST(OptimizeSettings, RejectValuesOutOfRange) {
  OptimizeSettings s;
  EXPECT_THROW(s.set("epsilon", 0.0), std::invalid_argument);
  EXPECT_THROW(s.set("knots_per_interval", 0), std::invalid_argument);
  EXPECT_THROW(s.set("samples", 1), std::invalid_argument);
  EXPECT_THROW(s.set("samples", 100001), std::invalid_argument);
  EXPECT_THROW(s.set("max_iterations", -1), std::invalid_argument);
  EXPECT_THROW(s.set("max_joint_turn", -1.0), std::invalid_argument);
  EXPECT_EQ(s, OptimizeSettings{});
}

TEST(OptimizeSettings, UndoStepsNameTheChangedOption) {
  OptimizeSettings a, b;
  EXPECT_EQ(first_changed_option(a, b), "");
  b.set("samples", 31);
  EXPECT_EQ(first_changed_option(a, b), option_spec("samples").label);
  b.set("formulation", std::string("strict"));
  EXPECT_EQ(first_changed_option(a, b), option_spec("formulation").label);
  const std::string tip = option_tooltip(option_spec("max_time_shift"));
  EXPECT_NE(tip.find("(s; >= 0)"), std::string::npos) << tip;
  EXPECT_NE(tip.find("--max-time-shift"), std::string::npos) << tip;
}

TEST(OptimizeSettings, StoredSettingsReadBackAndOldKeysStillRead) {
  OptimizeSettings s;
  s.set("formulation", std::string("strict"));
  s.set("epsilon", 12.5);
  s.set("optimize_timing", false);
  s.set("samples", 77);
  s.set("tolerance", 3e-9);
  s.set("max_joint_turn", 123.25);
  s.set("threads", std::string("auto"));
  std::map<std::string, std::string> stored;
  for (const auto& [key, text] : settings_entries(s))
    stored[key] = text;
  EXPECT_EQ(stored.size(), option_table().size());
  auto from = [](const std::map<std::string, std::string>& m) {
    return settings_from_entries([&m](const std::string& key) -> std::optional<std::string> {
      const auto it = m.find(key);
      if (it == m.end()) return std::nullopt;
      return it->second;
    });
  };
  EXPECT_EQ(from(stored), s);
  // What an earlier version stored (QSettings text of bools and doubles), and a value out of
  // today's range, which keeps the default.
  const OptimizeSettings old = from({{"optimize/strict", "true"},
                                     {"optimize/timing", "false"},
                                     {"optimize/max_joint_turn_deg", "90"},
                                     {"optimize/epsilon", "25"},
                                     {"optimize/samples", "500000"},
                                     {"optimize/max_iterations", "40"}});
  EXPECT_EQ(std::get<std::string>(old.get("formulation")), "strict");
  EXPECT_FALSE(old.on("optimize_timing"));
  EXPECT_EQ(old.real("max_joint_turn"), 90.0);
  EXPECT_EQ(old.real("epsilon"), 25.0);
  EXPECT_EQ(old.integer("samples"), kDefaultSamples);
  EXPECT_EQ(old.integer("max_iterations"), 40);
  EXPECT_EQ(from({}), OptimizeSettings{});
  // Knots: the key of the versions before the automatic resolution held their default 1, which
  // must not turn the new default (auto) off; a chosen number, or auto, is kept.
  EXPECT_EQ(from({{"optimize/knots_per_interval", "1"}}).get("knots_per_interval"),
            OptionValue(std::string("auto")));
  EXPECT_EQ(from({{"optimize/knots", "3"}}).get("knots_per_interval"), OptionValue(3));
  EXPECT_EQ(from({{"optimize/knots", "0"}}).get("knots_per_interval"),
            OptionValue(std::string("auto")));
  OptimizeSettings numbered;
  numbered.set("knots_per_interval", 2);
  for (const auto& [key, text] : settings_entries(numbered))
    stored[key] = text;
  EXPECT_EQ(stored.count("optimize/knots_per_interval"), 0u);
  EXPECT_EQ(from(stored).get("knots_per_interval"), OptionValue(2));
}

TEST(OptimizeSettings, ACostlyValueIsSaidOnceWhenItIsSet) {
  OptimizeSettings before;
  OptimizeSettings after = before;
  EXPECT_TRUE(newly_costly_settings(before, after).empty());
  after.set("samples", 100000);
  const std::vector<std::string> said = newly_costly_settings(before, after);
  ASSERT_EQ(said.size(), 1u);
  EXPECT_EQ(said[0].rfind("Samples = 100000: ", 0), 0u) << said[0];
  EXPECT_NE(said[0].find("1.6 GB"), std::string::npos) << said[0];
  // Already costly before: not said again; back to cheap: nothing to say.
  OptimizeSettings more = after;
  more.set("samples", 50000);
  EXPECT_TRUE(newly_costly_settings(after, more).empty());
  EXPECT_TRUE(newly_costly_settings(after, before).empty());
  // At the threshold itself it is not costly; words ("auto") never are.
  after = before;
  after.set("samples", 2001);
  EXPECT_TRUE(newly_costly_settings(before, after).empty());
  after.set("knots_per_interval", 20);
  EXPECT_EQ(newly_costly_settings(before, after).size(), 1u);
}

/// One short optimisation shared by the tests below (a few iterations on a coarse grid).
class OptimizedMotion : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    file_ = new MotionFile(load_motion_file(test::gui_test_motion_path()));
    OptimizeSettings s;
    s.set("max_iterations", 3);
    s.set("samples", 31);
    options_ = new OptimizeOptions(to_optimize_options(s));
    result_ = new OptimizationResult(optimize_motion(file_->motion, file_->model, *options_));
    folder_ = (saltus::test::temp_path("saltus_gui_optimize_settings_M")).string();
    fs::remove_all(folder_);
    write_optimization_outputs(folder_, *file_, *result_, *options_);
  }
  static void TearDownTestSuite() {
    fs::remove_all(folder_);
    delete result_;
    delete options_;
    delete file_;
  }
  static MotionFile* file_;
  static OptimizeOptions* options_;
  static OptimizationResult* result_;
  static std::string folder_;
};
MotionFile* OptimizedMotion::file_ = nullptr;
OptimizeOptions* OptimizedMotion::options_ = nullptr;
OptimizationResult* OptimizedMotion::result_ = nullptr;
std::string OptimizedMotion::folder_;

TEST_F(OptimizedMotion, ResultTableHasTheRequiredRows) {
  const std::vector<ResultRow> rows = result_table(*result_, *options_);
  auto find = [&](const std::string& name) -> const ResultRow* {
    for (const ResultRow& r : rows)
      if (r.quantity == name) return &r;
    return nullptr;
  };
  for (const char* name : {"keyframes", "variables", "constraints", "objective J (N²)",
                           "average root force √(J/6) (N)", "iterations", "seconds"})
    EXPECT_NE(find(name), nullptr) << name;
  EXPECT_EQ(find("variables")->after, std::to_string(result_->variables));
  EXPECT_EQ(find("iterations")->after, std::to_string(result_->solve.iterations));
  ASSERT_NE(find("knots per keyframe interval K"), nullptr);
  // The panel's default is the automatic resolution.
  ASSERT_TRUE(options_->automatic_resolution);
  EXPECT_EQ(find("knots per keyframe interval K")->before, "auto");
  std::string spans;
  for (int s : result_->subdivisions)
    spans += (spans.empty() ? "" : ", ") + std::to_string(s);
  const bool uniform = std::all_of(result_->subdivisions.begin(), result_->subdivisions.end(),
                                   [&](int s) { return s == result_->knots_per_interval; });
  EXPECT_EQ(find("knots per keyframe interval K")->after,
            uniform ? std::to_string(result_->knots_per_interval) : spans);
  EXPECT_EQ(find("keyframes")->before, std::to_string(file_->motion.keyframes.size()));
  const ResultRow* turn = find("largest joint turn between control points (°)");
  ASSERT_NE(turn, nullptr);
  EXPECT_NEAR(std::stod(turn->after),
              largest_control_turn(result_->after.trajectory, 1) * 180.0 / M_PI, 0.5);
}

TEST_F(OptimizedMotion, KnotRowNamesEachIntervalsSpansWhenTheyDiffer) {
  auto knot_row = [](const OptimizationResult& r, const OptimizeOptions& o) {
    for (const ResultRow& row : result_table(r, o))
      if (row.quantity == "knots per keyframe interval K") return row;
    return ResultRow{};
  };
  OptimizationResult r = *result_;
  r.subdivisions = {2, 3, 2};
  r.knots_per_interval = 3;
  EXPECT_EQ(knot_row(r, *options_).after, "2, 3, 2");
  r.subdivisions = {3, 3, 3};
  EXPECT_EQ(knot_row(r, *options_).after, "3");
  OptimizeSettings uniform;
  uniform.set("knots_per_interval", 2);
  EXPECT_EQ(knot_row(r, to_optimize_options(uniform)).before, "2");
  OptimizeSettings strict;
  strict.set("formulation", std::string("strict"));  // no automatic resolution: K = 1
  EXPECT_EQ(knot_row(r, to_optimize_options(strict)).before, "1");
}

TEST_F(OptimizedMotion, ReadsTheOutputFolderBack) {
  const ResultFolder f = read_optimization_folder(folder_);
  EXPECT_EQ(f.name, "saltus_gui_optimize_settings_M");
  EXPECT_EQ(f.result.motion, file_->motion.name);
  ASSERT_TRUE(f.after && f.result.optimization);
  EXPECT_EQ(f.before.samples.size(), 31u);
  EXPECT_EQ(f.after->samples.size(), 31u);
  EXPECT_EQ(f.result.before.avg_root_force, result_->before.metrics.avg_root_force);
  EXPECT_EQ(f.result.optimization->after.avg_root_force, result_->after.metrics.avg_root_force);
  EXPECT_EQ(f.result.optimization->keyframe_times_after, result_->after.keyframe_times);
  EXPECT_EQ(f.after->samples[10].root_wrench[0], result_->after.samples[10].root_wrench[0]);
}

TEST(ResultFolder, RejectsFoldersThatAreNotOptimisationResults) {
  EXPECT_THROW(read_optimization_folder("/nonexistent/folder"), InputError);
  const fs::path eval = saltus::test::temp_path("saltus_gui_not_optimized");
  fs::remove_all(eval);
  const MotionFile file = load_motion_file(test::gui_test_motion_path());
  EvaluateOptions options;
  options.samples = 11;
  write_evaluation_outputs(eval.string(), file, evaluate_motion(file.motion, file.model, options),
                           options);
  try {
    read_optimization_folder(eval.string());
    ADD_FAILURE() << "an evaluation folder was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/after"), std::string::npos) << e.what();
  }
  fs::remove_all(eval);
}

}  // namespace
}  // namespace saltus::gui
