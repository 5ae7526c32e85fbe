#include "core/run_progress.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "saltus/base/text_format.h"

namespace saltus::gui {

namespace {

/// The fewest reports of a solve from which its convergence is read.
constexpr std::size_t kReportsForTrend = 4;
/// The reports a trend is fitted on, at most (the latest).
constexpr std::size_t kTrendWindow = 8;

double relative_change(const ProgressInfo& now, const ProgressInfo& before) {
  return std::abs(now.objective - before.objective) / std::max(1.0, std::abs(now.objective));
}

std::string seconds_words(double s) {
  return s < 10.0 ? format_number("%.0f", std::max(1.0, std::round(s)))
                  : format_number("%.0f", 5.0 * std::round(s / 5.0));
}

}  // namespace

void RunProgress::add(const ProgressInfo& info) {
  // A new solve starts when the stage changes or the solve's own count starts again.
  if (!reports_.empty() && (info.stage != reports_.back().stage ||
                            info.stage_iteration < reports_.back().stage_iteration)) {
    const ProgressInfo& end = reports_.back();
    finished_.push_back(
        {end.stage.kind, end.stage_iteration, end.elapsed_seconds - solve_start_seconds_});
    solve_start_seconds_ = end.elapsed_seconds;
    solve_start_ = reports_.size();
  }
  reports_.push_back(info);
}

std::string RunProgress::stage_line() const {
  if (reports_.empty()) return "";
  std::string words = solve_stage_words(last().stage);
  if (!words.empty()) words[0] = static_cast<char>(std::toupper(words[0]));
  return words;
}

std::string RunProgress::count_line() const {
  if (reports_.empty()) return "";
  const ProgressInfo& p = last();
  return "iteration " + std::to_string(p.iteration) + " · " +
         format_number("%.1f s", p.elapsed_seconds) + " · " +
         format_number("objective %.3g", p.objective) + " · " +
         format_number("constraint violation %.1e", p.constraint_violation);
}

std::optional<double> RunProgress::current_solve_left() const {
  const std::size_t count = reports_.size() - solve_start_;
  if (count < kReportsForTrend + 1) return std::nullopt;
  const ProgressInfo& now = last();
  const double tolerance = now.objective_change_tolerance;
  if (!(tolerance > 0.0)) return std::nullopt;
  // Least squares of log(relative change) over the latest reports.
  const std::size_t first = reports_.size() - std::min(kTrendWindow, count - 1);
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = first; i < reports_.size(); ++i) {
    const double change = std::max(relative_change(reports_[i], reports_[i - 1]), 1e-12);
    const double x = static_cast<double>(i), y = std::log(change);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  if (!(slope < 0.0)) return std::nullopt;  // not converging yet
  const double latest = (sy + slope * (static_cast<double>(reports_.size() - 1) * n - sx)) / n;
  const double to_go = std::max(0.0, (std::log(tolerance) - latest) / slope);
  return to_go + std::max(1, now.acceptable_iterations);
}

std::optional<RunProgress::SolveRecord> RunProgress::typical(SolveStage::Kind kind) const {
  double iterations = 0.0, seconds = 0.0;
  int count = 0;
  for (const SolveRecord& r : finished_)
    if (r.kind == kind) {
      iterations += r.iterations;
      seconds += r.seconds;
      ++count;
    }
  if (count == 0) return std::nullopt;
  return SolveRecord{kind, static_cast<int>(std::lround(iterations / count)), seconds / count};
}

std::optional<TimeLeft> RunProgress::time_left() const {
  if (reports_.empty() || last().iteration < 1) return std::nullopt;
  const ProgressInfo& now = last();
  const SolveStage& stage = now.stage;
  const int done = now.stage_iteration;
  const double seconds_in = now.elapsed_seconds - solve_start_seconds_;
  const std::optional<SolveRecord> same = typical(stage.kind);
  // This solve's pace: its own once it has a few iterations, else that of its kind so far.
  double pace = 0.0;
  if (done >= kReportsForTrend)
    pace = seconds_in / done;
  else if (same && same->iterations > 0)
    pace = same->seconds / same->iterations;
  else if (done > 0)
    pace = seconds_in / done;
  else
    return std::nullopt;
  // Its iterations left: from its objective's convergence at the least; at the most, as many
  // as a solve of its kind took in this run, or half as many again as it has taken.
  const std::optional<double> trend = current_solve_left();
  if (!trend && !same && done < kReportsForTrend) return std::nullopt;
  const double least_left = trend ? *trend : 0.0;
  const double most_left =
      std::max(least_left, same ? static_cast<double>(same->iterations - done) : 0.5 * done);
  // The levels so far (finished, and the current one while in the levels): their mean
  // iterations and pace.
  double level_iterations = 0.0, level_seconds = 0.0;
  int levels = 0;
  for (const SolveRecord& r : finished_)
    if (r.kind == SolveStage::Kind::kLevel) {
      level_iterations += r.iterations;
      level_seconds += r.seconds;
      ++levels;
    }
  const bool in_levels = stage.kind == SolveStage::Kind::kLevel;
  const double level_pace = (level_seconds + (in_levels ? seconds_in : 0.0)) /
                            std::max(1.0, level_iterations + (in_levels ? done : 0));
  const double mean_level_iterations = levels > 0 ? level_iterations / levels : done + most_left;
  // A joints' try: as long as this run's, or before one has finished, kJointTryIterations
  // times a level's iterations at its own pace (in the joints) or kJointIterationCost times the
  // levels' (before them).
  double joint_try = 0.0;
  if (const std::optional<SolveRecord> joints = typical(SolveStage::Kind::kJoints))
    joint_try = joints->seconds;
  else if (stage.kind == SolveStage::Kind::kJoints)
    joint_try = std::max(kJointTryIterations * mean_level_iterations, 1.0 * done) * pace;
  else
    joint_try = kJointTryIterations * mean_level_iterations * kJointIterationCost * level_pace;
  TimeLeft left;
  left.least = least_left * pace;
  left.most = most_left * pace;
  if (in_levels) {
    const double level = levels > 0 ? level_seconds / levels : seconds_in + most_left * pace;
    left.most += (stage.max_steps - stage.step) * level;
    if (joints_follow_) {
      left.least += joint_try;
      left.most += 2 * joint_try;
    }
  } else if (stage.kind == SolveStage::Kind::kJoints && stage.step < stage.max_steps) {
    left.most += joint_try;
  }
  return left;
}

std::string RunProgress::time_left_line() const {
  const std::optional<TimeLeft> left = time_left();
  if (!left) return "time left: estimating…";
  const ProgressInfo& now = last();
  const std::string pace =
      format_number(" (at %.2g s an iteration)", now.elapsed_seconds / std::max(1, now.iteration));
  const std::string least = seconds_words(left->least), most = seconds_words(left->most);
  if (least == most) return "about " + least + " s left" + pace;
  return "about " + least + "–" + most + " s left" + pace;
}

std::string RunProgress::objective_line() const {
  return reports_.empty() ? "" : objective_meaning_words(last().stage);
}

}  // namespace saltus::gui
