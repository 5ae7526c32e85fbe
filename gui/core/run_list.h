#pragma once
/// @file
/// Every optimisation run of the open motion, kept: the result list. Which run the views show by
/// default follows one rule, so that no run can hide a better one: the solved run with the
/// smallest average root force; without a solved run, the finished run that improved most on
/// the interpolation; a cancelled, failed or worse run is listed but never shown in place of a
/// solved one unless the user picks it.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/optimize_settings.h"

namespace saltus::gui {

struct RunRecord {
  int number = 0;  ///< 1, 2, ... in the order the runs were started, for "run 2"
  OptimizeSettings settings;
  OptimizeOptions options;
  /// Null when optimize_motion threw (then `error` says why).
  std::shared_ptr<const OptimizationResult> result;
  std::string error;
  bool saved = false;  ///< written to a result folder since it finished
};

/// A status word of SolveReport for users: "solved", "stopped at the iteration limit",
/// "cancelled", ... (unknown words are returned as they are).
std::string status_text(const std::string& status);

class RunList {
 public:
  /// Adds a finished run (its number is the next free one); returns its index.
  int add(RunRecord run);
  const std::vector<RunRecord>& runs() const { return runs_; }
  const RunRecord& at(int index) const { return runs_.at(static_cast<std::size_t>(index)); }
  int size() const { return static_cast<int>(runs_.size()); }
  bool empty() const { return runs_.empty(); }
  /// The number the next run gets.
  int next_number() const { return next_number_; }
  void clear();

  /// The run to show by default (see the file comment), nullopt when none is worth showing.
  std::optional<int> preferred() const;
  /// Whether a run can be shown at all (it has a result).
  bool showable(int index) const;

  /// Runs that finished with a result and were not saved since.
  int unsaved() const;
  void mark_saved(int index);

  /// One line for the list: "Run 2 · solved · 118 → 11.2 N · relaxed, K = 1, 101 samples".
  std::string label(int index) const;

 private:
  std::vector<RunRecord> runs_;
  int next_number_ = 1;
};

/// "relaxed, times free, K = 1, 101 samples, joint turn ≤ 180°": the settings of a run in a line
/// (also in exported figure titles).
std::string settings_summary(const OptimizeSettings& settings);

}  // namespace saltus::gui
