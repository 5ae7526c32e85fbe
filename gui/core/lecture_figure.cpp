#include "core/lecture_figure.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>

namespace saltus::gui {

namespace {

std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* pattern, ...) {
  std::array<char, 512> buffer{};
  va_list args;
  va_start(args, pattern);
  std::vsnprintf(buffer.data(), buffer.size(), pattern, args);
  va_end(args);
  return buffer.data();
}

/// The stage in the words of the 3D view's title.
std::string stage_words(const Document& document, Stage stage) {
  if (stage == Stage::kAfter) return "optimised motion (after optimisation)";
  return document.file().motion.spline ? "optimised trajectory, as saved"
                                       : "interpolated keyframes (before optimisation)";
}

}  // namespace

LectureFigure lecture_figure(const Document& document, Stage stage, int pose_count) {
  const Stage shown = document.available(stage);
  const BodyModel& model = document.file().model;
  return lecture_figure_of(stroboscope(model, document.evaluation(shown).trajectory, pose_count),
                           model, document.file().motion.name, stage_words(document, shown));
}

LectureFigure lecture_figure_of(Stroboscope strobe, const BodyModel& model, const std::string& name,
                                const std::string& stage_words) {
  if (strobe.poses.empty()) throw std::invalid_argument("a lecture figure needs poses");
  LectureFigure f;
  f.model = model;
  double slowest = strobe.poses.front().spin_rev_per_s;
  double fastest = slowest;
  for (const StroboscopePose& p : strobe.poses) {
    slowest = std::min(slowest, p.spin_rev_per_s);
    fastest = std::max(fastest, p.spin_rev_per_s);
  }
  // A round step (0.1, 0.2, 0.5, 1 or 2 rev/s) giving at most 6 parts, the range whole steps
  // around the poses' rates, at least 0.2 rev/s wide and never below 0.
  for (const double step : {0.1, 0.2, 0.5, 1.0, 2.0}) {
    f.spin_step = step;
    if ((fastest - slowest) / step <= 5.0) break;
  }
  f.spin_low = std::max(0.0, std::floor(slowest / f.spin_step) * f.spin_step);
  f.spin_high = std::max(std::ceil(fastest / f.spin_step) * f.spin_step, f.spin_low + 0.2);
  f.title = name + " — " + stage_words;
  f.colour_bar_title = "Whole-body\nspin rate |ω|\n(rev/s)";

  const std::size_t n = strobe.poses.size();
  const double landing = strobe.poses.back().time;
  f.caption = format(
      "%zu poses %.3f s apart, from take-off (t = 0, left) to landing (t = %.2f s, "
      "right); the grey line is the centre of mass's path.",
      n, n > 1 ? landing / static_cast<double>(n - 1) : 0.0, landing);
  f.caption += strobe.along_velocity
                   ? "\nSeen from the side, along the somersault axis (across the take-off "
                     "horizontal velocity)."
                   : "\nSeen from the athlete's right (the take-off has no horizontal velocity "
                     "to speak of).";
  if (strobe.spread_m > 0.0)
    f.caption += format(
        "\nNot to scale horizontally: poses spread %.2f m further apart each so "
        "that they do not overlap; the flight itself travels %.2f m.",
        strobe.spread_m, strobe.travel_m);
  else
    f.caption += format("\nTo scale: the flight travels %.2f m.", strobe.travel_m);
  f.caption += format(
      "\nColour: the whole-body spin rate |ω| = |I⁻¹·L| at each pose's time, "
      "%.2f to %.2f rev/s.",
      slowest, fastest);
  f.strobe = std::move(strobe);
  return f;
}

Rgb spin_colour(double fraction) {
  static constexpr std::array<Rgb, 4> kStops{
      {{0.13, 0.23, 0.62}, {0.05, 0.58, 0.58}, {0.96, 0.62, 0.07}, {0.78, 0.08, 0.10}}};
  const double u = std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0) *
                   static_cast<double>(kStops.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(u), kStops.size() - 2);
  const double w = u - static_cast<double>(i);
  const Rgb& a = kStops[i];
  const Rgb& b = kStops[i + 1];
  return {a.r + w * (b.r - a.r), a.g + w * (b.g - a.g), a.b + w * (b.b - a.b)};
}

}  // namespace saltus::gui
