#include "core/plot_series.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "saltus/body/segment_names.h"
#include "saltus/evaluation/force_metrics.h"
#include "saltus/evaluation/residual_measures.h"

namespace saltus::gui {

namespace {

const char* const kAxisNames[3] = {"x", "y", "z"};

/// The paler "before" version of a colour: 45 % towards white.
Rgb paler(const Rgb& c) {
  const double k = 0.45;
  return {c.r + k * (1 - c.r), c.g + k * (1 - c.g), c.b + k * (1 - c.b)};
}

std::string stage_suffix(int stage, bool comparing) {
  if (!comparing) return "";
  return stage == 0 ? " before" : " after";
}

std::vector<double> times_of(const std::vector<RotationSample>& samples) {
  std::vector<double> out;
  out.reserve(samples.size());
  for (const RotationSample& s : samples)
    out.push_back(s.time);
  return out;
}

template <typename Get>
std::vector<double> values_of(const std::vector<RotationSample>& samples, Get get) {
  std::vector<double> out;
  out.reserve(samples.size());
  for (const RotationSample& s : samples)
    out.push_back(get(s));
  return out;
}

}  // namespace

int plot_samples_for(double duration) {
  const int check = static_cast<int>(std::ceil(duration / kCheckMaxSpacing)) + 1;
  return std::max(kPlotSamples, check);
}

WrenchSeries root_wrench_series(const std::vector<SampleRecord>& samples) {
  WrenchSeries out;
  out.time.reserve(samples.size());
  for (auto& c : out.component)
    c.reserve(samples.size());
  for (const SampleRecord& s : samples) {
    out.time.push_back(s.time);
    for (int i = 0; i < 6; ++i)
      out.component[static_cast<std::size_t>(i)].push_back(s.root_wrench[i]);
  }
  out.force_magnitude = root_force_magnitudes(samples);
  out.moment_magnitude = root_moment_magnitudes(samples);
  return out;
}

std::string wrench_component_name(int component) {
  static const char* const kNames[6] = {"F1 force x",  "F2 force y",  "F3 force z",
                                        "F4 moment x", "F5 moment y", "F6 moment z"};
  if (component < 0 || component >= 6) throw std::out_of_range("wrench component");
  return kNames[component];
}

Rgb component_colour(int component) {
  switch (component % 3) {
    case 0:
      return {0.84, 0.15, 0.16};
    case 1:
      return {0.17, 0.60, 0.17};
    default:
      return {0.12, 0.40, 0.80};
  }
}

Rgb magnitude_curve_colour(bool moment) {
  return moment ? Rgb{0.10, 0.50, 0.62} : Rgb{0.72, 0.18, 0.42};
}

Rgb given_keyframe_colour() {
  return {0.45, 0.45, 0.45};
}
Rgb optimised_keyframe_colour() {
  return {0.95, 0.55, 0.05};
}

void style_compared_line(LineSpec& line, bool second, bool comparing) {
  if (!comparing) {
    line.width = 2.2;
    return;
  }
  line.dashed = !second;
  line.width = second ? 2.6 : 1.8;
  if (!second) line.colour = paler(line.colour);
}

void add_keyframe_markers(ChartSpec& chart, const std::vector<double>& given,
                          const std::vector<double>& optimised) {
  for (std::size_t i = 0; i < given.size(); ++i)
    chart.markers.push_back(
        {given[i], given_keyframe_colour(), true, i == 0 ? "keyframes (given)" : ""});
  for (std::size_t i = 0; i < optimised.size(); ++i)
    chart.markers.push_back(
        {optimised[i], optimised_keyframe_colour(), false, i == 0 ? "keyframes (optimised)" : ""});
}

ChartSpec root_chart_frame(const RootChartStyle& style) {
  ChartSpec chart;
  chart.x_title = "time (s)";
  if (style.components) {
    chart.title = style.moment ? "Root moment F4-F6 (root frame)" : "Root force F1-F3 (root frame)";
    chart.y_title = style.moment ? "root moment (N·m)" : "root force (N)";
  } else {
    chart.title = style.moment ? "Root moment |M| (zero in a valid flight)"
                               : "Root force |F| (zero in a valid flight)";
    chart.y_title = style.moment ? "|M| (N·m)" : "|F| (N)";
    chart.log_y = style.log_scale;
  }
  if (!style.moment && style.body_weight_N > 0) {
    chart.y2_title = "% of body weight";
    chart.y2_per_y = 100.0 / style.body_weight_N;
  }
  return chart;
}

Rgb capture_curve_colour() {
  return {0.36, 0.50, 0.36};
}

ChartSpec root_chart(const RootChartStyle& style, const WrenchSeries& before,
                     const WrenchSeries* after, const std::vector<double>& keyframes_before,
                     const std::vector<double>& keyframes_after, const WrenchSeries* capture) {
  ChartSpec chart = root_chart_frame(style);
  const bool comparing = after != nullptr;
  // The log axis is there to show "after" beside a far larger "before" (or the capture's);
  // a lone curve reads better on a linear one (its dips to zero would fill the log axis with
  // spikes).
  chart.log_y = chart.log_y && (comparing || capture);
  const int first = style.moment ? 3 : 0;
  if (capture) {
    // First, so that the motion's own curves are drawn over it.
    const int axes = style.components ? 3 : 1;
    for (int a = 0; a < axes; ++a) {
      if (style.components && !style.axes[static_cast<std::size_t>(a)]) continue;
      LineSpec line;
      line.x = capture->time;
      if (style.components) {
        line.label = std::string(kAxisNames[a]) + " capture";
        line.y = capture->component[static_cast<std::size_t>(first + a)];
        line.colour = component_colour(a);
        line.colour = {0.5 * (line.colour.r + capture_curve_colour().r),
                       0.5 * (line.colour.g + capture_curve_colour().g),
                       0.5 * (line.colour.b + capture_curve_colour().b)};
      } else {
        line.label = std::string(style.moment ? "|M|" : "|F|") + " capture";
        line.y = style.moment ? capture->moment_magnitude : capture->force_magnitude;
        line.colour = capture_curve_colour();
      }
      line.width = 1.4;
      chart.lines.push_back(std::move(line));
    }
  }
  const std::size_t first_motion_line = chart.lines.size();
  for (int stage = 0; stage < 2; ++stage) {
    const WrenchSeries* series = stage == 0 ? &before : after;
    if (!series) continue;
    if (style.components) {
      for (int a = 0; a < 3; ++a) {
        if (!style.axes[static_cast<std::size_t>(a)]) continue;
        LineSpec line;
        line.label = std::string(kAxisNames[a]) + stage_suffix(stage, comparing);
        line.x = series->time;
        line.y = series->component[static_cast<std::size_t>(first + a)];
        line.colour = component_colour(a);
        style_compared_line(line, stage == 1, comparing);
        chart.lines.push_back(std::move(line));
      }
    } else {
      LineSpec line;
      line.label = (style.moment ? "|M|" : "|F|") + stage_suffix(stage, comparing);
      line.x = series->time;
      line.y = style.moment ? series->moment_magnitude : series->force_magnitude;
      line.colour = magnitude_curve_colour(style.moment);
      style_compared_line(line, stage == 1, comparing);
      chart.lines.push_back(std::move(line));
    }
  }
  // Beside the capture, a lone curve is the keyframes' interpolation.
  if (capture && !comparing)
    for (std::size_t i = first_motion_line; i < chart.lines.size(); ++i)
      chart.lines[i].label += " keyframes";
  add_keyframe_markers(chart, keyframes_before,
                       comparing ? keyframes_after : std::vector<double>{});
  return chart;
}

ChartSpec root_wrench_chart(bool moment, const WrenchSeries& before, const WrenchSeries* after,
                            const ComponentMask& shown, const std::vector<double>& keyframes_before,
                            const std::vector<double>& keyframes_after) {
  RootChartStyle style;
  style.moment = moment;
  style.components = true;
  const int first = moment ? 3 : 0;
  for (int a = 0; a < 3; ++a)
    style.axes[static_cast<std::size_t>(a)] = shown[static_cast<std::size_t>(first + a)];
  return root_chart(style, before, after, keyframes_before, keyframes_after);
}

std::vector<std::string> rotation_quantity_names() {
  return {"Moment of inertia and somersault rate", "Angular momentum about the CoM",
          "Somersault and twist rates", "Somersaults and twists counted",
          "Somersault, tilt and twist (Yeadon)"};
}

ChartSpec rotation_chart(RotationQuantity quantity, const std::vector<RotationSample>& before,
                         const std::vector<RotationSample>* after) {
  ChartSpec chart;
  chart.x_title = "time (s)";
  struct Quantity {
    std::string label;
    Rgb colour;
    bool right_axis;
    double (*get)(const RotationSample&);
  };
  std::vector<Quantity> quantities;
  switch (quantity) {
    case RotationQuantity::kInertiaAndRate:
      // The rate as a size, so that the inverse relation shows: inertia down, spin up.
      chart.title = "Tuck to spin faster: smaller inertia I, faster spin |ω| (L = I·ω constant)";
      chart.y_title = "inertia I_xx (kg·m²)";
      chart.y2_title = "spin |ω_x| (rad/s)";
      quantities = {
          {"I_xx",
           {0.50, 0.25, 0.70},
           false,
           [](const RotationSample& s) { return s.somersault_inertia; }},
          {"|ω_x|",
           {0.05, 0.55, 0.55},
           true,
           [](const RotationSample& s) { return std::abs(s.somersault_rate); }},
      };
      break;
    case RotationQuantity::kAngularMomentum:
      chart.title = "Angular momentum about the CoM (constant in a valid flight)";
      chart.y_title = "L (kg·m²/s)";
      quantities = {
          {"L_x", component_colour(0), false,
           [](const RotationSample& s) { return s.angular_momentum.x(); }},
          {"L_y", component_colour(1), false,
           [](const RotationSample& s) { return s.angular_momentum.y(); }},
          {"L_z", component_colour(2), false,
           [](const RotationSample& s) { return s.angular_momentum.z(); }},
      };
      break;
    case RotationQuantity::kRates:
      chart.title = "Whole-body angular velocity ω = I⁻¹·L";
      chart.y_title = "ω (rad/s)";
      quantities = {
          {"somersault ω_x",
           {0.05, 0.55, 0.55},
           false,
           [](const RotationSample& s) { return s.somersault_rate; }},
          {"spin about the long axis",
           {0.85, 0.45, 0.10},
           false,
           [](const RotationSample& s) { return s.twist_rate; }},
      };
      break;
    case RotationQuantity::kCounts:
      chart.title = "Somersaults and twists so far (Yeadon's angles of the trunk)";
      chart.y_title = "revolutions";
      quantities = {
          {"somersaults",
           {0.05, 0.55, 0.55},
           false,
           [](const RotationSample& s) { return s.somersaults; }},
          {"twists", {0.85, 0.45, 0.10}, false, [](const RotationSample& s) { return s.twists; }},
      };
      break;
    case RotationQuantity::kYeadonAngles:
      chart.title = "Somersault φ, tilt θ and twist ψ of the trunk (Yeadon's angles)";
      chart.y_title = "angle (°)";
      quantities = {
          {"somersault φ",
           {0.05, 0.55, 0.55},
           false,
           [](const RotationSample& s) { return s.somersault_deg; }},
          {"tilt θ", {0.55, 0.25, 0.75}, false, [](const RotationSample& s) { return s.tilt_deg; }},
          {"twist ψ",
           {0.85, 0.45, 0.10},
           false,
           [](const RotationSample& s) { return s.twist_deg; }},
      };
      break;
  }
  const bool comparing = after != nullptr;
  for (int stage = 0; stage < 2; ++stage) {
    const std::vector<RotationSample>* samples = stage == 0 ? &before : after;
    if (!samples) continue;
    for (const Quantity& q : quantities) {
      LineSpec line;
      line.label = q.label + stage_suffix(stage, comparing);
      line.x = times_of(*samples);
      line.y = values_of(*samples, q.get);
      line.colour = q.colour;
      line.right_axis = q.right_axis;
      style_compared_line(line, stage == 1, comparing);
      chart.lines.push_back(std::move(line));
    }
  }
  return chart;
}

}  // namespace saltus::gui
