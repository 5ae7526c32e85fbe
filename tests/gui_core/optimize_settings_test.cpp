// The optimisation panel's settings map onto the library's options like the CLI's flags; the
// result table and the figures read from a real `saltus optimize`-style output folder.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/optimize_settings.h"
#include "core/result_folder.h"
#include "gui_core/test_motion.h"
#include "saltus/base/input_error.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/result_json.h"
#include "support/temp_path.h"

namespace saltus::gui {
namespace {

namespace fs = std::filesystem;

TEST(OptimizeSettings, MapOntoTheLibraryOptions) {
  OptimizeSettings s;
  s.strict = true;
  s.epsilon = 40.0;
  s.optimize_timing = false;
  s.knots_per_interval = 2;
  s.max_iterations = 7;
  s.samples = 51;
  s.max_joint_turn_deg = 90.0;
  const OptimizeOptions o = to_optimize_options(s);
  EXPECT_EQ(o.nlp.formulation, Formulation::kStrict);
  EXPECT_DOUBLE_EQ(o.nlp.epsilon, 40.0);
  EXPECT_FALSE(o.nlp.optimize_timing);
  EXPECT_EQ(o.nlp.knots_per_interval, 2);
  EXPECT_FALSE(o.automatic_resolution);  // a number: uniform knots
  // The default, as `saltus optimize`'s: the automatic resolution.
  EXPECT_EQ(OptimizeSettings{}.knots_per_interval, 0);
  EXPECT_TRUE(to_optimize_options(OptimizeSettings{}).automatic_resolution);
  EXPECT_EQ(o.nlp.samples, 51);
  EXPECT_EQ(o.solver.max_iterations, 7);
  EXPECT_NEAR(o.nlp.joint_turn_limit, M_PI / 2, 1e-15);
  // The CLI's default limit, half a turn.
  EXPECT_NEAR(to_optimize_options(OptimizeSettings{}).nlp.joint_turn_limit, M_PI, 1e-15);
  // The CLI's defaults for what the panel does not show.
  EXPECT_DOUBLE_EQ(o.solver.tolerance, 1e-8);
  EXPECT_DOUBLE_EQ(o.solver.objective_change_tolerance, SolverOptions{}.objective_change_tolerance);
  EXPECT_EQ(OptimizeSettings{}.samples, kDefaultSamples);
  EXPECT_DOUBLE_EQ(o.nlp.max_time_shift, MotionNlpOptions{}.max_time_shift);
  EXPECT_DOUBLE_EQ(o.nlp.regularization, MotionNlpOptions{}.regularization);
  EXPECT_EQ(to_optimize_options(OptimizeSettings{}).nlp.formulation, Formulation::kRelaxed);
}

TEST(OptimizeSettings, RejectValuesOutOfRange) {
  OptimizeSettings s;
  s.epsilon = 0;
  EXPECT_THROW(to_optimize_options(s), std::invalid_argument);
  s = {};
  s.knots_per_interval = -1;
  EXPECT_THROW(to_optimize_options(s), std::invalid_argument);
  s = {};
  s.samples = 1;
  EXPECT_THROW(to_optimize_options(s), std::invalid_argument);
  s = {};
  s.max_iterations = -1;
  EXPECT_THROW(to_optimize_options(s), std::invalid_argument);
  s = {};
  s.max_joint_turn_deg = -1;
  EXPECT_THROW(to_optimize_options(s), std::invalid_argument);
}

TEST(OptimizeSettings, ProgressTextNamesIterationAndObjective) {
  ProgressInfo p;
  p.iteration = 12;
  p.objective = 34.1;
  p.elapsed_seconds = 3.21;
  const std::string text = progress_text(p);
  EXPECT_NE(text.find("iteration 12"), std::string::npos);
  EXPECT_NE(text.find("3.4100e+01"), std::string::npos);
}

/// One short optimisation shared by the tests below (a few iterations on a coarse grid).
class OptimizedMotion : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    file_ = new MotionFile(load_motion_file(test::gui_test_motion_path()));
    OptimizeSettings s;
    s.max_iterations = 3;
    s.samples = 31;
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
  EXPECT_EQ(find("knots per keyframe interval K")->after,
            std::to_string(result_->knots_per_interval));
  EXPECT_EQ(find("keyframes")->before, std::to_string(file_->motion.keyframes.size()));
  const ResultRow* turn = find("largest joint turn between control points (°)");
  ASSERT_NE(turn, nullptr);
  EXPECT_NEAR(std::stod(turn->after),
              largest_control_turn(result_->after.trajectory, 1) * 180.0 / M_PI, 0.5);
}

TEST_F(OptimizedMotion, ReadsTheOutputFolderBack) {
  const ResultFolder f = read_result_folder(folder_);
  EXPECT_EQ(f.name, "saltus_gui_optimize_settings_M");
  EXPECT_EQ(f.motion, file_->motion.name);
  EXPECT_EQ(f.before.time.size(), 31u);
  EXPECT_EQ(f.after.time.size(), 31u);
  EXPECT_NEAR(f.avg_root_force_before, result_->before.metrics.avg_root_force, 1e-9);
  EXPECT_NEAR(f.avg_root_force_after, result_->after.metrics.avg_root_force, 1e-9);
  EXPECT_EQ(f.keyframe_times_after, result_->after.keyframe_times);
  EXPECT_NEAR(f.after.component[0][10], result_->after.samples[10].root_wrench[0], 1e-12);
}

TEST_F(OptimizedMotion, PaperFiguresAreNamedPerFolderWithASummary) {
  const ResultFolder f = read_result_folder(folder_);
  const std::vector<Figure> figures = paper_figures({f, f});
  ASSERT_EQ(figures.size(), 7u);
  EXPECT_EQ(figures[0].file_name, "saltus_gui_optimize_settings_M_root_force.png");
  EXPECT_EQ(figures[1].file_name, "saltus_gui_optimize_settings_M_root_moment.png");
  EXPECT_EQ(figures[2].file_name, "saltus_gui_optimize_settings_M_keyframe_times.png");
  EXPECT_EQ(figures[3].file_name, "saltus_gui_optimize_settings_M-2_root_force.png");
  EXPECT_EQ(figures[6].file_name, "average_root_force.png");
  EXPECT_EQ(figures[0].chart.lines.size(), 6u);  // F1..F3 before and after
  EXPECT_EQ(figures[2].chart.x_labels.size(), file_->motion.keyframes.size());
  ASSERT_EQ(figures[6].chart.lines.size(), 2u);
  EXPECT_EQ(figures[6].chart.lines[0].kind, LineKind::kBars);
}

TEST(ResultFolder, RejectsFoldersThatAreNotOptimisationResults) {
  EXPECT_THROW(read_result_folder("/nonexistent/folder"), InputError);
  const fs::path eval = saltus::test::temp_path("saltus_gui_not_optimized");
  fs::remove_all(eval);
  const MotionFile file = load_motion_file(test::gui_test_motion_path());
  EvaluateOptions options;
  options.samples = 11;
  write_evaluation_outputs(eval.string(), file, evaluate_motion(file.motion, file.model, options),
                           options);
  try {
    read_result_folder(eval.string());
    ADD_FAILURE() << "an evaluation folder was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/after"), std::string::npos) << e.what();
  }
  fs::remove_all(eval);
}

}  // namespace
}  // namespace saltus::gui
