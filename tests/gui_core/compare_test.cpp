// The compare view's logic: where a result folder's run comes from, the shared timeline, and the
// overlay chart of two runs' root wrenches.

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "core/compare.h"
#include "core/document.h"
#include "gui_core/test_motion.h"
#include "saltus/base/input_error.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/result_json.h"
#include "saltus/use_cases/result_folders.h"
#include "support/temp_path.h"

namespace saltus::gui {
namespace {

namespace fs = std::filesystem;

WrenchSeries ramp(double scale) {
  WrenchSeries s;
  s.time = {0.0, 0.5, 1.0};
  for (int i = 0; i < 6; ++i)
    s.component[static_cast<std::size_t>(i)] = {scale * i, scale * (i + 1), scale * (i + 2)};
  return s;
}

TEST(CompareChart, OverlaysBothRunsInTheirOwnColoursAndThePlotsStyle) {
  WrenchSeries a = ramp(1.0), b = ramp(2.0);
  a.force_magnitude = {1, 2, 3};
  b.force_magnitude = {2, 4, 6};
  RootChartStyle style;
  const ChartSpec force = compare_root_chart(style, {&a, &b}, {"given", "heavy"});
  ASSERT_EQ(force.lines.size(), 2u);
  EXPECT_EQ(force.y_title, "|F| (N)");
  EXPECT_EQ(force.x_title, "time (s)");
  // Compact legends: the run's name alone; the first dashed, the second solid (as before and
  // after in the main window).
  EXPECT_EQ(force.lines[0].label, "given");
  EXPECT_EQ(force.lines[1].label, "heavy");
  EXPECT_TRUE(force.lines[0].dashed);
  EXPECT_FALSE(force.lines[1].dashed);
  EXPECT_EQ(force.lines[1].y, b.force_magnitude);
  // The runs differ in hue: blue (b > r) for the first, orange (r > b) for the second.
  EXPECT_GT(force.lines[0].colour.b, force.lines[0].colour.r);
  EXPECT_GT(force.lines[1].colour.r, force.lines[1].colour.b);
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(compare_colour(0, c).b, compare_colour(0, c).r);
    EXPECT_GT(compare_colour(1, c).r, compare_colour(1, c).b);
  }

  style.moment = true;
  style.components = true;
  style.axes = {false, true, false};
  const ChartSpec moment = compare_root_chart(style, {&a, &b}, {"given", "heavy"});
  ASSERT_EQ(moment.lines.size(), 2u);
  EXPECT_EQ(moment.y_title, "root moment (N·m)");
  EXPECT_EQ(moment.lines[0].label, "y given");
  EXPECT_EQ(moment.lines[0].y, a.component[4]);
  EXPECT_EQ(moment.lines[1].y, b.component[4]);
}

TEST(CompareChart, JointLoadsOfBothRunsAtOneJoint) {
  Document d;
  d.load(test::gui_test_motion_path(), "", 21);
  const BodyModel& model = d.file().model;
  const int hip = model.joint_index("hip_r");
  const std::vector<SampleRecord>& s = d.plot_samples(Stage::kBefore);
  const ChartSpec chart = compare_joint_chart(model, hip, false, {&s, &s}, {"a", "b"});
  ASSERT_EQ(chart.lines.size(), 2u);
  EXPECT_NE(chart.title.find("right hip"), std::string::npos) << chart.title;
  EXPECT_DOUBLE_EQ(chart.lines[0].y[7],
                   s[7].joint_wrench[static_cast<std::size_t>(hip)].head<3>().norm());
  const ChartSpec moment = compare_joint_chart(model, hip, true, {&s, &s}, {"a", "b"});
  EXPECT_DOUBLE_EQ(moment.lines[1].y[7],
                   s[7].joint_wrench[static_cast<std::size_t>(hip)].tail<3>().norm());
  EXPECT_THROW(compare_joint_chart(model, 99, false, {&s, &s}, {"a", "b"}), std::out_of_range);
}

TEST(CompareTimeline, RunsOverTheLongerFlightAndEachViewStopsAtItsEnd) {
  EXPECT_DOUBLE_EQ(compare_duration(2.04, 1.5), 2.04);
  EXPECT_DOUBLE_EQ(compare_duration(1.0, 1.5), 1.5);
  EXPECT_DOUBLE_EQ(run_time(1.8, 1.5), 1.5);
  EXPECT_DOUBLE_EQ(run_time(0.7, 1.5), 0.7);
  EXPECT_DOUBLE_EQ(run_time(-0.1, 1.5), 0.0);
}

TEST(FolderRun, EvaluateFolderGivesItsMotionWithTheModelCopy) {
  const fs::path dir = saltus::test::temp_path("saltus_gui_compare_eval");
  fs::remove_all(dir);
  const MotionFile file = load_motion_file(test::gui_test_motion_path());
  EvaluateOptions options;
  options.samples = 11;
  write_evaluation_outputs(dir.string(), file, evaluate_motion(file.motion, file.model, options),
                           options);
  const FolderRun run = folder_run(dir.string());
  EXPECT_EQ(run.motion_path, file.path);
  EXPECT_EQ(run.model_path, (dir / "model.json").string());
  EXPECT_EQ(run.label, "saltus_gui_compare_eval");
  EXPECT_NE(run.description.find("interpolated"), std::string::npos);
  // What the compare view then does: load it as the main view would.
  Document document;
  document.load(run.motion_path, run.model_path, 11);
  EXPECT_EQ(document.file().motion.name, file.motion.name);
  fs::remove_all(dir);

  EXPECT_THROW(folder_run("/nonexistent/folder"), InputError);
  EXPECT_THROW(folder_run(SALTUS_EXAMPLES_DIR), InputError);
}

}  // namespace
}  // namespace saltus::gui
