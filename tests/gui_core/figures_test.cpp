// Exported figures: titled with the motion and the settings, resultants on a log axis with the
// "after" curve, distinct short bar labels, human names in the mass study's panels.

#include <gtest/gtest.h>

#include <set>

#include "core/figures.h"
#include "core/twist_report.h"

namespace saltus::gui {
namespace {

/// An optimisation folder as the library reads it (read_result_folder), not on disk: its
/// curves come from its CSV samples.
ResultFolder folder(const std::string& name, double before, double after) {
  ResultFolder f;
  f.path = "/nonexistent/" + name;
  f.name = name;
  f.result.kind = ResultJson::Kind::kOptimization;
  f.result.motion = "M1 straight back somersault";
  f.result.status = "solved";
  f.result.options = {{"formulation", std::string("relaxed")}};
  f.result.before.avg_root_force = before;
  f.result.keyframe_times_before = {0.0, 1.0, 2.0};
  ResultJson::Optimization o;
  o.iterations = 25;
  o.after.avg_root_force = after;
  o.keyframe_times_after = {0.0, 1.1, 2.0};
  f.result.optimization = o;
  for (double t : {0.0, 1.0, 2.0}) {
    SampleRecord r;
    r.time = t;
    r.root_wrench << 1.0, -2.0, 3.0, 1.0, -2.0, 3.0;
    f.before.samples.push_back(r);
  }
  f.after = f.before;
  return f;
}

TEST(Figures, EveryFigureIsTitledWithTheMotionAndTheSettings) {
  const std::vector<Figure> figures =
      result_figures({folder("M1-opt", 10.6, 0.5), folder("M2-opt", 20.0, 1.0)});
  std::set<std::string> names;
  for (const Figure& f : figures) {
    names.insert(f.file_name);
    if (f.file_name == "average_root_force.png") continue;
    EXPECT_NE(f.chart.title.find("M1 straight back somersault"), std::string::npos) << f.file_name;
    EXPECT_NE(f.chart.title.find("relaxed"), std::string::npos) << f.file_name;
    EXPECT_NE(f.chart.title.find("solved in 25 iterations"), std::string::npos) << f.file_name;
  }
  for (const char* expected :
       {"M1-opt_root_force.png", "M1-opt_root_moment.png", "M1-opt_root_force_components.png",
        "M1-opt_keyframe_times.png", "M2-opt_root_moment_components.png", "average_root_force.png"})
    EXPECT_TRUE(names.count(expected)) << expected;
  // The paper's Fig. 4 plots |F|; here before and after, on a log axis so "after" shows.
  const Figure& force = figures[0];
  ASSERT_EQ(force.file_name, "M1-opt_root_force.png");
  ASSERT_EQ(force.chart.lines.size(), 2u);
  EXPECT_TRUE(force.chart.log_y);
  EXPECT_EQ(force.chart.lines[0].label, "|F| before");
  EXPECT_EQ(force.chart.lines[1].label, "|F| after");
  // Keyframe lines are named in the legend.
  bool named = false;
  for (const MarkerSpec& m : force.chart.markers)
    named = named || m.label == "keyframes (optimised)";
  EXPECT_TRUE(named);
}

TEST(Figures, AverageForceAfterOptimisationIsReadableBesideBefore) {
  // 450 N before, 0.15 N after: on a linear axis the after value was a line of zero height.
  const ChartSpec chart = average_root_force_figure(
      {folder("M7-double-front", 450, 0.15), folder("M1-straight-back-somersault", 10, 0.09)});
  EXPECT_TRUE(chart.log_y);
  const AxisRange range = log_y_range(chart);
  EXPECT_LE(range.min, 0.09);
  EXPECT_GE(range.max, 450.0);
  ASSERT_EQ(chart.lines.size(), 2u);
  for (const LineSpec& line : chart.lines) {
    EXPECT_EQ(line.kind, LineKind::kPoints) << "bars on a log axis would start at 1 N";
    for (std::size_t i = 0; i < line.x.size(); ++i)
      EXPECT_NEAR(line.x[i], static_cast<double>(i), 0.25) << "within its result's label";
  }
}

TEST(Figures, AverageForcePairsHaveShortDistinctLabels) {
  const ChartSpec chart = average_root_force_figure(
      {folder("M1-straight-back-somersault", 10, 1), folder("M2-tucked-back-somersault", 20, 2)});
  ASSERT_EQ(chart.x_labels.size(), 2u);
  EXPECT_EQ(chart.x_labels[0], "M1");
  EXPECT_EQ(chart.x_labels[1], "M2");
  // Same first word twice: numbers, with the names listed in the title.
  const ChartSpec numbered =
      average_root_force_figure({folder("relaxed-a", 10, 1), folder("relaxed-b", 20, 2)});
  EXPECT_EQ(numbered.x_labels[0], "1");
  EXPECT_NE(numbered.title.find("1 relaxed-a"), std::string::npos) << numbered.title;
}

TEST(Figures, TitlesGoOnTwoLinesAndStemsAreFileSafe) {
  ChartSpec c;
  c.title = "Root force |F|";
  EXPECT_EQ(titled_figure(c, "M1", "relaxed").title, "Root force |F|\nM1 · relaxed");
  EXPECT_EQ(titled_figure(c, "M1", "").title, "Root force |F|\nM1");
  // Too long for one line of a figure (the dive's name and its settings): a line each.
  const std::string dive = "5 m platform dive: forward 1 1/2 somersaults with 1 1/2 twists";
  const std::string settings =
      "relaxed · solved in 54 iterations · average root force 118 → 11.2 N";
  EXPECT_EQ(titled_figure(c, dive, settings).title, "Root force |F|\n" + dive + "\n" + settings);
  EXPECT_EQ(figure_stem("M1 straight/back"), "M1_straight_back");
}

TEST(Figures, MassStudyPanelsNameTheSegmentsAsPeopleDo) {
  MassStudyFolder f;
  f.path = "/nonexistent";
  f.name = "mass-M7";
  f.motion = "M7";
  f.runs[0].label = "given";
  f.runs[1].label = "thigh_l+thigh_r x1.5";
  f.scaled_segments = {"thigh_l", "thigh_r"};
  f.factor = 1.5;
  f.loads.time = {0.0, 1.0};
  f.loads.load_segments = {"thigh_r"};
  f.loads.loads.resize(1);
  f.loads.loads[0][0].force_N = {1, 2};
  f.loads.loads[0][0].moment_Nm = {5, 6};
  f.loads.loads[0][1].force_N = {3, 4};
  f.loads.loads[0][1].moment_Nm = {7, 8};
  const std::vector<FigureGrid> grids = mass_study_load_figures({f});
  ASSERT_EQ(grids.size(), 1u);
  ASSERT_EQ(grids[0].panels.size(), 2u);
  EXPECT_NE(grids[0].panels[0].title.find("right thigh"), std::string::npos)
      << grids[0].panels[0].title;
  EXPECT_EQ(grids[0].panels[0].title.find("thigh_r"), std::string::npos);
  EXPECT_EQ(grids[0].panels[1].lines[1].y, (std::vector<double>{7, 8}));
  EXPECT_EQ(grids[0].panels[0].lines[1].label, "model with left and right thighs × 1.5");
}

TEST(Figures, ATwistFolderGivesThePanelsChartUnderItsSentence) {
  TwistFolder f;
  f.name = "twist-M7";
  f.motion = "M7 double front";
  f.sources.reference_time_s = 1.0;
  f.sources.total_tilt_deg = -20.0;
  f.sources.twists = 1.5;
  f.sources.shares = {{"take-off", -20.0, 100.0}, {"left arm", 0.0, 0.0}};
  f.sources.times = {0.0, 1.0, 2.0};
  f.sources.flight_names = {"actual", "take-off only", "without left arm"};
  f.sources.tilt_deg = {{0, -20, 0}, {0, -20, 0}, {0, -20, 0}};
  f.sources.sentence = "Of the 20° of tilt at mid-flight, 100 % came from the take-off.";
  const std::vector<Figure> figures = twist_figures({f});
  ASSERT_EQ(figures.size(), 1u);
  EXPECT_EQ(figures[0].file_name, "twist-M7_twist.png");
  const ChartSpec& c = figures[0].chart;
  // The sentence first, then the motion, then its tilt and twists (the panel's summary line).
  EXPECT_EQ(c.title.rfind(f.sources.sentence + "\nM7 double front", 0), 0u) << c.title;
  EXPECT_NE(c.title.find("1.50 twists"), std::string::npos) << c.title;
  const ChartSpec panel = twist_report(f.sources).chart;
  ASSERT_EQ(c.lines.size(), panel.lines.size());
  for (std::size_t k = 0; k < c.lines.size(); ++k) {
    EXPECT_EQ(c.lines[k].label, panel.lines[k].label);
    EXPECT_EQ(c.lines[k].y, panel.lines[k].y);
  }
  EXPECT_EQ(c.lines[1].label, "left arm made symmetric");
}

}  // namespace
}  // namespace saltus::gui
