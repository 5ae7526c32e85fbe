#include "core/plot_series.h"

#include <cmath>
#include <stdexcept>

namespace saltus::gui {

namespace {

/// The paler "before" version of a colour: 45 % towards white.
Rgb paler(const Rgb& c) {
  const double k = 0.45;
  return {c.r + k * (1 - c.r), c.g + k * (1 - c.g), c.b + k * (1 - c.b)};
}

/// Before/after styling only when both are drawn: alone, a motion's lines are plain and solid.
void style_stage(LineSpec& line, bool after, bool comparing) {
  if (!comparing) {
    line.width = 2.2;
    return;
  }
  line.dashed = !after;
  line.width = after ? 2.5 : 1.8;
  if (!after) line.colour = paler(line.colour);
}

std::string stage_suffix(int stage, bool comparing) {
  if (!comparing) return "";
  return stage == 0 ? ", before" : ", after";
}

void add_keyframe_markers(ChartSpec& chart, const std::vector<double>& before,
                          const std::vector<double>& after) {
  for (double t : before)
    chart.markers.push_back({t, given_keyframe_colour(), true});
  for (double t : after)
    chart.markers.push_back({t, optimised_keyframe_colour(), false});
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

WrenchSeries root_wrench_series(const std::vector<SampleRecord>& samples) {
  WrenchSeries out;
  out.time.reserve(samples.size());
  for (auto& c : out.component)
    c.reserve(samples.size());
  for (const SampleRecord& s : samples) {
    out.time.push_back(s.time);
    for (int i = 0; i < 6; ++i)
      out.component[i].push_back(s.root_wrench[i]);
  }
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

Rgb given_keyframe_colour() {
  return {0.45, 0.45, 0.45};
}
Rgb optimised_keyframe_colour() {
  return {0.95, 0.55, 0.05};
}

ChartSpec root_wrench_chart_frame(bool moment) {
  ChartSpec chart;
  chart.title = moment ? "Root moment F4-F6 (root frame)" : "Root force F1-F3 (root frame)";
  chart.x_title = "time (s)";
  chart.y_title = moment ? "root moment (N·m)" : "root force (N)";
  return chart;
}

ChartSpec root_wrench_chart(bool moment, const WrenchSeries& before, const WrenchSeries* after,
                            const ComponentMask& shown, const std::vector<double>& keyframes_before,
                            const std::vector<double>& keyframes_after) {
  ChartSpec chart = root_wrench_chart_frame(moment);
  const int first = moment ? 3 : 0;
  for (int stage = 0; stage < 2; ++stage) {
    const WrenchSeries* series = stage == 0 ? &before : after;
    if (!series) continue;
    for (int i = first; i < first + 3; ++i) {
      if (!shown[i]) continue;
      LineSpec line;
      line.label = wrench_component_name(i) + stage_suffix(stage, after != nullptr);
      line.x = series->time;
      line.y = series->component[i];
      line.colour = component_colour(i);
      style_stage(line, stage == 1, after != nullptr);
      chart.lines.push_back(std::move(line));
    }
  }
  add_keyframe_markers(chart, keyframes_before, after ? keyframes_after : std::vector<double>{});
  return chart;
}

ChartSpec joint_load_chart(const BodyModel& model, int segment,
                           const std::vector<SampleRecord>& before,
                           const std::vector<SampleRecord>* after) {
  if (segment < 0 || segment >= model.size()) throw std::out_of_range("joint load segment");
  const Segment& s = model.segments[segment];
  ChartSpec chart;
  chart.title = "Loads at joint " + s.joint + " (on " + s.name + ")";
  chart.x_title = "time (s)";
  chart.y_title = "force |F| (N)";
  chart.y2_title = "moment |M| (N·m)";
  const Rgb force_colour{0.75, 0.20, 0.45};
  const Rgb moment_colour{0.10, 0.55, 0.60};
  for (int stage = 0; stage < 2; ++stage) {
    const std::vector<SampleRecord>* samples = stage == 0 ? &before : after;
    if (!samples) continue;
    LineSpec force, torque;
    const std::string suffix = stage_suffix(stage, after != nullptr);
    force.label = "|F| force" + suffix;
    torque.label = "|M| moment" + suffix;
    force.colour = force_colour;
    torque.colour = moment_colour;
    torque.right_axis = true;
    for (const SampleRecord& r : *samples) {
      force.x.push_back(r.time);
      torque.x.push_back(r.time);
      force.y.push_back(r.joint_wrench.at(segment).head<3>().norm());
      torque.y.push_back(r.joint_wrench.at(segment).tail<3>().norm());
    }
    style_stage(force, stage == 1, after != nullptr);
    style_stage(torque, stage == 1, after != nullptr);
    chart.lines.push_back(std::move(force));
    chart.lines.push_back(std::move(torque));
  }
  return chart;
}

std::vector<std::string> rotation_quantity_names() {
  return {"Moment of inertia and somersault rate", "Angular momentum about the CoM",
          "Somersault and twist rates", "Somersaults and twists counted"};
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
          {"inertia about x, I_xx",
           {0.50, 0.25, 0.70},
           false,
           [](const RotationSample& s) { return s.somersault_inertia; }},
          {"somersault rate |ω_x|",
           {0.05, 0.55, 0.55},
           true,
           [](const RotationSample& s) { return std::abs(s.somersault_rate); }},
      };
      break;
    case RotationQuantity::kAngularMomentum:
      chart.title = "Angular momentum about the CoM (constant in valid flight)";
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
          {"twist (long axis)",
           {0.85, 0.45, 0.10},
           false,
           [](const RotationSample& s) { return s.twist_rate; }},
      };
      break;
    case RotationQuantity::kCounts:
      chart.title = "Somersaults and twists so far (negative: backward / to the right)";
      chart.y_title = "revolutions";
      quantities = {
          {"somersaults",
           {0.05, 0.55, 0.55},
           false,
           [](const RotationSample& s) { return s.somersaults; }},
          {"twists", {0.85, 0.45, 0.10}, false, [](const RotationSample& s) { return s.twists; }},
      };
      break;
  }
  for (int stage = 0; stage < 2; ++stage) {
    const std::vector<RotationSample>* samples = stage == 0 ? &before : after;
    if (!samples) continue;
    for (const Quantity& q : quantities) {
      LineSpec line;
      line.label = q.label + stage_suffix(stage, after != nullptr);
      line.x = times_of(*samples);
      line.y = values_of(*samples, q.get);
      line.colour = q.colour;
      line.right_axis = q.right_axis;
      style_stage(line, stage == 1, after != nullptr);
      chart.lines.push_back(std::move(line));
    }
  }
  return chart;
}

}  // namespace saltus::gui
