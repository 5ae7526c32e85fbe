// CoM parabola sampling against the closed form s(t) = S0 + v t + ½ g t² (paper eq. 9).

#include <gtest/gtest.h>

#include "core/chart_spec.h"
#include "core/parabola.h"

namespace saltus::gui {
namespace {

TEST(Parabola, SamplesTheClosedFormAndFindsTheApex) {
  Takeoff takeoff;
  takeoff.com_position = Eigen::Vector3d(0.1, 1.0, -0.2);
  takeoff.com_velocity = Eigen::Vector3d(0.15, 10.0, 0.3);
  const ParabolaSamples p = sample_parabola(takeoff, 2.04, 103);
  ASSERT_EQ(p.points.size(), 103u);
  ASSERT_EQ(p.times.size(), 103u);
  EXPECT_DOUBLE_EQ(p.times.back(), 2.04);
  for (std::size_t k = 0; k < p.points.size(); ++k) {
    const double t = p.times[k];
    const Eigen::Vector3d expected = takeoff.com_position + takeoff.com_velocity * t +
                                     0.5 * Eigen::Vector3d(0, -9.81, 0) * t * t;
    EXPECT_LT((p.points[k] - expected).norm(), 1e-12);
  }
  EXPECT_NEAR(p.apex_time, 10.0 / 9.81, 1e-12);
  EXPECT_NEAR(p.apex.y(), 1.0 + 100.0 / (2 * 9.81), 1e-12);
}

TEST(Parabola, ApexIsClampedToTheFlightAndBadArgumentsThrow) {
  Takeoff down;
  down.com_velocity = Eigen::Vector3d(0, -1, 0);
  EXPECT_DOUBLE_EQ(sample_parabola(down, 1.0, 2).apex_time, 0.0);
  EXPECT_THROW(sample_parabola(down, 1.0, 1), std::invalid_argument);
  EXPECT_THROW(sample_parabola(down, 0.0, 5), std::invalid_argument);
}

TEST(ChartRanges, PadTheDataAndHandleFlatAndEmptyCharts) {
  ChartSpec chart;
  EXPECT_DOUBLE_EQ(y_range(chart, false).min, 0.0);
  EXPECT_DOUBLE_EQ(y_range(chart, false).max, 1.0);
  LineSpec line;
  line.x = {0, 1, 2};
  line.y = {-10, 0, 10};
  chart.lines.push_back(line);
  EXPECT_DOUBLE_EQ(y_range(chart, false).min, -11.0);
  EXPECT_DOUBLE_EQ(y_range(chart, false).max, 11.0);
  EXPECT_DOUBLE_EQ(y_range(chart, true).max, 1.0);  // nothing on the right axis
  EXPECT_DOUBLE_EQ(x_range(chart).min, 0.0);
  EXPECT_DOUBLE_EQ(x_range(chart).max, 2.0);
  LineSpec flat;
  flat.right_axis = true;
  flat.x = {0, 1};
  flat.y = {3, 3};
  chart.lines.push_back(flat);
  EXPECT_DOUBLE_EQ(y_range(chart, true).min, 2.0);
  EXPECT_DOUBLE_EQ(y_range(chart, true).max, 4.0);
  LineSpec bars;
  bars.kind = LineKind::kBars;
  bars.x = {0};
  bars.y = {5};
  ChartSpec bar_chart;
  bar_chart.lines.push_back(bars);
  EXPECT_LE(y_range(bar_chart, false).min, 0.0);
}

}  // namespace
}  // namespace saltus::gui
