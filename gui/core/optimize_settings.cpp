#include "core/optimize_settings.h"

#include <cctype>
#include <cstdio>

#include "saltus/base/constants.h"
#include "saltus/base/text_format.h"
#include "saltus/evaluation/force_metrics.h"

namespace saltus::gui {

namespace {
/// One time per line, so the table's columns stay narrow.
std::string times_text(const std::vector<double>& times) {
  std::string out;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (i) out += "\n";
    out += format_number("%.3f", times[i]);
  }
  return out;
}

/// The knot spans per keyframe interval used: K when every interval has K, else each one's.
std::string spans_text(const OptimizationResult& r) {
  bool uniform = true;
  for (int s : r.subdivisions)
    uniform = uniform && s == r.knots_per_interval;
  if (uniform) return std::to_string(r.knots_per_interval);
  std::string out;
  for (std::size_t i = 0; i < r.subdivisions.size(); ++i)
    out += (i ? ", " : "") + std::to_string(r.subdivisions[i]);
  return out;
}
}  // namespace

OptimizeOptions to_optimize_options(const OptimizeSettings& settings) {
  return settings.optimize_options();
}

std::string first_changed_option(const OptimizeSettings& before, const OptimizeSettings& after) {
  for (const OptionSpec& spec : option_table())
    if (before.get(spec.name) != after.get(spec.name)) return spec.label;
  return "";
}

namespace {

bool costly(const OptionSpec& spec, const OptionValue& value) {
  if (const int* i = std::get_if<int>(&value)) return *i > spec.costly_above;
  if (const double* d = std::get_if<double>(&value)) return *d > spec.costly_above;
  return false;  // a word ("auto") or a switch
}

}  // namespace

std::vector<std::string> newly_costly_settings(const OptimizeSettings& before,
                                               const OptimizeSettings& after) {
  std::vector<std::string> out;
  for (const OptionSpec& spec : option_table())
    if (costly(spec, after.get(spec.name)) && !costly(spec, before.get(spec.name)))
      out.push_back(spec.label + " = " + option_value_text(after.get(spec.name)) + ": " +
                    spec.cost);
  return out;
}

std::string option_tooltip(const OptionSpec& spec) {
  std::string out = option_description(spec);
  if (!out.empty()) out[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(out[0])));
  if (out.back() != '.') out += ".";
  return out + "\n" + spec.flag + " in saltus optimize and saltus-gui";
}

namespace {

constexpr const char* kSettingsPrefix = "optimize/";

/// Settings an earlier version stored under another key or in another form.
struct LegacySetting {
  const char* key;
  const char* option;
  std::optional<std::string> (*convert)(const std::string& text);
};
const LegacySetting kLegacySettings[] = {
    {"optimize/strict", "formulation",
     [](const std::string& t) -> std::optional<std::string> {
       if (t == "true") return std::string("strict");
       if (t == "false") return std::string("relaxed");
       return std::nullopt;
     }},
    {"optimize/timing", "optimize_timing",
     [](const std::string& t) -> std::optional<std::string> { return t; }},
    {"optimize/max_joint_turn_deg", "max_joint_turn",
     [](const std::string& t) -> std::optional<std::string> { return t; }},
    // A build of the app stored the automatic resolution as knots 0.
    {"optimize/knots", "knots_per_interval",
     [](const std::string& t) -> std::optional<std::string> {
       return t == "0" ? std::string("auto") : t;
     }},
};

/// The key an option is stored under: "optimize/<name>", except where an earlier version's
/// value under that name must not be read. "optimize/knots_per_interval" held the paper's 1 as
/// a default nobody chose before the automatic resolution (auto) became the default.
std::string settings_key(const OptionSpec& spec) {
  if (spec.name == "knots_per_interval") return std::string(kSettingsPrefix) + "knots";
  return kSettingsPrefix + spec.name;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> settings_entries(
    const OptimizeSettings& settings) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const OptionSpec& spec : option_table())
    out.emplace_back(settings_key(spec), option_value_text(settings.get(spec.name)));
  return out;
}

OptimizeSettings settings_from_entries(
    const std::function<std::optional<std::string>(const std::string& key)>& stored) {
  OptimizeSettings settings;
  auto take = [&settings](const std::string& name, const std::string& text) {
    try {
      settings.set_text(name, text);
    } catch (const OptionValueError&) {
      // Out of today's range or not a value: the default stays.
    }
  };
  for (const LegacySetting& legacy : kLegacySettings)
    if (const auto text = stored(legacy.key))
      if (const auto converted = legacy.convert(*text)) take(legacy.option, *converted);
  for (const OptionSpec& spec : option_table())
    if (const auto text = stored(settings_key(spec))) take(spec.name, *text);
  return settings;
}

std::vector<ResultRow> result_table(const OptimizationResult& r, const OptimizeOptions& options) {
  const ForceMetrics& b = r.before.metrics;
  const ForceMetrics& a = r.after.metrics;
  std::vector<ResultRow> rows;
  const bool strict = options.nlp.formulation == Formulation::kStrict;
  rows.push_back({"status", "", r.solve.status});
  rows.push_back({"model", "",
                  strict ? "strict, ε = " + format_number("%g", options.nlp.epsilon) : "relaxed"});
  rows.push_back({"keyframes", std::to_string(r.before.keyframe_times.size()),
                  std::to_string(r.after.keyframe_times.size())});
  // K before is the one asked for ("auto": the automatic resolution, relaxed model); after, the
  // spans per interval used (optimize_motion refines the knots when the interpolation cannot
  // pass through the keyframes, and the automatic resolution where the residual lives).
  const bool automatic = options.resolution_is_automatic();
  rows.push_back({"knots per keyframe interval K",
                  automatic ? "auto" : std::to_string(options.nlp.knots_per_interval),
                  spans_text(r)});
  rows.push_back({"variables", "", std::to_string(r.variables)});
  rows.push_back({"constraints", "", std::to_string(r.constraints)});
  rows.push_back(
      {"objective J (N²)", format_number("%.4g", b.objective), format_number("%.4g", a.objective)});
  rows.push_back({"average root force √(J/6) (N)", format_number("%.4g", b.avg_root_force),
                  format_number("%.4g", a.avg_root_force)});
  rows.push_back({"RMS root force (N)", format_number("%.4g", b.rms_force_N),
                  format_number("%.4g", a.rms_force_N)});
  rows.push_back({"RMS root moment (N·m)", format_number("%.4g", b.rms_moment_Nm),
                  format_number("%.4g", a.rms_moment_Nm)});
  rows.push_back({"max root force (N)", format_number("%.4g", b.max_force_N),
                  format_number("%.4g", a.max_force_N)});
  rows.push_back({"max root moment (N·m)", format_number("%.4g", b.max_moment_Nm),
                  format_number("%.4g", a.max_moment_Nm)});
  rows.push_back({"iterations", "", std::to_string(r.solve.iterations)});
  if (r.solve.restarts > 0)
    rows.push_back(
        {"restarts from the best feasible iterate", "", std::to_string(r.solve.restarts)});
  rows.push_back({"seconds", "", format_number("%.2f", r.solve.seconds)});
  rows.push_back({"keyframe times (s)", times_text(r.before.keyframe_times),
                  times_text(r.after.keyframe_times)});
  rows.push_back({"max keyframe translation error (m)",
                  format_number("%.3g", r.before.keyframe_errors.max_translation_error_m),
                  format_number("%.3g", r.after.keyframe_errors.max_translation_error_m)});
  // Light limbs spin between keyframes when nothing holds them (MotionNlpOptions::
  // joint_turn_limit): the largest turn of a joint between two control points shows it.
  rows.push_back(
      {"largest joint turn between control points (°)",
       format_number("%.0f", largest_control_turn(r.before.trajectory, 1) * kDegreesPerRadian),
       format_number("%.0f", largest_control_turn(r.after.trajectory, 1) * kDegreesPerRadian)});
  rows.push_back({"max keyframe rotation error (°)",
                  format_number("%.3g", r.before.keyframe_errors.max_rotation_error_deg),
                  format_number("%.3g", r.after.keyframe_errors.max_rotation_error_deg)});
  return rows;
}

}  // namespace saltus::gui
