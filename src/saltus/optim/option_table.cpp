#include "saltus/optim/option_table.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "saltus/base/constants.h"

namespace saltus {

namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

/// The table. Ranges: `--samples` stops at 100000 because an optimisation there already holds
/// 1.6 GB (the wrench Jacobian of every sample) and writes two 200 MB trajectories; the limit
/// is the same for every verb, the app and the studies.
std::vector<OptionSpec> make_table() {
  std::vector<OptionSpec> t;
  {
    OptionSpec o;
    o.name = "formulation";
    o.flag = "--formulation";
    o.label = "Model";
    o.help =
        "relaxed: minimise the root force with the keyframes within tolerance (the paper's "
        "model); strict: classic spacetime constraints, every root force and moment component "
        "bounded by --epsilon at every sample";
    o.kind = OptionKind::kChoice;
    o.choices = {"relaxed", "strict"};
    o.choice_labels = {"relaxed (paper)", "strict: |F_i| ≤ ε"};
    o.result_key = "formulation";
    o.recorded = ResultRecord::kOptimization;
    o.read = [](const OptimizeOptions& x) -> OptionValue {
      return std::string(x.nlp.formulation == Formulation::kStrict ? "strict" : "relaxed");
    };
    o.write = [](OptimizeOptions& x, const OptionValue& v) {
      x.nlp.formulation =
          std::get<std::string>(v) == "strict" ? Formulation::kStrict : Formulation::kRelaxed;
    };
    t.push_back(std::move(o));
  }
  {
    OptionSpec o;
    o.name = "epsilon";
    o.flag = "--epsilon";
    o.label = "ε (strict)";
    o.unit = "N or N·m";
    o.help = "the strict model's bound on each |F_i| at every sample";
    o.min = 0.0;
    o.min_exclusive = true;
    o.max = kUnbounded;
    o.result_key = "epsilon";
    o.recorded = ResultRecord::kOptimization;
    o.read = [](const OptimizeOptions& x) -> OptionValue { return x.nlp.epsilon; };
    o.write = [](OptimizeOptions& x, const OptionValue& v) { x.nlp.epsilon = std::get<double>(v); };
    o.applies = [](const OptimizeOptions& x) { return x.nlp.formulation == Formulation::kStrict; };
    t.push_back(std::move(o));
  }
  {
    OptionSpec o;
    o.name = "optimize_timing";
    o.flag = "--no-timing";
    o.label = "Optimise keyframe times";
    o.help = "the interior keyframe times are optimised too; --no-timing keeps the given times";
    o.kind = OptionKind::kSwitch;
    o.result_key = "timing_optimized";
    o.recorded = ResultRecord::kOptimization;
    o.read = [](const OptimizeOptions& x) -> OptionValue { return x.nlp.optimize_timing; };
    o.write = [](OptimizeOptions& x, const OptionValue& v) {
      x.nlp.optimize_timing = std::get<bool>(v);
    };
    t.push_back(std::move(o));
  }
  {
    OptionSpec o;
    o.name = "knots_per_interval";
    o.flag = "--knots-per-interval";
    o.label = "Knots per interval";
    o.help =
        "spline knot sub-intervals per keyframe interval (1 = knots at the keyframes, the "
        "paper's resolution)";
    o.kind = OptionKind::kInteger;
    o.use = OptionUse::kEvaluation;
    o.min = 1;
    o.max = 50;
    o.result_key = "knots_per_interval_requested";  // "knots_per_interval" is the K used
    o.recorded = ResultRecord::kOptimization;
    o.read = [](const OptimizeOptions& x) -> OptionValue { return x.nlp.knots_per_interval; };
    o.write = [](OptimizeOptions& x, const OptionValue& v) {
      x.nlp.knots_per_interval = std::get<int>(v);
    };
    t.push_back(std::move(o));
  }
  {
    OptionSpec o;
    o.name = "samples";
    o.flag = "--samples";
    o.label = "Samples";
    o.help =
        "time samples on [0, T], both ends included: the evaluation grid and the optimiser's "
        "quadrature grid (fewer = faster)";
    o.kind = OptionKind::kInteger;
    o.use = OptionUse::kEvaluation;
    o.min = 2;
    o.max = 100000;
    o.result_key = "samples";
    o.recorded = ResultRecord::kEveryResult;
    o.read = [](const OptimizeOptions& x) -> OptionValue { return x.nlp.samples; };
    o.write = [](OptimizeOptions& x, const OptionValue& v) { x.nlp.samples = std::get<int>(v); };
    t.push_back(std::move(o));
  }
  {
    OptionSpec o;
    o.name = "max_iterations";
    o.flag = "--max-iter";
    o.label = "Max iterations";
    o.help = "Ipopt's iteration limit (0: only the starting point is evaluated)";
    o.kind = OptionKind::kInteger;
    o.min = 0;
    o.max = 100000;
    o.read = [](const OptimizeOptions& x) -> OptionValue { return x.solver.max_iterations; };
    o.write = [](OptimizeOptions& x, const OptionValue& v) {
      x.solver.max_iterations = std::get<int>(v);
    };
    t.push_back(std::move(o));
  }
  {
    OptionSpec o;
    o.name = "tolerance";
    o.flag = "--tol";
    o.label = "Tolerance";
    o.help = "Ipopt's convergence tolerance: the NLP error of an optimal exit";
    o.min = 0.0;
    o.min_exclusive = true;
    o.max = kUnbounded;
    o.read = [](const OptimizeOptions& x) -> OptionValue { return x.solver.tolerance; };
    o.write = [](OptimizeOptions& x, const OptionValue& v) {
      x.solver.tolerance = std::get<double>(v);
    };
    t.push_back(std::move(o));
  }
  {
    OptionSpec o;
    o.name = "objective_change_tolerance";
    o.flag = "--objective-change-tol";
    o.label = "Objective change tolerance";
    o.help =
        "also stop (solved, Ipopt 'acceptable') once the objective changes by less than this "
        "fraction for 3 iterations with the keyframes met; 0 = off";
    o.min = 0.0;
    o.max = kUnbounded;
    o.read = [](const OptimizeOptions& x) -> OptionValue {
      return x.solver.objective_change_tolerance;
    };
    o.write = [](OptimizeOptions& x, const OptionValue& v) {
      x.solver.objective_change_tolerance = std::get<double>(v);
    };
    t.push_back(std::move(o));
  }
  {
    OptionSpec o;
    o.name = "max_time_shift";
    o.flag = "--max-time-shift";
    o.label = "Max time shift";
    o.unit = "s";
    o.help = "how far a keyframe time may move from the given one";
    o.min = 0.0;
    o.max = kUnbounded;
    o.read = [](const OptimizeOptions& x) -> OptionValue { return x.nlp.max_time_shift; };
    o.write = [](OptimizeOptions& x, const OptionValue& v) {
      x.nlp.max_time_shift = std::get<double>(v);
    };
    o.applies = [](const OptimizeOptions& x) { return x.nlp.optimize_timing; };
    t.push_back(std::move(o));
  }
  {
    OptionSpec o;
    o.name = "regularization";
    o.flag = "--regularization";
    o.label = "Regularization";
    o.unit = "N²/rad²";
    o.help =
        "weight of the proximity term that keeps the joints near the interpolated motion (light "
        "limbs would otherwise flail); 0 = none";
    o.min = 0.0;
    o.max = kUnbounded;
    o.read = [](const OptimizeOptions& x) -> OptionValue { return x.nlp.regularization; };
    o.write = [](OptimizeOptions& x, const OptionValue& v) {
      x.nlp.regularization = std::get<double>(v);
    };
    t.push_back(std::move(o));
  }
  {
    OptionSpec o;
    o.name = "max_joint_turn";
    o.flag = "--max-joint-turn";
    o.label = "Max joint turn";
    o.unit = "°";
    o.help =
        "soft limit on how far a joint turns relative to its parent between two spline control "
        "points (where the interpolation itself turns further, that is the limit); 0 = none";
    o.min = 0.0;
    o.max = 360.0;
    o.result_key = "joint_turn_limit_deg";
    o.recorded = ResultRecord::kOptimization;
    o.read = [](const OptimizeOptions& x) -> OptionValue {
      return x.nlp.joint_turn_limit * kDegreesPerRadian;
    };
    o.write = [](OptimizeOptions& x, const OptionValue& v) {
      x.nlp.joint_turn_limit = std::get<double>(v) / kDegreesPerRadian;
    };
    o.recorded_value = [](const OptimizeOptions& x) -> OptionValue {
      return x.nlp.limits_joint_turns() ? x.nlp.joint_turn_limit * kDegreesPerRadian : 0.0;
    };
    t.push_back(std::move(o));
  }
  {
    OptionSpec o;
    o.name = "threads";
    o.flag = "--threads";
    o.label = "Threads";
    o.help =
        "threads that evaluate the root wrench and its derivatives (auto: one per hardware "
        "thread, at most 4). The values do not depend on it, but their rounding does, and the "
        "iterations can follow the rounding";
    o.kind = OptionKind::kInteger;
    o.min = 1;
    o.max = 64;
    o.word = "auto";
    o.read = [](const OptimizeOptions& x) -> OptionValue {
      if (x.nlp.threads == 0) return std::string("auto");
      return x.nlp.threads;
    };
    o.write = [](OptimizeOptions& x, const OptionValue& v) {
      x.nlp.threads = std::holds_alternative<std::string>(v) ? 0 : std::get<int>(v);
    };
    t.push_back(std::move(o));
  }
  return t;
}

[[noreturn]] void reject(const OptionSpec& spec, const std::string& problem) {
  throw OptionValueError(spec.flag, problem);
}

std::string quoted(const std::string& text) {
  return "\"" + text + "\"";
}

bool in_range(const OptionSpec& spec, double v) {
  return (spec.min_exclusive ? v > spec.min : v >= spec.min) && v <= spec.max;
}

std::size_t index_of(std::string_view name) {
  const std::vector<OptionSpec>& table = option_table();
  for (std::size_t i = 0; i < table.size(); ++i)
    if (table[i].name == name) return i;
  throw std::logic_error("no option named \"" + std::string(name) + "\" in the option table");
}

}  // namespace

const std::vector<OptionSpec>& option_table() {
  static const std::vector<OptionSpec> table = make_table();
  return table;
}

const OptionSpec& option_spec(std::string_view name) {
  return option_table()[index_of(name)];
}

OptionValue parse_option_value(const OptionSpec& spec, const std::string& text) {
  switch (spec.kind) {
    case OptionKind::kSwitch:
      if (text == "true" || text == "on" || text == "1") return true;
      if (text == "false" || text == "off" || text == "0") return false;
      reject(spec, quoted(text) + " is not true or false");
    case OptionKind::kChoice:
      return checked_option_value(spec, text);
    case OptionKind::kInteger:
    case OptionKind::kReal:
      break;
  }
  if (!spec.word.empty() && text == spec.word) return text;
  const char* first = text.data();
  const char* last = first + text.size();
  if (spec.kind == OptionKind::kInteger) {
    int value = 0;
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last || text.empty())
      reject(spec,
             quoted(text) + " is not a whole number (allowed: " + option_range_text(spec) + ")");
    return checked_option_value(spec, value);
  }
  double value = 0.0;  // from_chars: the same text gives the same number in every locale
  const auto [end, error] = std::from_chars(first, last, value);
  if (error != std::errc() || end != last || text.empty() || !std::isfinite(value))
    reject(spec, quoted(text) + " is not a number (allowed: " + option_range_text(spec) + ")");
  return checked_option_value(spec, value);
}

OptionValue checked_option_value(const OptionSpec& spec, const OptionValue& value) {
  const auto* word = std::get_if<std::string>(&value);
  switch (spec.kind) {
    case OptionKind::kSwitch:
      if (!std::holds_alternative<bool>(value)) reject(spec, "expected on or off");
      return value;
    case OptionKind::kChoice:
      if (word)
        for (const std::string& choice : spec.choices)
          if (*word == choice) return value;
      reject(spec, (word ? quoted(*word) : std::string("the value")) + " is not one of " +
                       option_range_text(spec));
    case OptionKind::kInteger:
    case OptionKind::kReal:
      break;
  }
  if (word) {
    if (!spec.word.empty() && *word == spec.word) return value;
    reject(spec, quoted(*word) + " is not allowed (allowed: " + option_range_text(spec) + ")");
  }
  double number = 0.0;
  if (const auto* i = std::get_if<int>(&value))
    number = *i;
  else if (const auto* d = std::get_if<double>(&value))
    number = *d;
  else
    reject(spec, "expected a number (allowed: " + option_range_text(spec) + ")");
  if (spec.kind == OptionKind::kInteger && !std::holds_alternative<int>(value))
    reject(spec, option_value_text(value) + " is not a whole number");
  if (!std::isfinite(number) || !in_range(spec, number))
    reject(spec, option_value_text(value) +
                     " is out of range (allowed: " + option_range_text(spec) + ")");
  if (spec.kind == OptionKind::kReal) return number;
  return value;
}

std::string option_value_text(const OptionValue& value) {
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const auto* i = std::get_if<int>(&value)) return std::to_string(*i);
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, std::get<double>(value)).ptr;
  return std::string(buffer, end);
}

std::string option_range_text(const OptionSpec& spec) {
  if (spec.kind == OptionKind::kSwitch) return "true|false";
  if (spec.kind == OptionKind::kChoice) {
    std::string out;
    for (const std::string& c : spec.choices)
      out += (out.empty() ? "" : "|") + c;
    return out;
  }
  const std::string low =
      option_value_text(spec.kind == OptionKind::kInteger ? OptionValue(static_cast<int>(spec.min))
                                                          : OptionValue(spec.min));
  std::string out;
  if (std::isinf(spec.max))
    out = (spec.min_exclusive ? "> " : ">= ") + low;
  else
    out = low + "-" +
          option_value_text(spec.kind == OptionKind::kInteger
                                ? OptionValue(static_cast<int>(spec.max))
                                : OptionValue(spec.max));
  if (!spec.word.empty()) out += " or " + spec.word;
  return out;
}

OptionValues::OptionValues() : OptionValues(OptimizeOptions{}) {}

OptionValues::OptionValues(const OptimizeOptions& options) {
  for (const OptionSpec& spec : option_table())
    values_.push_back(spec.read(options));
}

const OptionValue& OptionValues::get(std::string_view name) const {
  return values_[index_of(name)];
}

int OptionValues::integer(std::string_view name) const {
  return std::get<int>(get(name));
}

double OptionValues::real(std::string_view name) const {
  return std::get<double>(get(name));
}

bool OptionValues::on(std::string_view name) const {
  return std::get<bool>(get(name));
}

void OptionValues::set(std::string_view name, const OptionValue& value) {
  const std::size_t i = index_of(name);
  values_[i] = checked_option_value(option_table()[i], value);
}

void OptionValues::set_text(std::string_view name, const std::string& text) {
  const std::size_t i = index_of(name);
  values_[i] = parse_option_value(option_table()[i], text);
}

OptimizeOptions OptionValues::optimize_options() const {
  OptimizeOptions options;
  const std::vector<OptionSpec>& table = option_table();
  for (std::size_t i = 0; i < table.size(); ++i)
    table[i].write(options, values_[i]);
  return options;
}

EvaluateOptions OptionValues::evaluate_options() const {
  return evaluation_options(optimize_options());
}

bool OptionValues::applies(std::string_view name) const {
  const OptionSpec& spec = option_spec(name);
  return !spec.applies || spec.applies(optimize_options());
}

EvaluateOptions evaluation_options(const OptimizeOptions& options) {
  EvaluateOptions e;
  e.samples = options.nlp.samples;
  e.interpolation.knots_per_interval = options.nlp.knots_per_interval;
  return e;
}

OptimizeOptions with_evaluation_options(const EvaluateOptions& options) {
  OptimizeOptions o;
  o.nlp.samples = options.samples;
  o.nlp.knots_per_interval = options.interpolation.knots_per_interval;
  return o;
}

std::vector<std::pair<std::string, OptionValue>> recorded_options(const OptimizeOptions& options,
                                                                  bool optimization) {
  std::vector<std::pair<std::string, OptionValue>> out;
  for (const OptionSpec& spec : option_table()) {
    const bool recorded = spec.recorded == ResultRecord::kEveryResult ||
                          (optimization && spec.recorded == ResultRecord::kOptimization);
    if (!recorded || (spec.applies && !spec.applies(options))) continue;
    out.emplace_back(spec.result_key,
                     spec.recorded_value ? spec.recorded_value(options) : spec.read(options));
  }
  return out;
}

}  // namespace saltus
