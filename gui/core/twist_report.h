#pragma once
/// @file
/// What the Twist panel shows of the library's `twist_sources`: the rows of its table (each
/// source's tilt and share, then the total, which the shares add up to) and the chart of tilt over
/// time of the actual flight and of each counterfactual. Which motion it analyses is the one the 3D
/// view shows (core/shown_motion.h). The numbers are the library's; this file only labels and
/// formats them.

#include <string>
#include <vector>

#include "core/chart_spec.h"
#include "saltus/evaluation/twist_sources.h"

namespace saltus::gui {

/// One row of the table.
struct TwistRow {
  enum class Kind { kSource, kTotal };
  Kind kind = Kind::kSource;
  std::string label;  ///< "Right arm", "Total"
  /// The library's tilt counted in the direction of the total tilt (its sign, Yeadon's θ,
  /// says which side the body leans; here a share < 0 works against the total, as its percent).
  double tilt_deg = 0.0;
  double percent = 0.0;      ///< of the total tilt, the library's
  std::string tilt_text;     ///< "17.2°"
  std::string percent_text;  ///< "70 %"
};

struct TwistReport {
  std::string sentence;  ///< the library's, as it wrote it
  /// False when the flight is not tilted enough to share out (has_tilt_to_share): the panel
  /// shows the sentence alone, no table of zeros and no percentages of nearly nothing.
  bool tilted = false;
  /// Sources in the library's order, then the total; empty if !tilted.
  std::vector<TwistRow> rows;
  /// "Tilt 23.1° at mid-flight (t = 1.02 s; θ = −23.1° in the chart); 1.50 twists to the left."
  std::string summary;
  ChartSpec chart;
};

TwistReport twist_report(const TwistSources& sources);

/// The chart alone: tilt θ (°) against time (s) of every flight the library flew, labelled for
/// a coach ("actual flight", "take-off only", "left arm made symmetric", ...), the reference
/// time as a marker. The actual flight is a wide pale band under the others: a movement that
/// changes nothing draws its curve inside the band instead of hiding it.
ChartSpec twist_chart(const TwistSources& sources);

/// "17.2°", "−3.0°" (no "−0.0°").
std::string tilt_text(double degrees);
/// "70 %", "−12 %" (no "−0 %").
std::string percent_text(double percent);

}  // namespace saltus::gui
