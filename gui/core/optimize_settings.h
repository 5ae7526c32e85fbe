#pragma once
/// @file
/// The optimisation panel's values (one per option of the library's option table, so the panel,
/// saltus-gui's command line and `saltus optimize` share names, ranges and defaults), how they
/// are stored between sessions and the rows of the result table (the progress: run_progress.h).

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "saltus/optim/optimize.h"
#include "saltus/optim/option_table.h"

namespace saltus::gui {

/// The Optimise panel's values: every option of saltus/optim/option_table.h, each at the
/// library's default until set (set() checks the table's range and names the flag).
using OptimizeSettings = OptionValues;

/// The library's options for these values.
OptimizeOptions to_optimize_options(const OptimizeSettings& settings);

/// The label of the first option (table order) whose value differs, "" when none: what an undo
/// step names.
std::string first_changed_option(const OptimizeSettings& before, const OptimizeSettings& after);

/// The options `after` sets to a value that costs minutes or gigabytes (OptionSpec::
/// costly_above) where `before` did not, each in words: "Samples = 100000: every evaluation's
/// time and memory grow with the samples: …". The app asks before keeping such a value.
std::vector<std::string> newly_costly_settings(const OptimizeSettings& before,
                                               const OptimizeSettings& after);

/// A form's tooltip for an option: its help, then unit and range, then the CLI flag.
std::string option_tooltip(const OptionSpec& spec);

/// The values as stored settings: ("optimize/<name>", text) per option ("optimize/knots" for
/// knots_per_interval: the older key held a default nobody chose, see settings_key).
std::vector<std::pair<std::string, std::string>> settings_entries(const OptimizeSettings& settings);
/// Stored settings back (`stored` gives a key's text, or none). A value that no longer reads
/// (another version's range, a hand edit) keeps the default. Keys of earlier versions
/// ("optimize/strict", "optimize/timing", "optimize/max_joint_turn_deg") still read;
/// "optimize/knots_per_interval" (always 1 before the automatic resolution) does not.
OptimizeSettings settings_from_entries(
    const std::function<std::optional<std::string>(const std::string& key)>& stored);

struct ResultRow {
  std::string quantity;
  std::string before;
  std::string after;
};

/// Keyframes, knot spans per interval (asked: K or auto; used: K, or each interval's),
/// variables, constraints, objective and average root
/// force before/after, iterations (and restarts), seconds, status, RMS/peak force and moment,
/// keyframe times and errors.
std::vector<ResultRow> result_table(const OptimizationResult& result,
                                    const OptimizeOptions& options);

}  // namespace saltus::gui
