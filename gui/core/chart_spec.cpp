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
/// The widest a logarithmic axis gets below its largest value, decades.
constexpr double kMaxLogDecades = 6.0;
/// A line's floor on a logarithmic axis: this quantile of its positive values, so that its bulk
/// shows and only its dips towards zero are cut.
constexpr double kLogFloorQuantile = 0.1;
/// The most labelled powers of ten on a logarithmic axis (more: every other one).
constexpr std::size_t kMaxLogLabels = 6;
}  // namespace

AxisRange log_y_range(const ChartSpec& chart) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = 0.0;
  for (const LineSpec& line : chart.lines) {
    if (line.right_axis) continue;
    std::vector<double> positive;
    for (double y : line.y)
      if (std::isfinite(y) && y > 0) positive.push_back(y);
    if (positive.empty()) continue;
    const std::size_t floor_index = static_cast<std::size_t>(
        std::floor(kLogFloorQuantile * static_cast<double>(positive.size() - 1)));
    std::nth_element(positive.begin(), positive.begin() + floor_index, positive.end());
    lo = std::min(lo, positive[floor_index]);
    hi = std::max(hi, *std::max_element(positive.begin(), positive.end()));
  }
  if (!(hi > 0)) return {1.0, 10.0};
  // The floor follows the data (each curve's low values, so that a small "after" keeps its
  // shape), at most kMaxLogDecades below the largest value.
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
  if (ticks.size() > kMaxLogLabels) {
    // Every other power, keeping the largest.
    std::vector<double> fewer;
    for (std::size_t i = ticks.size() % 2 == 0 ? 1 : 0; i < ticks.size(); i += 2)
      fewer.push_back(ticks[i]);
    return fewer;
  }
  if (ticks.size() >= 3) return ticks;
  ticks.clear();
  for (int e = first; e <= last; ++e)
    for (double m : {1.0, 2.0, 5.0})
      if (inside(m * std::pow(10.0, e))) ticks.push_back(m * std::pow(10.0, e));
  return ticks;
}

std::vector<double> linear_ticks(const AxisRange& range, std::size_t max_labels) {
  std::vector<double> ticks;
  const double span = range.max - range.min;
  if (!(span > 0) || !std::isfinite(span) || max_labels < 5) return ticks;
  // The smallest 1-2-5 step with at most max_labels multiples inside the range.
  double step = std::pow(10.0, std::floor(std::log10(span / static_cast<double>(max_labels))));
  for (int guard = 0; guard < 8; ++guard) {
    for (double m : {1.0, 2.0, 5.0}) {
      const double candidate = m * step;
      const double first = std::ceil(range.min / candidate - 1e-9);
      const double last = std::floor(range.max / candidate + 1e-9);
      if (last - first + 1 <= static_cast<double>(max_labels)) {
        for (double k = first; k <= last; k += 1.0)
          ticks.push_back(k * candidate == 0.0 ? 0.0 : k * candidate);  // no "-0"
        return ticks;
      }
    }
    step *= 10.0;
  }
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
