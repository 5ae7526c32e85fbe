#include "saltus/optim/option_table.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "saltus/base/constants.h"

namespace saltus {

namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

/// An entry's name, flag and texts; the rest is set by the helpers below.
OptionSpec entry(const char* name, const char* flag, const char* label, const char* unit,
                 const char* help) {
  OptionSpec o;
  o.name = name;
  o.flag = flag;
  o.label = label;
  o.unit = unit;
  o.help = help;
  return o;
}

/// A number in [min, max] (or (min, max] when min_exclusive).
void range(OptionSpec& o, OptionKind kind, double min, double max, bool min_exclusive = false) {
  o.kind = kind;
  o.min = min;
  o.max = max;
  o.min_exclusive = min_exclusive;
}

/// The value is the field options.*part.*field (bool, int or double, as the option's kind).
template <typename Part, typename T>
void bind(OptionSpec& o, Part OptimizeOptions::*part, T Part::*field) {
  o.read = [part, field](const OptimizeOptions& x) -> OptionValue { return x.*part.*field; };
  o.write = [part, field](OptimizeOptions& x, const OptionValue& v) {
    x.*part.*field = std::get<T>(v);
  };
}

void record(OptionSpec& o, const char* key, ResultRecord recorded) {
  o.result_key = key;
  o.recorded = recorded;
}

/// The table. Ranges: `--samples` stops at 100000 because an optimisation there already holds
/// 1.6 GB (the wrench Jacobian of every sample) and writes two 200 MB trajectories; the limit
/// is the same for every verb, the app and the studies.
std::vector<OptionSpec> make_table() {
  constexpr auto nlp = &OptimizeOptions::nlp;
  constexpr auto solver = &OptimizeOptions::solver;
  std::vector<OptionSpec> t;

  OptionSpec o = entry("formulation", "--formulation", "Model", "",
                       "relaxed: minimise the root force with the keyframes within tolerance (the "
                       "paper's model); strict: classic spacetime constraints, every root force "
                       "and moment component bounded by --epsilon at every sample");
  o.kind = OptionKind::kChoice;
  o.choices = {"relaxed", "strict"};
  o.choice_labels = {"relaxed (paper)", "strict: |F_i| ≤ ε"};
  record(o, "formulation", ResultRecord::kOptimization);
  o.read = [](const OptimizeOptions& x) -> OptionValue {
    return std::string(x.nlp.formulation == Formulation::kStrict ? "strict" : "relaxed");
  };
  o.write = [](OptimizeOptions& x, const OptionValue& v) {
    x.nlp.formulation =
        std::get<std::string>(v) == "strict" ? Formulation::kStrict : Formulation::kRelaxed;
  };
  t.push_back(o);

  o = entry("epsilon", "--epsilon", "ε (strict)", "N or N·m",
            "the strict model's bound on each |F_i| at every sample");
  range(o, OptionKind::kReal, 0.0, kUnbounded, true);
  record(o, "epsilon", ResultRecord::kOptimization);
  bind(o, nlp, &MotionNlpOptions::epsilon);
  o.applies = [](const OptimizeOptions& x) { return x.nlp.formulation == Formulation::kStrict; };
  o.applies_when = "with --formulation strict";
  t.push_back(o);

  o = entry("optimize_timing", "--no-timing", "Optimise keyframe times", "",
            "the interior keyframe times are optimised too; --no-timing keeps the given times");
  o.kind = OptionKind::kSwitch;
  record(o, "timing_optimized", ResultRecord::kOptimization);
  bind(o, nlp, &MotionNlpOptions::optimize_timing);
  t.push_back(o);

  o = entry("knots_per_interval", "--knots-per-interval", "Knots per interval", "",
            "knot spans per keyframe interval: a number (1 = knots at the keyframes, the paper's "
            "resolution) or, for optimize, auto (chosen from how far the body turns, then "
            "refined where the residual lives; relaxed model)");
  range(o, OptionKind::kInteger, 1, 50);
  o.use = OptionUse::kEvaluation;
  o.word = "auto";
  o.word_use = OptionUse::kOptimization;
  // "knots_per_interval" records the K used, which may be finer (optimize_motion), and
  // "resolution" whether it was automatic; this key keeps the number as it always did.
  record(o, "knots_per_interval_requested", ResultRecord::kOptimization);
  o.costly_above = 8;
  o.cost =
      "the optimiser's variables grow with the knots and its time and memory faster still: "
      "at K = 50 a run takes minutes and gigabytes";
  o.read = [](const OptimizeOptions& x) -> OptionValue {
    if (x.automatic_resolution) return std::string("auto");
    return x.nlp.knots_per_interval;
  };
  o.write = [](OptimizeOptions& x, const OptionValue& v) {
    x.automatic_resolution = std::holds_alternative<std::string>(v);
    x.nlp.knots_per_interval = x.automatic_resolution ? 1 : std::get<int>(v);
  };
  o.recorded_value = [](const OptimizeOptions& x) -> OptionValue {
    return x.nlp.knots_per_interval;
  };
  t.push_back(o);

  o = entry("samples", "--samples", "Samples", "",
            "time samples on [0, T], both ends included: the grid of the written trajectories "
            "and figures, and of the strict model's force bounds (the relaxed objective is "
            "integrated on every knot span, and every residual is checked densely, whatever "
            "this is)");
  range(o, OptionKind::kInteger, 2, 100000);
  o.use = OptionUse::kEvaluation;
  record(o, "samples", ResultRecord::kEveryResult);
  o.costly_above = 2001;
  o.cost =
      "every evaluation's time and memory grow with the samples: at 100000 an optimisation "
      "holds 1.6 GB and writes two 200 MB trajectories";
  bind(o, nlp, &MotionNlpOptions::samples);
  t.push_back(o);

  o = entry("max_iterations", "--max-iter", "Max iterations", "",
            "Ipopt's iteration limit (0: only the starting point is evaluated)");
  range(o, OptionKind::kInteger, 0, 100000);
  bind(o, solver, &SolverOptions::max_iterations);
  o.costly_above = 3000;
  o.cost = "a run that does not converge goes on for that many iterations: minutes to hours";
  t.push_back(o);

  o = entry("tolerance", "--tol", "Tolerance", "",
            "Ipopt's convergence tolerance: the NLP error of an optimal exit");
  range(o, OptionKind::kReal, 0.0, kUnbounded, true);
  bind(o, solver, &SolverOptions::tolerance);
  t.push_back(o);

  o = entry("objective_change_tolerance", "--objective-change-tol", "Objective change tolerance",
            "",
            "also stop (solved, Ipopt 'acceptable') once the objective changes by less than this "
            "fraction for 3 iterations with the keyframes met; 0 = off");
  range(o, OptionKind::kReal, 0.0, kUnbounded);
  bind(o, solver, &SolverOptions::objective_change_tolerance);
  t.push_back(o);

  o = entry("max_time_shift", "--max-time-shift", "Max time shift", "s",
            "how far a keyframe time may move from the given one");
  range(o, OptionKind::kReal, 0.0, kUnbounded);
  bind(o, nlp, &MotionNlpOptions::max_time_shift);
  o.applies = [](const OptimizeOptions& x) { return x.nlp.optimize_timing; };
  o.applies_when = "unless --no-timing";
  t.push_back(o);

  o = entry("min_time_gap", "--min-time-gap", "Min keyframe gap", "s",
            "the least time between consecutive keyframes (paper eq. 4), at most half the "
            "shortest given interval");
  range(o, OptionKind::kReal, 0.0, kUnbounded, true);
  bind(o, nlp, &MotionNlpOptions::min_time_gap);
  o.applies = [](const OptimizeOptions& x) { return x.nlp.optimize_timing; };
  o.applies_when = "unless --no-timing";
  t.push_back(o);

  o = entry("regularization", "--regularization", "Regularization", "N²/rad²",
            "weight of the proximity term that keeps the joints near the interpolated motion "
            "(light limbs would otherwise flail); 0 = none");
  range(o, OptionKind::kReal, 0.0, kUnbounded);
  bind(o, nlp, &MotionNlpOptions::regularization);
  t.push_back(o);

  o = entry("joint_effort", "--joint-effort", "Joint effort", "",
            "weight of the term that keeps each joint's angular acceleration near the starting "
            "motion's, in units of the joint moment it asks for (acceleration times the inertia "
            "the joint moves): the joints do not pay for a physical root, e.g. with kicks at "
            "take-off; 1 weighs a joint moment like a root moment; 0 = none");
  range(o, OptionKind::kReal, 0.0, kUnbounded);
  record(o, "joint_effort", ResultRecord::kOptimization);
  bind(o, nlp, &MotionNlpOptions::joint_effort);
  o.applies = [](const OptimizeOptions& x) { return x.nlp.formulation == Formulation::kRelaxed; };
  o.applies_when = "with --formulation relaxed";
  t.push_back(o);

  o = entry("joint_load_weight", "--joint-load-weight", "Joint-load weight", "N²/(N·m)²",
            "weight of least joint effort in a last solve at the keyframe times found: the mean "
            "square of every joint's moment over the flight, in root-wrench N² per (N·m)²; among "
            "motions of nearly the same root force it prefers the one whose joints work least, "
            "without which the optimiser buys the last newtons with kicks of a foot or forearm "
            "at take-off or landing; 0 = none (no last solve)");
  range(o, OptionKind::kReal, 0.0, kUnbounded);
  record(o, "joint_load_weight", ResultRecord::kOptimization);
  bind(o, nlp, &MotionNlpOptions::joint_load_weight);
  o.applies = [](const OptimizeOptions& x) { return x.nlp.formulation == Formulation::kRelaxed; };
  o.applies_when = "with --formulation relaxed";
  t.push_back(o);

  o = entry("keyframe_weight", "--keyframe-weight", "Keyframe prior", "N²",
            "weight of the prior that prefers, among motions of nearly the same root force, the "
            "one closest to the keyframes (their distance in units of the tolerances): it is "
            "what brings keyframe times back (a fixed resolution keeps the paper's objective, "
            "so it is 0 there); 0 = none");
  range(o, OptionKind::kReal, 0.0, kUnbounded);
  record(o, "keyframe_weight", ResultRecord::kOptimization);
  bind(o, nlp, &MotionNlpOptions::keyframe_weight);
  // The prior is a tie-break among near-physical motions, which only knots fine enough to reach
  // near zero give: on a resolution the user fixed (the paper's K = 1 above all) the motion
  // must use its tolerances to cut the force, and the prior would fight it.
  o.applies = [](const OptimizeOptions& x) { return x.resolution_is_automatic(); };
  o.applies_when = "with --knots-per-interval auto and --formulation relaxed";
  o.value_when_inactive = 0.0;
  t.push_back(o);

  o = entry("max_joint_turn", "--max-joint-turn", "Max joint turn", "°",
            "soft limit on how far a joint turns relative to its parent between two spline "
            "control points (where the interpolation itself turns further, that is the limit); "
            "0 = none");
  range(o, OptionKind::kReal, 0.0, 360.0);
  record(o, "joint_turn_limit_deg", ResultRecord::kOptimization);
  o.read = [](const OptimizeOptions& x) -> OptionValue {
    return x.nlp.joint_turn_limit * kDegreesPerRadian;
  };
  o.write = [](OptimizeOptions& x, const OptionValue& v) {
    x.nlp.joint_turn_limit = std::get<double>(v) / kDegreesPerRadian;
  };
  o.recorded_value = [](const OptimizeOptions& x) -> OptionValue {
    return x.nlp.limits_joint_turns() ? x.nlp.joint_turn_limit * kDegreesPerRadian : 0.0;
  };
  t.push_back(o);

  o = entry("threads", "--threads", "Threads", "",
            "threads that evaluate the root wrench and its derivatives (auto: one per hardware "
            "thread, at most 4). The values do not depend on it, but their rounding does, and "
            "the iterations can follow the rounding");
  range(o, OptionKind::kInteger, 1, 64);
  o.word = "auto";
  o.read = [](const OptimizeOptions& x) -> OptionValue {
    if (x.nlp.threads == 0) return std::string("auto");
    return x.nlp.threads;
  };
  o.write = [](OptimizeOptions& x, const OptionValue& v) {
    x.nlp.threads = std::holds_alternative<std::string>(v) ? 0 : std::get<int>(v);
  };
  t.push_back(o);
  return t;
}

[[noreturn]] void reject(const OptionSpec& spec, const std::string& problem) {
  throw OptionValueError(spec.flag, problem);
}

std::string quoted(const std::string& text) {
  return "\"" + text + "\"";
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

OptionValue OptionSpec::default_value(OptionUse runs) const {
  return read(runs == OptionUse::kEvaluation ? with_evaluation_options(EvaluateOptions{})
                                             : OptimizeOptions{});
}

OptionValue parse_option_value(const OptionSpec& spec, const std::string& text, OptionUse runs) {
  switch (spec.kind) {
    case OptionKind::kSwitch:
      if (text == "true" || text == "on" || text == "1") return true;
      if (text == "false" || text == "off" || text == "0") return false;
      reject(spec, quoted(text) + " is not true or false");
    case OptionKind::kChoice:
      return checked_option_value(spec, text, runs);
    case OptionKind::kInteger:
    case OptionKind::kReal:
      break;
  }
  if (!spec.word.empty() && text == spec.word) return checked_option_value(spec, text, runs);
  const char* first = text.data();
  const char* last = first + text.size();
  if (spec.kind == OptionKind::kInteger) {
    int value = 0;
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last || text.empty())
      reject(spec, quoted(text) +
                       " is not a whole number (allowed: " + option_range_text(spec, runs) + ")");
    return checked_option_value(spec, value, runs);
  }
  // from_chars: the same text gives the same number in every locale; "nan" and "inf" are
  // numbers outside every option's bound (checked_option_value says so, as for every flag).
  double value = 0.0;
  const auto [end, error] = std::from_chars(first, last, value);
  if (error != std::errc() || end != last || text.empty())
    reject(spec,
           quoted(text) + " is not a number (allowed: " + option_range_text(spec, runs) + ")");
  return checked_option_value(spec, value, runs);
}

OptionValue checked_option_value(const OptionSpec& spec, const OptionValue& value, OptionUse runs) {
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
                       option_range_text(spec, runs));
    case OptionKind::kInteger:
    case OptionKind::kReal:
      break;
  }
  if (word) {
    if (spec.takes_word(runs) && *word == spec.word) return value;
    if (!spec.word.empty() && *word == spec.word)
      reject(spec, quoted(*word) + " is for optimisations only (allowed here: " +
                       option_range_text(spec, runs) + ")");
    reject(spec,
           quoted(*word) + " is not allowed (allowed: " + option_range_text(spec, runs) + ")");
  }
  double number = 0.0;
  if (const auto* i = std::get_if<int>(&value))
    number = *i;
  else if (const auto* d = std::get_if<double>(&value))
    number = *d;
  else
    reject(spec, "expected a number (allowed: " + option_range_text(spec, runs) + ")");
  if (spec.kind == OptionKind::kInteger && !std::holds_alternative<int>(value))
    reject(spec, option_value_text(value) + " is not a whole number");
  if (!within(option_bound(spec), number))
    reject(spec, bound_problem(option_bound(spec), number) +
                     (spec.takes_word(runs) ? " (or " + spec.word + ")" : ""));
  if (spec.kind == OptionKind::kReal) return number;
  return value;
}

NumberBound option_bound(const OptionSpec& spec) {
  NumberBound bound;
  bound.lower = spec.min;
  bound.upper = spec.max;
  bound.lower_open = spec.min_exclusive;
  bound.unit = spec.unit.c_str();
  bound.whole = spec.kind == OptionKind::kInteger;
  return bound;
}

std::string option_value_text(const OptionValue& value) {
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const auto* i = std::get_if<int>(&value)) return std::to_string(*i);
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, std::get<double>(value)).ptr;
  return std::string(buffer, end);
}

std::string option_range_text(const OptionSpec& spec, OptionUse runs) {
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
  if (spec.takes_word(runs)) out += " or " + spec.word;
  return out;
}

OptionValues::OptionValues(OptionUse runs)
    : OptionValues(runs == OptionUse::kEvaluation ? with_evaluation_options(EvaluateOptions{})
                                                  : OptimizeOptions{},
                   runs) {}

OptionValues::OptionValues(const OptimizeOptions& options, OptionUse runs) : runs_(runs) {
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
  values_[i] = checked_option_value(option_table()[i], value, runs_);
}

void OptionValues::set_text(std::string_view name, const std::string& text) {
  const std::size_t i = index_of(name);
  values_[i] = parse_option_value(option_table()[i], text, runs_);
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
  o.automatic_resolution = false;
  o.nlp.samples = options.samples;
  o.nlp.knots_per_interval = options.interpolation.knots_per_interval;
  return o;
}

nlohmann::json option_value_json(const OptionValue& value) {
  return std::visit([](const auto& v) { return nlohmann::json(v); }, value);
}

std::string option_description(const OptionSpec& spec, OptionUse runs) {
  std::string out = spec.help;
  if (spec.kind != OptionKind::kSwitch && spec.kind != OptionKind::kChoice)
    out += " (" + (spec.unit.empty() ? std::string() : spec.unit + "; ") +
           option_range_text(spec, runs) + ")";
  if (!spec.applies_when.empty()) out += ". Applies " + spec.applies_when + ".";
  return out;
}

OptimizeOptions effective_options(const OptimizeOptions& options) {
  OptimizeOptions effective = options;
  for (const OptionSpec& spec : option_table())
    if (spec.applies && spec.value_when_inactive && !spec.applies(options))
      spec.write(effective, *spec.value_when_inactive);
  return effective;
}

namespace {

/// Converts to any member type: T{AnyField{}, ...} compiles for at most T's member count.
struct AnyField {
  template <class T>
  operator T() const;
};

template <class T, class Indices, class = void>
struct BraceInitializable : std::false_type {};
template <class T, std::size_t... I>
struct BraceInitializable<T, std::index_sequence<I...>,
                          std::void_t<decltype(T{(void(I), AnyField{})...})>> : std::true_type {};

/// The number of members of the aggregate T.
template <class T, std::size_t N = 0>
constexpr std::size_t member_count() {
  if constexpr (BraceInitializable<T, std::make_index_sequence<N + 1>>::value)
    return member_count<T, N + 1>();
  else
    return N;
}

// Every member of the option structs is either an option of the table or one of the internal
// settings below (or, like verbose and derivative_test_file, decides only what is logged). A new
// member changes these counts: declare it in the table or below, then update the count.
static_assert(member_count<MotionNlpOptions>() == 24, "new MotionNlpOptions member: declare it");
static_assert(member_count<DampingRule>() == 7, "new DampingRule member: declare it");
static_assert(member_count<SolverOptions>() == 11, "new SolverOptions member: declare it");
static_assert(member_count<OptimizeOptions>() == 4, "new OptimizeOptions member: declare it");

/// The settings that decide a result but have no flag: the objective's quadrature, the
/// Hessian's damping, Ipopt's acceptable exit and restarts, the knot refinement.
nlohmann::json internal_settings(const OptimizeOptions& o) {
  const MotionNlpOptions& n = o.nlp;
  const SolverOptions& s = o.solver;
  nlohmann::json checkpoints = nlohmann::json::array();
  for (const FeasibilityCheckpoint& c : s.feasibility_checkpoints)
    checkpoints.push_back({c.iterations, c.violation});
  return {{"subdivisions", n.subdivisions},
          {"quadrature_nodes", n.quadrature_nodes},
          {"quadrature_spacing", n.quadrature_spacing},
          {"given_keyframe_times", n.given_keyframe_times},
          {"damping",
           {{"initial", n.damping.initial},
            {"minimum", n.damping.minimum},
            {"maximum", n.damping.maximum},
            {"shrink", n.damping.shrink},
            {"grow", n.damping.grow},
            {"good_ratio", n.damping.good_ratio},
            {"poor_ratio", n.damping.poor_ratio}}},
          {"adapt_damping", n.adapt_damping},
          {"joint_turn_weight", n.joint_turn_weight},
          {"root_moment_weight", n.root_moment_weight},
          {"joint_load_scales", n.joint_load_scales},
          {"joint_moment_bounds", n.joint_moment_bounds},
          {"joint_force_bounds", n.joint_force_bounds},
          {"acceptable_iterations", s.acceptable_iterations},
          {"acceptable_constraint_violation", s.acceptable_constraint_violation},
          {"stall_iterations", s.stall_iterations},
          {"max_restarts", s.max_restarts},
          {"feasibility_checkpoints", checkpoints},
          {"warm_start", s.warm_start},
          {"refine_when_keyframes_missed", o.refine_when_keyframes_missed}};
}

}  // namespace

nlohmann::json result_deciding_settings(const OptimizeOptions& options) {
  // As a run uses them: an option that does not apply is recorded at the value it acts with.
  const OptimizeOptions effective = effective_options(options);
  nlohmann::json settings = nlohmann::json::object();
  for (const OptionSpec& spec : option_table())
    settings[spec.name] = option_value_json(spec.read(effective));
  settings["internal"] = internal_settings(effective);
  return settings;
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
