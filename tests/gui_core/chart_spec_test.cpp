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

TEST(ChartSpec, LogRangeStopsSixDecadesBelowTheLargestValue) {
  const AxisRange r = log_y_range(chart_of({1000.0, 1e-9, 50.0}));
  EXPECT_GT(r.min, 5e-4);  // 1000 × 1e-6 = 1e-3, padded
  EXPECT_LT(r.min, 1e-3);
}

TEST(ChartSpec, LogFloorFollowsEachCurvesLowValuesNotItsDips) {
  // The case: before 100-1600 N; after optimisation 0.1-4 N, most of it near 0.2 N,
  // with two dips towards zero. The floor sits under the after curve's bulk (its 10th
  // percentile, padded), not four decades under 1600 N (0.16 N, where only its spikes
  // showed), nor at its dips.
  std::vector<double> before, after;
  for (int i = 0; i < 100; ++i) {
    before.push_back(100.0 + 15.0 * i);
    after.push_back(i % 10 == 3 ? 4.0 : 0.12 + 0.002 * i);
  }
  after[50] = 1e-7;
  after[51] = 1e-6;
  const AxisRange r = log_y_range(chart_of(before, after));
  EXPECT_LT(r.min, 0.12);
  EXPECT_GT(r.min, 0.05);
  EXPECT_GT(r.max, 1585.0);
}

TEST(ChartSpec, LogTicksArePowersOfTenOverSeveralDecades) {
  // The widest range log_y_range gives (four decades and padding): one label a decade, not the
  // twelve 1-2-5 labels that overlapped on a laptop's 120-pixel plot.
  const std::vector<double> ticks = log_ticks({0.07, 1500.0});
  EXPECT_EQ(ticks, (std::vector<double>{0.1, 1.0, 10.0, 100.0, 1000.0}));
}

TEST(ChartSpec, LogTicksTakeEveryOtherPowerOverManyDecades) {
  const std::vector<double> ticks = log_ticks({5e-4, 1800.0});
  EXPECT_EQ(ticks, (std::vector<double>{1e-3, 0.1, 10.0, 1000.0}));
}

TEST(ChartSpec, LinearTicksAreAtLeastTwoAndAtMostTheLimitOnOneTwoFiveSteps) {
  EXPECT_EQ(linear_ticks({0.0, 1.0}), (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_EQ(linear_ticks({-0.05, 1.6}), (std::vector<double>{0.0, 0.5, 1.0, 1.5}));
  EXPECT_EQ(linear_ticks({-52.0, 1750.0}), (std::vector<double>{0.0, 500.0, 1000.0, 1500.0}));
  // A family of ranges: never one label, never more than asked, evenly spaced inside.
  for (double lo : {-3.7, 0.0, 0.013, 12.0, 990.0})
    for (double span : {0.011, 0.7, 1.0, 3.3, 47.0, 1234.0}) {
      for (std::size_t most : {5u, 6u, 8u}) {
        const std::vector<double> ticks = linear_ticks({lo, lo + span}, most);
        ASSERT_GE(ticks.size(), 2u) << lo << " " << span;
        EXPECT_LE(ticks.size(), most) << lo << " " << span;
        EXPECT_GE(ticks.front(), lo - 1e-9 * span);
        EXPECT_LE(ticks.back(), lo + span + 1e-9 * span);
        for (std::size_t i = 2; i < ticks.size(); ++i)
          EXPECT_NEAR(ticks[i] - ticks[i - 1], ticks[1] - ticks[0], 1e-9 * span);
      }
    }
  EXPECT_TRUE(linear_ticks({1.0, 1.0}).empty());
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
