#pragma once
/// @file
/// What a chart shows, independent of how it is drawn: lines with labels, colours and styles,
/// axis titles with units and vertical markers (keyframe times, the time cursor). The core
/// decides what to plot (tested without a window); gui/scene draws a ChartSpec with VTK, both in
/// the app and for the exported figures.

#include <string>
#include <vector>

namespace saltus::gui {

struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;  ///< each in [0, 1]
};

enum class LineKind { kLine, kPoints, kBars };

struct LineSpec {
  std::string label;  ///< legend entry
  std::vector<double> x;
  std::vector<double> y;
  Rgb colour;
  bool dashed = false;
  double width = 2.0;       ///< pixels
  bool right_axis = false;  ///< plotted against the right-hand y axis (y2_title)
  LineKind kind = LineKind::kLine;
};

/// A vertical line across the plot at x (keyframe times).
struct MarkerSpec {
  double x = 0.0;
  Rgb colour;
  bool dashed = false;
  /// Legend entry ("keyframes (given)"); empty: none. One marker of a kind carries it.
  std::string label;
};

struct ChartSpec {
  std::string title;
  std::string x_title;   ///< with unit, e.g. "time (s)"
  std::string y_title;   ///< with unit, e.g. "root force (N)"
  std::string y2_title;  ///< right axis; empty when no line uses it and y2_per_y is 0
  /// Left y axis logarithmic (values <= 0 are not drawn there).
  bool log_y = false;
  /// > 0: the right axis is the left one in other units (right = left × y2_per_y, e.g. % of
  /// body weight) and no line uses it.
  double y2_per_y = 0.0;
  std::vector<LineSpec> lines;
  std::vector<MarkerSpec> markers;
  /// Labels for integer x positions 0, 1, ... (bar charts); empty: numeric axis.
  std::vector<std::string> x_labels;
  bool legend = true;
  /// The legend in a column right of the plot instead of in its top right corner: for curves
  /// that may reach any corner (the twist figure's tilts), so that no entry hides one.
  bool legend_beside = false;
};

/// Smallest and largest y over the lines on one axis (left: right_axis false), padded by 5 % of
/// the span (and at least ±1 when flat); {0, 1} when there is no data. Bar charts include 0.
struct AxisRange {
  double min = 0.0, max = 1.0;
};
AxisRange y_range(const ChartSpec& chart, bool right_axis);
/// The left axis for a logarithmic scale: from the lowest of the lines' floors (each line's 10th
/// percentile of its positive values: its bulk shows, its dips towards zero are cut) to the
/// largest value, at most six decades wide and at least one, padded 5 % in log space; {1, 10}
/// when nothing is positive. The floor follows the data: a small "after" curve keeps its shape
/// beside a large "before" or a capture's.
AxisRange log_y_range(const ChartSpec& chart);
/// Where a logarithmic axis over `range` (both ends > 0) puts its labelled ticks: the powers of
/// ten inside it (every other one beyond six, the largest kept), and also 2× and 5× each power
/// when fewer than three powers fall inside (a short range). At most about six labels, so that
/// they do not overlap on a plot 120 pixels high (1-2-5 steps over four decades gave twelve).
std::vector<double> log_ticks(const AxisRange& range);
/// Where a linear axis over `range` puts its labelled ticks: multiples of the smallest 1-2-5
/// step (…, 0.1, 0.2, 0.5, 1, 2, 5, 10, …) that puts at most `max_labels` of them inside it, so
/// that every axis has at least two labels (a short plot's axis with one label could not be
/// read) and none overlap. `max_labels` at least 5, which guarantees the two (fewer: empty).
std::vector<double> linear_ticks(const AxisRange& range, std::size_t max_labels = 5);
/// A tick's label: "0.01", "0.5", "20", "1000", "1e+05".
std::string tick_label(double value);

/// Smallest and largest x over all lines and markers (unpadded); {0, 1} when empty.
AxisRange x_range(const ChartSpec& chart);

}  // namespace saltus::gui
