#pragma once
/// @file
/// What the Optimise panel says while a run goes: its stage in the library's words
/// (solve_stage_words: the levels, the joints' tries), the iteration and the time so far, the
/// time left estimated from the run's own pace, and what the objective means
/// (objective_meaning_words), so that a jump between stages does not read as a failure.
///
/// The time left is a range, from what this run has done so far:
///  - the current solve's iterations left, from how fast the objective's relative change falls
///    towards the solve's acceptable exit (SolverOptions::objective_change_tolerance, held for
///    acceptable_iterations): a Gauss–Newton solve converges linearly, so that change falls
///    about geometrically; before it does, a solve is taken to last as long as those before it;
///  - the solves that may follow: none more at the least (the levels stop once the root force is
///    met; one joints' try is kept), and every level left plus two joints' tries at the most;
///    each as long as this run's solves so far, in iterations;
///  - iterations in seconds at this run's own pace (its seconds per iteration so far).

#include <optional>
#include <string>
#include <vector>

#include "saltus/optim/solve_policy.h"

namespace saltus::gui {

/// The time left of a run, s.
struct TimeLeft {
  double least = 0.0;
  double most = 0.0;
};

class RunProgress {
 public:
  /// `joints_follow`: the run ends with least joint effort's tries (a joint-load weight > 0 on
  /// the relaxed model), which follow the levels.
  explicit RunProgress(bool joints_follow = true) : joints_follow_(joints_follow) {}

  /// One iteration's report, in the order they come.
  void add(const ProgressInfo& info);
  bool started() const { return !reports_.empty(); }
  const ProgressInfo& last() const { return reports_.back(); }

  /// "Level 2 of at most 3: the least root force on knots refined where it lives".
  std::string stage_line() const;
  /// "iteration 57 · 9.8 s · objective 3.21e+01 · constraint violation 2.0e-05".
  std::string count_line() const;
  /// The estimate (above), none until the current solve has reported a few iterations.
  std::optional<TimeLeft> time_left() const;
  /// "about 5–15 s left at this run's pace (0.18 s an iteration)", or "time left: estimating…".
  std::string time_left_line() const;
  /// objective_meaning_words of the stage.
  std::string objective_line() const;

 private:
  /// Iterations the current solve still needs, none when its objective does not yet converge.
  std::optional<double> current_solve_left() const;
  double mean_solve_iterations() const;

  bool joints_follow_;
  std::vector<ProgressInfo> reports_;
  /// Iteration counts of the solves finished so far (a solve ends when the next starts).
  std::vector<int> finished_solves_;
  /// The current solve's reports from its first.
  std::size_t solve_start_ = 0;
};

}  // namespace saltus::gui
