#include "core/twist_report.h"

#include <cmath>
#include <optional>

#include "saltus/base/text_format.h"
#include "saltus/body/segment_names.h"

namespace saltus::gui {

namespace {

/// A number printed with `pattern`, without a sign on what rounds to 0 and with a real minus.
std::string signed_text(const char* pattern, double value, double rounding) {
  const double rounded = std::round(value / rounding) * rounding;
  const std::string text = format_number(pattern, rounded == 0.0 ? 0.0 : std::abs(rounded));
  return rounded < 0.0 ? "\u2212" + text : text;
}

/// Each source's curve colour: the arms as the 3D view draws the sides (left blue, right
/// orange), the take-off grey.
Rgb source_colour(const std::string& source) {
  if (source == "left arm") return {0.16, 0.42, 0.80};
  if (source == "right arm") return {0.93, 0.50, 0.08};
  if (source == "legs") return {0.20, 0.62, 0.25};
  if (source == "trunk") return {0.60, 0.30, 0.70};
  return {0.10, 0.10, 0.10};
}

}  // namespace

std::string tilt_text(double degrees) {
  return signed_text("%.1f°", degrees, 0.1);
}

std::string percent_text(double percent) {
  return signed_text("%.0f %%", percent, 1.0);
}

ChartSpec twist_chart(const TwistSources& s) {
  ChartSpec chart;
  chart.title = "Tilt over the flight";
  chart.x_title = "time (s)";
  chart.y_title = "tilt θ (°)";
  // The counterfactual tilts can end in any corner (the aerial full twist's "right arm made
  // symmetric" rose under the legend's box at 1.9 s).
  chart.legend_beside = true;
  std::optional<LineSpec> takeoff_only;
  for (std::size_t k = 0; k < s.tilt_deg.size() && k < s.flight_names.size(); ++k) {
    LineSpec line;
    line.x = s.times;
    line.y = s.tilt_deg[k];
    if (k == 0) {
      line.label = "actual flight";
      line.colour = {0.72, 0.72, 0.72};
      line.width = 7.0;
    } else if (k == 1) {
      line.label = "take-off only";
      line.colour = source_colour("take-off");
      line.dashed = true;
      line.width = 2.5;
      // Drawn last, over the others: where it follows the band, the take-off did it all.
      takeoff_only = std::move(line);
      continue;
    } else if (k < s.shares.size() + 1 &&
               s.flight_names[k] == "without " + s.shares[k - 1].source) {
      // The library flies the movements in the order of their shares (twist_sources.h).
      const std::string& source = s.shares[k - 1].source;
      line.label = source + " made symmetric";
      line.colour = source_colour(source);
    } else {
      line.label = s.flight_names[k];
      line.colour = source_colour("");
    }
    chart.lines.push_back(std::move(line));
  }
  if (takeoff_only) chart.lines.push_back(std::move(*takeoff_only));
  MarkerSpec mid;
  mid.x = s.reference_time_s;
  mid.colour = {0.85, 0.05, 0.05};  // solid: a dotted 1-pixel line vanished among the curves
  mid.label = "mid-flight";
  chart.markers.push_back(mid);
  return chart;
}

TwistReport twist_report(const TwistSources& s) {
  TwistReport r;
  r.sentence = s.sentence;
  r.tilted = has_tilt_to_share(s.total_tilt_deg);
  // Yeadon's twists are > 0 to the left (yeadon_angles.h).
  const std::string side = std::abs(s.twists) < 0.005 ? ""
                           : s.twists > 0             ? " to the left"
                                                      : " to the right";
  const std::string theta =
      r.tilted ? "; θ = " + tilt_text(s.total_tilt_deg) + " in the chart" : "";
  r.summary = "Tilt " + tilt_text(std::abs(s.total_tilt_deg)) +
              format_number(" at mid-flight (t = %.2f s", s.reference_time_s) + theta + "); " +
              format_number("%.2f twists", std::abs(s.twists)) + side + ".";
  r.chart = twist_chart(s);
  if (!r.tilted) return r;
  // Counted in the direction of the total: "the take-off gave 23°", not "−23°".
  const double sign = s.total_tilt_deg < 0 ? -1.0 : 1.0;
  for (const TwistShare& share : s.shares) {
    TwistRow row;
    row.label = capitalised(share.source);
    row.tilt_deg = sign * share.tilt_deg;
    row.percent = share.percent;
    r.rows.push_back(row);
  }
  TwistRow total;
  total.kind = TwistRow::Kind::kTotal;
  total.label = "Total";
  total.tilt_deg = std::abs(s.total_tilt_deg);
  total.percent = 100.0;
  r.rows.push_back(total);
  for (TwistRow& row : r.rows) {
    row.tilt_text = tilt_text(row.tilt_deg);
    row.percent_text = percent_text(row.percent);
  }
  return r;
}

}  // namespace saltus::gui
