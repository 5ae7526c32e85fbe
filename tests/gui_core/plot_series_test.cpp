// Plot series: the charts carry exactly the library's numbers, with units and styles.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/document.h"
#include "core/plot_series.h"
#include "gui_core/test_motion.h"
#include "saltus/base/input_error.h"
#include "support/temp_path.h"

namespace saltus::gui {
namespace {

class PlotSeriesTest : public ::testing::Test {
 protected:
  void SetUp() override { document_.load(test::gui_test_motion_path(), "", 41); }
  const std::vector<SampleRecord>& samples() const {
    return document_.evaluation(Stage::kBefore).samples;
  }
  Document document_;
};

TEST_F(PlotSeriesTest, RootWrenchSeriesCarriesF1ToF6) {
  const WrenchSeries w = root_wrench_series(samples());
  ASSERT_EQ(w.time.size(), samples().size());
  for (std::size_t k = 0; k < samples().size(); ++k)
    for (int i = 0; i < 6; ++i)
      EXPECT_EQ(w.component[i][k], samples()[k].root_wrench[i]);
}

TEST_F(PlotSeriesTest, RootForceChartShowsTheSelectedComponentsBeforeAndAfter) {
  const WrenchSeries w = root_wrench_series(samples());
  ComponentMask mask = all_components();
  mask[1] = false;  // hide F2
  const ChartSpec before_only = root_wrench_chart(false, w, nullptr, mask, {0.0, 1.0}, {0.0, 1.1});
  ASSERT_EQ(before_only.lines.size(), 2u);
  // Alone, a motion's lines are plain: no "before" without an "after".
  EXPECT_EQ(before_only.lines[0].label, "F1 force x");
  EXPECT_EQ(before_only.lines[1].label, "F3 force z");
  EXPECT_FALSE(before_only.lines[0].dashed);
  EXPECT_EQ(before_only.y_title, "root force (N)");
  EXPECT_EQ(before_only.x_title, "time (s)");
  EXPECT_EQ(before_only.markers.size(), 2u);  // optimised times only with an "after"

  const ChartSpec both = root_wrench_chart(true, w, &w, mask, {0.0, 1.0}, {0.0, 1.1});
  ASSERT_EQ(both.lines.size(), 6u);
  EXPECT_EQ(both.y_title, "root moment (N·m)");
  EXPECT_EQ(both.lines[0].label, "F4 moment x, before");
  EXPECT_TRUE(both.lines[0].dashed);
  EXPECT_EQ(both.lines[3].label, "F4 moment x, after");
  EXPECT_FALSE(both.lines[3].dashed);
  EXPECT_EQ(both.lines[3].y, w.component[3]);
  EXPECT_EQ(both.markers.size(), 4u);
}

TEST_F(PlotSeriesTest, JointLoadChartHasForceAndMomentMagnitudes) {
  const BodyModel& model = document_.file().model;
  const int knee = model.joint_index("knee_l");
  const ChartSpec chart = joint_load_chart(model, knee, samples(), nullptr);
  ASSERT_EQ(chart.lines.size(), 2u);
  EXPECT_FALSE(chart.lines[0].right_axis);
  EXPECT_TRUE(chart.lines[1].right_axis);
  EXPECT_EQ(chart.y2_title, "moment |M| (N·m)");
  EXPECT_NE(chart.title.find("knee_l"), std::string::npos);
  for (std::size_t k = 0; k < samples().size(); ++k) {
    EXPECT_DOUBLE_EQ(chart.lines[0].y[k], samples()[k].joint_wrench[knee].head<3>().norm());
    EXPECT_DOUBLE_EQ(chart.lines[1].y[k], samples()[k].joint_wrench[knee].tail<3>().norm());
  }
  EXPECT_THROW(joint_load_chart(model, 99, samples(), nullptr), std::out_of_range);
}

TEST_F(PlotSeriesTest, RotationChartsShowTheLibrarysRotationMetrics) {
  const auto& rotation = document_.rotation(Stage::kBefore);
  const ChartSpec inertia = rotation_chart(RotationQuantity::kInertiaAndRate, rotation, &rotation);
  ASSERT_EQ(inertia.lines.size(), 4u);
  EXPECT_EQ(inertia.y_title, "inertia I_xx (kg·m²)");
  EXPECT_EQ(inertia.y2_title, "spin |ω_x| (rad/s)");
  EXPECT_DOUBLE_EQ(inertia.lines[0].y[5], rotation[5].somersault_inertia);
  EXPECT_DOUBLE_EQ(inertia.lines[1].y[5], std::abs(rotation[5].somersault_rate));
  EXPECT_TRUE(inertia.lines[1].right_axis);
  const ChartSpec momentum = rotation_chart(RotationQuantity::kAngularMomentum, rotation, nullptr);
  ASSERT_EQ(momentum.lines.size(), 3u);
  EXPECT_DOUBLE_EQ(momentum.lines[0].y[7], rotation[7].angular_momentum.x());
  const ChartSpec counts = rotation_chart(RotationQuantity::kCounts, rotation, nullptr);
  EXPECT_DOUBLE_EQ(counts.lines[0].y.back(), rotation.back().somersaults);
  EXPECT_EQ(rotation_quantity_names().size(), 4u);
}

TEST_F(PlotSeriesTest, ReadsTheSameSeriesFromATrajectoryCsv) {
  const std::filesystem::path csv = saltus::test::temp_path("saltus_gui_plot_series.csv");
  {
    std::ofstream out(csv);
    write_trajectory_csv(out, document_.file().model, samples());
  }
  const WrenchSeries from_csv = root_wrench_series(read_csv_table(csv.string()), csv.string());
  const WrenchSeries direct = root_wrench_series(samples());
  EXPECT_EQ(from_csv.time, direct.time);
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(from_csv.component[i], direct.component[i]);

  CsvTable missing;
  missing.columns = {"t", "root_fx"};
  EXPECT_THROW(root_wrench_series(missing, "x.csv"), InputError);
  std::filesystem::remove(csv);
}

}  // namespace
}  // namespace saltus::gui
