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

TEST(CompareChart, OverlaysBothRunsInTheirOwnColours) {
  const WrenchSeries a = ramp(1.0), b = ramp(2.0);
  const ChartSpec force = compare_root_chart(false, {&a, &b}, {"given", "heavy"}, all_components());
  ASSERT_EQ(force.lines.size(), 6u);
  EXPECT_EQ(force.y_title, "root force (N)");
  EXPECT_EQ(force.x_title, "time (s)");
  std::set<std::string> labels;
  for (std::size_t i = 0; i < 6; ++i) {
    const LineSpec& line = force.lines[i];
    labels.insert(line.label);
    const bool second = i >= 3;
    EXPECT_EQ(line.dashed, second);
    EXPECT_NE(line.label.find(second ? "heavy" : "given"), std::string::npos) << line.label;
    EXPECT_EQ(line.y, (second ? b : a).component[i % 3]);
  }
  EXPECT_EQ(labels.size(), 6u);  // every legend entry distinct
  // The runs differ in hue: blue (b > r) for the first, orange (r > b) for the second.
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(compare_colour(0, c).b, compare_colour(0, c).r);
    EXPECT_GT(compare_colour(1, c).r, compare_colour(1, c).b);
  }

  const ChartSpec moment = compare_root_chart(true, {&a, &b}, {"given", "heavy"},
                                              {false, false, false, false, true, false});
  ASSERT_EQ(moment.lines.size(), 2u);
  EXPECT_EQ(moment.y_title, "root moment (N·m)");
  EXPECT_EQ(moment.lines[0].y, a.component[4]);
  EXPECT_EQ(moment.lines[1].y, b.component[4]);
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
