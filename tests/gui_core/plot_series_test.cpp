// Plot series: the charts carry exactly the library's numbers, with units and styles.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/document.h"
#include "core/plot_series.h"
#include "gui_core/test_motion.h"
#include "saltus/evaluation/force_metrics.h"
#include "saltus/formats/trajectory_csv.h"
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

TEST(PlotSamples, NeverCoarserThanTheDenseResidualCheck) {
  // Short flights keep the plots' own grid; longer ones the check's spacing, and no finer.
  EXPECT_EQ(plot_samples_for(0.5), kPlotSamples);
  for (double duration : {0.3, 1.7, 2.04, 6.01, 12.345, 30.0}) {
    const int n = plot_samples_for(duration);
    EXPECT_GE(n, kPlotSamples) << duration;
    EXPECT_LE(duration / (n - 1), kCheckMaxSpacing * (1 + 1e-12)) << duration;
    if (n > kPlotSamples) {
      EXPECT_GT(duration / (n - 2), kCheckMaxSpacing) << duration;
    }
  }
}

TEST_F(PlotSeriesTest, RootWrenchSeriesCarriesF1ToF6) {
  const WrenchSeries w = root_wrench_series(samples());
  ASSERT_EQ(w.time.size(), samples().size());
  for (std::size_t k = 0; k < samples().size(); ++k)
    for (int i = 0; i < 6; ++i)
      EXPECT_EQ(w.component[i][k], samples()[k].root_wrench[i]);
}

TEST_F(PlotSeriesTest, RootWrenchSeriesCarriesTheResultantsFromTheLibrary) {
  const WrenchSeries w = root_wrench_series(samples());
  ASSERT_EQ(w.force_magnitude.size(), samples().size());
  for (std::size_t k = 0; k < samples().size(); ++k) {
    EXPECT_DOUBLE_EQ(w.force_magnitude[k], samples()[k].root_wrench.head<3>().norm());
    EXPECT_DOUBLE_EQ(w.moment_magnitude[k], samples()[k].root_wrench.tail<3>().norm());
  }
}

TEST_F(PlotSeriesTest, RootChartShowsTheResultantByDefaultAsThePaperDoes) {
  const WrenchSeries w = root_wrench_series(samples());
  RootChartStyle style;
  style.body_weight_N = 650.0;
  const ChartSpec alone = root_chart(style, w, nullptr, {0.0, 1.0}, {0.0, 1.1});
  ASSERT_EQ(alone.lines.size(), 1u);
  // Alone, a motion's line is plain: no "before" without an "after".
  EXPECT_EQ(alone.lines[0].label, "|F|");
  EXPECT_FALSE(alone.lines[0].dashed);
  EXPECT_EQ(alone.lines[0].y, w.force_magnitude);
  EXPECT_EQ(alone.y_title, "|F| (N)");
  EXPECT_EQ(alone.x_title, "time (s)");
  // The right axis is the left one in % of body weight.
  EXPECT_EQ(alone.y2_title, "% of body weight");
  EXPECT_FALSE(alone.log_y);
  EXPECT_DOUBLE_EQ(alone.y2_per_y, 100.0 / 650.0);
  // Optimised times only with an "after"; the first of each kind of marker is in the legend.
  ASSERT_EQ(alone.markers.size(), 2u);
  EXPECT_EQ(alone.markers[0].label, "keyframes (given)");
  EXPECT_EQ(alone.markers[1].label, "");

  style.moment = true;
  style.log_scale = true;
  const ChartSpec both = root_chart(style, w, &w, {0.0, 1.0}, {0.0, 1.1});
  ASSERT_EQ(both.lines.size(), 2u);
  EXPECT_EQ(both.y_title, "|M| (N·m)");
  EXPECT_TRUE(both.log_y);
  EXPECT_EQ(both.y2_per_y, 0.0);  // body weight is for forces
  EXPECT_EQ(both.lines[0].label, "|M| before");
  EXPECT_TRUE(both.lines[0].dashed);
  EXPECT_EQ(both.lines[1].label, "|M| after");
  EXPECT_FALSE(both.lines[1].dashed);
  EXPECT_EQ(both.lines[1].y, w.moment_magnitude);
  ASSERT_EQ(both.markers.size(), 4u);
  EXPECT_EQ(both.markers[2].label, "keyframes (optimised)");
}

TEST_F(PlotSeriesTest, ComponentsOnDemandWithShortLegends) {
  const WrenchSeries w = root_wrench_series(samples());
  RootChartStyle style;
  style.components = true;
  style.axes = {true, false, true};
  style.log_scale = true;  // ignored: components change sign
  const ChartSpec chart = root_chart(style, w, &w, {}, {});
  ASSERT_EQ(chart.lines.size(), 4u);
  EXPECT_FALSE(chart.log_y);
  EXPECT_EQ(chart.lines[0].label, "x before");
  EXPECT_EQ(chart.lines[1].label, "z before");
  EXPECT_EQ(chart.lines[2].label, "x after");
  EXPECT_EQ(chart.lines[3].y, w.component[2]);
  EXPECT_EQ(chart.y_title, "root force (N)");
  // The form the result-folder figures use.
  ComponentMask mask = all_components();
  mask[4] = false;
  const ChartSpec moment = root_wrench_chart(true, w, nullptr, mask, {}, {});
  ASSERT_EQ(moment.lines.size(), 2u);
  EXPECT_EQ(moment.lines[1].y, w.component[5]);
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
  const ChartSpec angles = rotation_chart(RotationQuantity::kYeadonAngles, rotation, nullptr);
  ASSERT_EQ(angles.lines.size(), 3u);
  EXPECT_DOUBLE_EQ(angles.lines[1].y.back(), rotation.back().tilt_deg);
  EXPECT_NEAR(angles.lines[0].y.back() - angles.lines[0].y.front(),
              360.0 * rotation.back().somersaults, 1e-9);
  EXPECT_EQ(rotation_quantity_names().size(), 5u);
}

TEST_F(PlotSeriesTest, ReadsTheSameSeriesFromATrajectoryCsv) {
  const std::filesystem::path csv = saltus::test::temp_path("saltus_gui_plot_series.csv");
  {
    std::ofstream out(csv);
    write_trajectory_csv(out, document_.file().model, samples());
  }
  const WrenchSeries from_csv = root_wrench_series(read_trajectory_csv(csv.string()).samples);
  const WrenchSeries direct = root_wrench_series(samples());
  EXPECT_EQ(from_csv.time, direct.time);
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(from_csv.component[i], direct.component[i]);
  // The resultants of the CSV's components equal those of the samples (shortest round-trip
  // numbers in the file).
  ASSERT_EQ(from_csv.force_magnitude.size(), direct.force_magnitude.size());
  for (std::size_t k = 0; k < direct.force_magnitude.size(); ++k)
    EXPECT_NEAR(from_csv.force_magnitude[k], direct.force_magnitude[k],
                1e-12 * (1.0 + direct.force_magnitude[k]));

  std::filesystem::remove(csv);
}

}  // namespace
}  // namespace saltus::gui
