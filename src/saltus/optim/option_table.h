#pragma once
/// @file
/// The option table: every evaluation and optimiser option declared once, with its name, flag,
/// label, unit, range, help, how result.json records it and where its value goes in
/// OptimizeOptions. The CLI's flags, saltus-gui's command line and Optimise panel, and the
/// result.json writer and reader are built from it, so a new option is one entry in
/// option_table.cpp (plus the code that uses its value). Defaults are the option structs' own
/// (MotionNlpOptions, SolverOptions, kDefaultSamples), read through each entry: stated once.

#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "saltus/base/number_bound.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/optim/optimize.h"

namespace saltus {

/// One option's value: on/off, a whole number, a real number, or a word (a choice, or the word
/// a numeric option may take instead of a number, such as "auto").
using OptionValue = std::variant<bool, int, double, std::string>;

enum class OptionKind {
  kSwitch,   ///< on/off; its flag sets the opposite of the default ("--no-timing")
  kInteger,  ///< a whole number in [min, max], or `word`
  kReal,     ///< a finite number in [min, max] (min excluded when min_exclusive), or `word`
  kChoice,   ///< one of `choices`
};

/// Which runs use an option.
enum class OptionUse {
  kEvaluation,    ///< every run: evaluate, simulate, optimize and the studies' optimisations
  kOptimization,  ///< the optimiser only
};

/// Which result.json files record an option, under OptionSpec::result_key.
enum class ResultRecord { kNone, kOptimization, kEveryResult };

struct OptionSpec {
  std::string name;   ///< identifier, e.g. "max_iterations" (also the GUI's settings key)
  std::string flag;   ///< command-line flag, e.g. "--max-iter"
  std::string label;  ///< a form's label, e.g. "Max iterations"
  std::string unit;   ///< "" when dimensionless, e.g. "s", "°", "N or N·m"
  std::string help;   ///< what it does, for --help and tooltips
  OptionKind kind = OptionKind::kReal;
  OptionUse use = OptionUse::kOptimization;
  double min = 0.0;  ///< numbers: the range, inclusive (see min_exclusive); max may be +inf
  double max = 0.0;
  bool min_exclusive = false;              ///< numbers: the value must exceed min ("positive")
  std::vector<std::string> choices;        ///< kChoice: the words
  std::vector<std::string> choice_labels;  ///< kChoice: what a form shows for each word
  std::string word;                        ///< numbers: a word taken instead of a number, or ""
  /// The runs that take the word: kEvaluation, every run the option is for; kOptimization,
  /// optimisations only ("auto" knots: the automatic resolution is the optimiser's).
  OptionUse word_use = OptionUse::kEvaluation;
  std::string result_key;  ///< result.json key, "" when not recorded
  ResultRecord recorded = ResultRecord::kNone;
  /// The option's value in `options`, and writing a (checked) value into them.
  std::function<OptionValue(const OptimizeOptions&)> read;
  std::function<void(OptimizeOptions&, const OptionValue&)> write;
  /// Whether the option acts, given the others (ε: the strict model only); null = always.
  /// Forms disable it when it does not, result.json leaves it out, and a run uses
  /// `value_when_inactive` instead of its value (effective_options).
  std::function<bool(const OptimizeOptions&)> applies;
  /// When `applies` holds, in words for --help and the app ("with --formulation strict").
  std::string applies_when;
  /// The value a run uses when the option does not apply; empty: its value is simply unused.
  std::optional<OptionValue> value_when_inactive;
  /// What result.json records when that differs from `read`; null = `read`.
  std::function<OptionValue(const OptimizeOptions&)> recorded_value;
  /// Numbers: a value above this costs minutes or gigabytes where the default costs a second
  /// or two (the app asks before keeping one); +inf: no value does.
  double costly_above = std::numeric_limits<double>::infinity();
  /// What such a value costs, in words ("" when none does).
  std::string cost;

  /// The default of an optimisation, or (kEvaluation) of `saltus evaluate` and `simulate`:
  /// read from with_evaluation_options(EvaluateOptions{}).
  OptionValue default_value(OptionUse runs = OptionUse::kOptimization) const;
  /// Whether runs of `runs` take `word`.
  bool takes_word(OptionUse runs) const {
    return !word.empty() &&
           (word_use == OptionUse::kEvaluation || runs == OptionUse::kOptimization);
  }
};

/// Every option, in the order forms and help list them.
const std::vector<OptionSpec>& option_table();
/// The entry named `name`; throws std::logic_error when there is none (a programming error).
const OptionSpec& option_spec(std::string_view name);

/// A value that is not one of an option's: what() is "<flag>: <problem>".
class OptionValueError : public std::invalid_argument {
 public:
  OptionValueError(const std::string& flag, const std::string& problem)
      : std::invalid_argument(flag + ": " + problem), problem_(problem) {}
  const std::string& problem() const { return problem_; }

 private:
  std::string problem_;
};

/// Reads text given for `spec` (a flag's value, a form field, a stored setting): a number, the
/// option's word (if runs of `runs` take it), a choice, or for switches true/false. Throws
/// OptionValueError for anything else or a value out of range.
OptionValue parse_option_value(const OptionSpec& spec, const std::string& text,
                               OptionUse runs = OptionUse::kOptimization);
/// Throws OptionValueError when `value` is of the wrong type or range for runs of `runs`.
/// Returns the value as stored (an integer given for a real option becomes a double).
OptionValue checked_option_value(const OptionSpec& spec, const OptionValue& value,
                                 OptionUse runs = OptionUse::kOptimization);
/// The value as JSON: true/false, a number or a word (result.json, study definitions).
nlohmann::json option_value_json(const OptionValue& value);
/// Text that parse_option_value reads back to the same value (reals in the shortest such form).
std::string option_value_text(const OptionValue& value);
/// A number option's range as a NumberBound (its unit points into `spec`, which must outlive it;
/// the table's entries do). use_cases/flag_bounds.h lists it with every other flag's.
NumberBound option_bound(const OptionSpec& spec);
/// The allowed values, e.g. "2-100000", "> 0", ">= 0", "relaxed|strict", "1-64 or auto".
std::string option_range_text(const OptionSpec& spec, OptionUse runs = OptionUse::kOptimization);
/// What --help and the app's tooltips say of an option: its help, unit and range, and when it
/// applies ("... (N²; >= 0). Applies with --knots-per-interval auto and --formulation relaxed.").
std::string option_description(const OptionSpec& spec, OptionUse runs = OptionUse::kOptimization);

/// `options` as a run uses them: every option that does not apply set to its
/// OptionSpec::value_when_inactive. optimize_motion runs on these.
OptimizeOptions effective_options(const OptimizeOptions& options);

/// Every setting that decides an optimisation's result, as JSON: the table's options by name and
/// the internal settings no flag reaches (quadrature, damping, solver safeguards). A study's
/// definition holds it, so shards and resumed runs with other settings never merge.
nlohmann::json result_deciding_settings(const OptimizeOptions& options);

/// A value for every option of the table, each at its default until set. The values of an
/// optimisation, or (OptionUse::kEvaluation) of `saltus evaluate` and `simulate`: their
/// defaults, and words only optimisations take refused.
class OptionValues {
 public:
  explicit OptionValues(OptionUse runs = OptionUse::kOptimization);
  /// The values in `options`.
  explicit OptionValues(const OptimizeOptions& options, OptionUse runs = OptionUse::kOptimization);

  const OptionValue& get(std::string_view name) const;
  int integer(std::string_view name) const;  ///< std::bad_variant_access if not a number
  double real(std::string_view name) const;
  bool on(std::string_view name) const;
  /// Throws OptionValueError for a value of the wrong type or range.
  void set(std::string_view name, const OptionValue& value);
  /// parse_option_value, then set.
  void set_text(std::string_view name, const std::string& text);
  /// OptimizeOptions{} with every option written into it.
  OptimizeOptions optimize_options() const;
  /// The evaluation options (OptionUse::kEvaluation) as evaluate and simulate take them.
  EvaluateOptions evaluate_options() const;
  /// OptionSpec::applies at these values.
  bool applies(std::string_view name) const;

  OptionUse runs() const { return runs_; }

  bool operator==(const OptionValues& other) const {
    return runs_ == other.runs_ && values_ == other.values_;
  }
  bool operator!=(const OptionValues& other) const { return !(*this == other); }

 private:
  OptionUse runs_;
  std::vector<OptionValue> values_;  ///< in table order
};

/// The evaluation part of optimiser options (samples, knots per interval; automatic
/// resolution evaluates at one knot span per interval), and back (no automatic resolution).
EvaluateOptions evaluation_options(const OptimizeOptions& options);
OptimizeOptions with_evaluation_options(const EvaluateOptions& options);

/// What result.json records of `options`: (key, value) in table order. `optimization` false
/// for evaluate and simulate results, which record only ResultRecord::kEveryResult options.
std::vector<std::pair<std::string, OptionValue>> recorded_options(const OptimizeOptions& options,
                                                                  bool optimization);

}  // namespace saltus
