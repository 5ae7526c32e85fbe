// Axis ranges of charts, the logarithmic one in particular: positive values only, at least a
// decade, so a small "after" curve keeps its shape next to a large "before".

#include <gtest/gtest.h>

#include <cmath>

#include "core/chart_spec.h"

namespace saltus::gui {
namespace {

ChartSpec chart_of(std::vector<double> a, std::vector<double> b = {}) {
  ChartSpec c;
  LineSpec l1;
  l1.x.resize(a.size());
  l1.y = std::move(a);
  c.lines.push_back(l1);
  if (!b.empty()) {
    LineSpec l2;
    l2.x.resize(b.size());
    l2.y = std::move(b);
    c.lines.push_back(l2);
  }
  return c;
}

TEST(ChartSpec, LogRangeSpansTheDecadesOfBothCurves) {
  // Before around 800 N, after around 3 N: both inside the range, padded in log space.
  const AxisRange r = log_y_range(chart_of({800, 300, 120}, {3, 5, 0.9}));
  EXPECT_LT(r.min, 0.9);
  EXPECT_GT(r.min, 0.5);
  EXPECT_GT(r.max, 800);
  EXPECT_LT(r.max, 1500);
}

TEST(ChartSpec, LogRangeIgnoresZerosAndKeepsAtLeastADecade) {
  const AxisRange r = log_y_range(chart_of({0.0, 4.0, 5.0, -1.0}));
  EXPECT_GT(r.min, 0.0);
  EXPECT_NEAR(std::log10(r.max) - std::log10(r.min), 1.0, 1e-9);
  EXPECT_LT(r.min, 4.0);
  EXPECT_GT(r.max, 5.0);
  const AxisRange empty = log_y_range(chart_of({0.0, -2.0}));
  EXPECT_EQ(empty.min, 1.0);
  EXPECT_EQ(empty.max, 10.0);
}

TEST(ChartSpec, LogRangeStopsFourDecadesBelowTheLargestValue) {
  const AxisRange r = log_y_range(chart_of({1000.0, 1e-6, 50.0}));
  EXPECT_GT(r.min, 0.05);  // 1000 × 1e-4 = 0.1, padded
  EXPECT_LT(r.min, 0.1);
}

TEST(ChartSpec, LogTicksArePowersOfTenOverSeveralDecades) {
  // The widest range log_y_range gives (four decades and padding): one label a decade, not the
  // twelve 1-2-5 labels that overlapped on a laptop's 120-pixel plot.
  const std::vector<double> ticks = log_ticks({0.07, 1500.0});
  EXPECT_EQ(ticks, (std::vector<double>{0.1, 1.0, 10.0, 100.0, 1000.0}));
}

TEST(ChartSpec, LogTicksAddTwoAndFiveOnAShortRange) {
  // One decade: a single power of ten would leave the axis nearly unlabelled.
  const std::vector<double> ticks = log_ticks({3.0, 30.0});
  ASSERT_EQ(ticks.size(), 3u);
  EXPECT_DOUBLE_EQ(ticks[0], 5.0);
  EXPECT_DOUBLE_EQ(ticks[1], 10.0);
  EXPECT_DOUBLE_EQ(ticks[2], 20.0);
  EXPECT_TRUE(log_ticks({0.0, 10.0}).empty());
  EXPECT_EQ(tick_label(0.01), "0.01");
  EXPECT_EQ(tick_label(1000.0), "1000");
}

}  // namespace
}  // namespace saltus::gui
