#include "core/chart_spec.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace saltus::gui {

AxisRange y_range(const ChartSpec& chart, bool right_axis) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const LineSpec& line : chart.lines) {
    if (line.right_axis != right_axis) continue;
    for (double y : line.y) {
      if (!std::isfinite(y)) continue;
      lo = std::min(lo, y);
      hi = std::max(hi, y);
    }
    if (line.kind == LineKind::kBars && !line.y.empty()) {
      lo = std::min(lo, 0.0);
      hi = std::max(hi, 0.0);
    }
  }
  if (!(lo <= hi)) return {};
  const double span = hi - lo;
  const double pad = span > 0 ? 0.05 * span : std::max(1.0, 0.05 * std::abs(hi));
  return {lo - pad, hi + pad};
}

namespace {
constexpr double kMaxLogDecades = 4.0;
}  // namespace

AxisRange log_y_range(const ChartSpec& chart) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = 0.0;
  for (const LineSpec& line : chart.lines) {
    if (line.right_axis) continue;
    for (double y : line.y) {
      if (!std::isfinite(y) || y <= 0) continue;
      lo = std::min(lo, y);
      hi = std::max(hi, y);
    }
  }
  if (!(hi > 0)) return {1.0, 10.0};
  // At most kMaxDecades below the largest value: a curve that touches zero must not spend the
  // axis on its dips.
  lo = std::max(lo, hi * std::pow(10.0, -kMaxLogDecades));
  // A little room above the largest value and below the smallest, in log space (5 %), and at
  // least one decade so that a flat curve still gets an axis with a label.
  double log_lo = std::log10(lo), log_hi = std::log10(hi);
  const double pad = 0.05 * std::max(log_hi - log_lo, 1.0);
  log_lo -= pad;
  log_hi += pad;
  if (log_hi - log_lo < 1.0) {
    const double mid = 0.5 * (log_lo + log_hi);
    log_lo = mid - 0.5;
    log_hi = mid + 0.5;
  }
  return {std::pow(10.0, log_lo), std::pow(10.0, log_hi)};
}

std::vector<double> log_ticks(const AxisRange& range) {
  std::vector<double> ticks;
  if (!(range.min > 0) || !(range.max > range.min)) return ticks;
  const int first = static_cast<int>(std::floor(std::log10(range.min)));
  const int last = static_cast<int>(std::ceil(std::log10(range.max)));
  // Rounding: a power of ten at the very end of the range counts as inside.
  const auto inside = [&](double v) {
    return v >= range.min * (1 - 1e-9) && v <= range.max * (1 + 1e-9);
  };
  for (int e = first; e <= last; ++e)
    if (inside(std::pow(10.0, e))) ticks.push_back(std::pow(10.0, e));
  if (ticks.size() >= 3) return ticks;
  ticks.clear();
  for (int e = first; e <= last; ++e)
    for (double m : {1.0, 2.0, 5.0})
      if (inside(m * std::pow(10.0, e))) ticks.push_back(m * std::pow(10.0, e));
  return ticks;
}

std::string tick_label(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

AxisRange x_range(const ChartSpec& chart) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const LineSpec& line : chart.lines)
    for (double x : line.x) {
      if (!std::isfinite(x)) continue;
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  for (const MarkerSpec& m : chart.markers) {
    lo = std::min(lo, m.x);
    hi = std::max(hi, m.x);
  }
  if (!(lo <= hi)) return {};
  if (lo == hi) return {lo - 0.5, hi + 0.5};
  return {lo, hi};
}

}  // namespace saltus::gui
