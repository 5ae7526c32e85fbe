#include "core/what_if_report.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "saltus/base/text_format.h"

namespace saltus::gui {

namespace {

/// Steps of a range, kept inside it against rounding (0.05 / 0.01 is 5.000000000000001).
int steps_of(double seconds, bool up) {
  const double steps = seconds / kWhatIfShiftStepS;
  const double rounded = std::round(steps);
  if (std::abs(steps - rounded) < 1e-9) return static_cast<int>(rounded);
  return static_cast<int>(up ? std::ceil(steps) : std::floor(steps));
}

}  // namespace

SliderSteps shift_slider_steps(double min_s, double max_s) {
  SliderSteps out;
  out.min = std::min(0, steps_of(min_s, true));
  out.max = std::max(0, steps_of(max_s, false));
  return out;
}

SliderSteps tightness_slider_steps() {
  return {static_cast<int>(std::ceil(100.0 * kMinTuckScale - 1e-9)),
          static_cast<int>(std::floor(100.0 * kMaxTuckScale + 1e-9))};
}

WhatIfChange change_at(int tuck_steps, int open_steps, int tightness_percent) {
  WhatIfChange change;
  change.tuck_later_s = tuck_steps * kWhatIfShiftStepS;
  change.open_later_s = open_steps * kWhatIfShiftStepS;
  change.tuck_scale = tightness_percent / 100.0;
  return change;
}

std::string shift_text(double seconds) {
  if (seconds == 0.0) return "as keyframed";
  return format_number("%.2f s", std::abs(seconds)) + (seconds > 0 ? " later" : " earlier");
}

std::string tightness_text(int percent) {
  const std::string number = format_number("%.0f %%", percent);
  if (percent == 100) return number + " (as keyframed)";
  return number + (percent > 100 ? " (tighter)" : " (looser)");
}

std::string tuck_text(const TuckPhases& tuck) {
  if (!tuck.found) return tuck.reason;
  std::string out =
      format_number("Tucks %.2f", tuck.tuck_start_s) + format_number("\u2013%.2f s", tuck.tucked_s);
  if (tuck.opens)
    out += format_number(", opens %.2f", tuck.open_start_s) +
           format_number("\u2013%.2f s", tuck.opened_s);
  else
    out += ", lands in the tuck";
  return out + format_number("; hips and knees bend up to %.0f°.", tuck.peak_bend_deg);
}

std::string reference_text(const WhatIf& prepared) {
  const YeadonSummary& target = prepared.target();
  const YeadonSummary& flown = prepared.unchanged_landing();
  const bool twists = std::abs(target.twists) >= 0.05 || std::abs(flown.twists) >= 0.05;
  if (!twists)
    return format_number("Keyframed to land after %.2f somersaults; ",
                         std::abs(target.somersaults)) +
           format_number("flown as it is, %.2f.", std::abs(flown.somersaults));
  return format_number("Keyframed to land after %.2f somersaults", std::abs(target.somersaults)) +
         format_number(" and %.2f twists; ", std::abs(target.twists)) +
         format_number("flown as it is, %.2f", std::abs(flown.somersaults)) +
         format_number(" and %.2f.", std::abs(flown.twists));
}

SampleRecord flight_sample_at(const std::vector<SampleRecord>& samples, double t) {
  if (samples.empty()) throw std::invalid_argument("a flight without samples");
  if (t <= samples.front().time) return samples.front();
  if (t >= samples.back().time) return samples.back();
  const auto after =
      std::upper_bound(samples.begin(), samples.end(), t,
                       [](double time, const SampleRecord& s) { return time < s.time; });
  const SampleRecord& b = *after;
  const SampleRecord& a = *(after - 1);
  const double u = (t - a.time) / (b.time - a.time);
  SampleRecord out = a;
  out.time = t;
  out.com = a.com + u * (b.com - a.com);
  out.com_velocity = a.com_velocity + u * (b.com_velocity - a.com_velocity);
  out.angular_momentum = a.angular_momentum + u * (b.angular_momentum - a.angular_momentum);
  for (std::size_t k = 0; k < a.segment_position.size(); ++k) {
    out.segment_position[k] =
        a.segment_position[k] + u * (b.segment_position[k] - a.segment_position[k]);
    out.segment_rotation[k] = a.segment_rotation[k].slerp(u, b.segment_rotation[k]);
  }
  out.root_wrench = a.root_wrench + u * (b.root_wrench - a.root_wrench);
  out.residual = a.residual + u * (b.residual - a.residual);
  for (std::size_t k = 0; k < a.joint_wrench.size(); ++k)
    out.joint_wrench[k] = a.joint_wrench[k] + u * (b.joint_wrench[k] - a.joint_wrench[k]);
  return out;
}

double median_ms(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace saltus::gui
