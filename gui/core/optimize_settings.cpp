#include "core/optimize_settings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/evaluation/force_metrics.h"

namespace saltus::gui {

namespace {
std::string number(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

/// One time per line, so the table's columns stay narrow.
std::string times_text(const std::vector<double>& times) {
  std::string out;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (i) out += "\n";
    out += number("%.3f", times[i]);
  }
  return out;
}
}  // namespace

OptimizeOptions to_optimize_options(const OptimizeSettings& s) {
  if (!(s.epsilon > 0) || !std::isfinite(s.epsilon))
    throw std::invalid_argument("epsilon must be positive");
  if (s.knots_per_interval < 0 || s.knots_per_interval > kMaxKnotsPerInterval)
    throw std::invalid_argument("knots per interval must be auto or 1-50");
  if (s.max_iterations < 0 || s.max_iterations > kMaxIterations)
    throw std::invalid_argument("max iterations must be in 0-100000");
  if (s.samples < kMinSamples || s.samples > kMaxSamples)
    throw std::invalid_argument("samples must be in 2-100000");
  if (!(s.max_joint_turn_deg >= 0 && s.max_joint_turn_deg <= 360))
    throw std::invalid_argument("max joint turn must be in 0-360°");
  OptimizeOptions o;
  o.nlp.formulation = s.strict ? Formulation::kStrict : Formulation::kRelaxed;
  o.nlp.epsilon = s.epsilon;
  o.nlp.optimize_timing = s.optimize_timing;
  o.automatic_resolution = s.knots_per_interval == 0;
  o.nlp.knots_per_interval = std::max(1, s.knots_per_interval);
  o.nlp.samples = s.samples;
  o.nlp.joint_turn_limit = s.max_joint_turn_deg / kDegreesPerRadian;
  o.solver.max_iterations = s.max_iterations;
  // The CLI's default tolerance (src/cli/main.cpp); the stalled-objective exit keeps the
  // library's default, as the CLI does.
  o.solver.tolerance = kCliTolerance;
  return o;
}

std::vector<ResultRow> result_table(const OptimizationResult& r, const OptimizeOptions& options) {
  const ForceMetrics& b = r.before.metrics;
  const ForceMetrics& a = r.after.metrics;
  std::vector<ResultRow> rows;
  const bool strict = options.nlp.formulation == Formulation::kStrict;
  rows.push_back({"status", "", r.solve.status});
  rows.push_back(
      {"model", "", strict ? "strict, ε = " + number("%g", options.nlp.epsilon) : "relaxed"});
  rows.push_back({"keyframes", std::to_string(r.before.keyframe_times.size()),
                  std::to_string(r.after.keyframe_times.size())});
  // K before is the one asked for; after, the one used (optimize_motion refines the knots when
  // the interpolation cannot pass through the keyframes).
  rows.push_back(
      {"knots per keyframe interval K",
       options.automatic_resolution ? "auto" : std::to_string(options.nlp.knots_per_interval),
       std::to_string(r.knots_per_interval)});
  rows.push_back({"variables", "", std::to_string(r.variables)});
  rows.push_back({"constraints", "", std::to_string(r.constraints)});
  rows.push_back({"objective J (N²)", number("%.4g", b.objective), number("%.4g", a.objective)});
  rows.push_back({"average root force √(J/6) (N)", number("%.4g", b.avg_root_force),
                  number("%.4g", a.avg_root_force)});
  rows.push_back(
      {"RMS root force (N)", number("%.4g", b.rms_force_N), number("%.4g", a.rms_force_N)});
  rows.push_back(
      {"RMS root moment (N·m)", number("%.4g", b.rms_moment_Nm), number("%.4g", a.rms_moment_Nm)});
  rows.push_back(
      {"max root force (N)", number("%.4g", b.max_force_N), number("%.4g", a.max_force_N)});
  rows.push_back(
      {"max root moment (N·m)", number("%.4g", b.max_moment_Nm), number("%.4g", a.max_moment_Nm)});
  rows.push_back({"iterations", "", std::to_string(r.solve.iterations)});
  if (r.solve.restarts > 0)
    rows.push_back(
        {"restarts from the best feasible iterate", "", std::to_string(r.solve.restarts)});
  rows.push_back({"seconds", "", number("%.2f", r.solve.seconds)});
  rows.push_back({"keyframe times (s)", times_text(r.before.keyframe_times),
                  times_text(r.after.keyframe_times)});
  rows.push_back({"max keyframe translation error (m)",
                  number("%.3g", r.before.keyframe_errors.max_translation_error_m),
                  number("%.3g", r.after.keyframe_errors.max_translation_error_m)});
  // Light limbs spin between keyframes when nothing holds them (MotionNlpOptions::
  // joint_turn_limit): the largest turn of a joint between two control points shows it.
  rows.push_back({"largest joint turn between control points (°)",
                  number("%.0f", largest_control_turn(r.before.trajectory, 1) * kDegreesPerRadian),
                  number("%.0f", largest_control_turn(r.after.trajectory, 1) * kDegreesPerRadian)});
  rows.push_back({"max keyframe rotation error (°)",
                  number("%.3g", r.before.keyframe_errors.max_rotation_error_deg),
                  number("%.3g", r.after.keyframe_errors.max_rotation_error_deg)});
  return rows;
}

std::string progress_text(const ProgressInfo& p) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "iteration %d   objective %.4e   violation %.1e   %.1f s",
                p.iteration, p.objective, p.constraint_violation, p.elapsed_seconds);
  return buffer;
}

}  // namespace saltus::gui
