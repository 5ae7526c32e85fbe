#pragma once
/// @file
/// Every optimisation run of the open motion, kept: the result list. Runs rank as the optimiser
/// ranks its own solves (optim/result_standing.h): solved before not (a cancelled run is not
/// solved), then the joints within the joint policy, then the least average root force. The run
/// the views show by default is the best of that ranking, if it solved or improved on the
/// interpolation; a cancelled, failed or worse run is listed but never shown in place of a
/// better one unless the user picks it.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/optimize_settings.h"
#include "saltus/optim/result_standing.h"

namespace saltus::gui {

struct RunRecord {
  int number = 0;  ///< 1, 2, ... in the order the runs were started, for "run 2"
  OptimizeSettings settings;
  OptimizeOptions options;
  /// Null when optimize_motion threw (then `error` says why).
  std::shared_ptr<const OptimizationResult> result;
  std::string error;
  ResultStanding standing;  ///< of `result` on the model it ran on (RunList::add)
  bool saved = false;       ///< written to a result folder since it finished
};

/// A status word of SolveReport for users: "solved", "stopped at the iteration limit",
/// "cancelled", ... (unknown words are returned as they are).
std::string status_text(const std::string& status);

class RunList {
 public:
  /// Adds a finished run that ran on `model` (its standing is worked out on it; its number is
  /// the next free one); returns its index.
  int add(RunRecord run, const BodyModel& model);
  const std::vector<RunRecord>& runs() const { return runs_; }
  const RunRecord& at(int index) const { return runs_.at(static_cast<std::size_t>(index)); }
  int size() const { return static_cast<int>(runs_.size()); }
  bool empty() const { return runs_.empty(); }
  /// The number the next run gets.
  int next_number() const { return next_number_; }
  void clear();

  /// Every run's index, best first (ranks_above); runs without a result (failed) last, in the
  /// order they ran.
  std::vector<int> ranking() const;
  /// The run to show by default: the best of the ranking if it solved or improved on the
  /// interpolation, else nullopt.
  std::optional<int> preferred() const;
  /// Whether a run can be shown at all (it has a result).
  bool showable(int index) const;

  /// Runs that finished with a result and were not saved since.
  int unsaved() const;
  void mark_saved(int index);

  /// One line for the list: "Best · Run 2 · solved after 40 iterations · 118 → 11.2 N · every
  /// joint within 1.27x of its peak load before · 2 joints beyond the athlete's strength ·
  /// relaxed, K = 1, 101 samples" ("Best · " for preferred() only; the joints in
  /// joint_load_verdict_words, as `saltus optimize` says them; the strength part only when a
  /// joint of the optimised motion is beyond it).
  /// `with_settings` false leaves the settings out (the panel's list: they go to its tooltip).
  std::string label(int index, bool with_settings = true) const;

 private:
  std::vector<RunRecord> runs_;
  int next_number_ = 1;
};

/// "relaxed, times free, K = 1, 101 samples, joint turn ≤ 180°": the settings of a run in a line
/// (also in exported figure titles).
std::string settings_summary(const OptimizeSettings& settings);

}  // namespace saltus::gui
