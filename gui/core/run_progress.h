#pragma once
/// @file
/// What the Optimise panel says while a run goes: its stage in the library's words
/// (solve_stage_words: the levels, the joints' tries), the iteration and the time so far, the
/// time left estimated from the run's own pace, and what the objective means
/// (objective_meaning_words), so that a jump between stages does not read as a failure.
///
/// The time left is a range, from what this run has done so far:
///  - the current solve's iterations left: at the least, from how fast the objective's relative
///    change falls towards the solve's acceptable exit (SolverOptions::objective_change_tolerance,
///    held for acceptable_iterations; a Gauss–Newton solve converges linearly, so that change
///    falls about geometrically); at the most, as many as a solve of its kind took in this run
///    (or half as many again as it has taken), at the solve's own pace;
///  - the solves that may follow: after a level, at the least one joints' try (one is kept), at
///    the most every level left and two tries; a level as long as this run's levels, a try as
///    long as this run's tries, or before one has finished, kJointTryIterations and
///    kJointIterationCost against this run's levels.
/// Measured on M7 (docs/app.md, "Optimises in the background").

#include <optional>
#include <string>
#include <vector>

#include "saltus/optim/solve_policy.h"

namespace saltus::gui {

/// A joints' try against the levels, before one has run in this run: its iterations per level
/// iteration, and the time of each per level iteration's (the joint-load term and the bounds add
/// their Jacobians and rows). From M7's runs: levels of 31, 21 and 12 iterations, tries of 42
/// and 27; a try's iteration 5-8 times a level's on average (docs/performance.md).
inline constexpr double kJointTryIterations = 1.5;
inline constexpr double kJointIterationCost = 5.0;

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
  int reports() const { return static_cast<int>(reports_.size()); }
  const ProgressInfo& last() const { return reports_.back(); }

  /// "Level 2 of at most 3: the least root force on knots refined where it lives".
  std::string stage_line() const;
  /// "iteration 57 · 9.8 s · objective 3.21e+01 · constraint violation 2.0e-05".
  std::string count_line() const;
  /// The estimate (above), none until the current solve has reported a few iterations.
  std::optional<TimeLeft> time_left() const;
  /// "about 5–15 s left (at 0.18 s an iteration)", or "time left: estimating…".
  std::string time_left_line() const;
  /// objective_meaning_words of the stage.
  std::string objective_line() const;

 private:
  /// A finished solve: its kind, iterations and seconds (to the next solve's first report).
  struct SolveRecord {
    SolveStage::Kind kind = SolveStage::Kind::kSolve;
    int iterations = 0;
    double seconds = 0.0;
  };
  /// Iterations the current solve still needs, none when its objective does not yet converge.
  std::optional<double> current_solve_left() const;
  /// The mean of this run's finished solves of `kind`, none before one has finished.
  std::optional<SolveRecord> typical(SolveStage::Kind kind) const;

  bool joints_follow_;
  std::vector<ProgressInfo> reports_;
  std::vector<SolveRecord> finished_;
  /// The current solve's first report, and the run's seconds when it began.
  std::size_t solve_start_ = 0;
  double solve_start_seconds_ = 0.0;
};

}  // namespace saltus::gui
