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
    finished_solves_.push_back(reports_.back().stage_iteration);
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

double RunProgress::mean_solve_iterations() const {
  if (finished_solves_.empty()) return std::max(1, last().stage_iteration);
  double sum = 0.0;
  for (int n : finished_solves_)
    sum += n;
  return sum / static_cast<double>(finished_solves_.size());
}

std::optional<TimeLeft> RunProgress::time_left() const {
  if (reports_.empty() || last().iteration < 1) return std::nullopt;
  const ProgressInfo& now = last();
  const std::optional<double> trend = current_solve_left();
  const double typical = mean_solve_iterations();
  double current = 0.0;
  if (trend) {
    current = *trend;
  } else if (!finished_solves_.empty()) {
    current = std::max(0.0, typical - now.stage_iteration);
  } else {
    return std::nullopt;  // the first solve, not converging yet: nothing to go by
  }
  // The solves that may follow.
  int most_solves = 0;
  const SolveStage& stage = now.stage;
  if (stage.kind == SolveStage::Kind::kLevel) {
    most_solves = stage.max_steps - stage.step + (joints_follow_ ? 2 : 0);
  } else if (stage.kind == SolveStage::Kind::kJoints) {
    most_solves = stage.step < stage.max_steps ? 1 : 0;
  }
  const double seconds_per_iteration = now.elapsed_seconds / std::max(1, now.iteration);
  TimeLeft left;
  left.least = current * seconds_per_iteration;
  left.most = (current + most_solves * typical) * seconds_per_iteration;
  return left;
}

std::string RunProgress::time_left_line() const {
  const std::optional<TimeLeft> left = time_left();
  if (!left) return "time left: estimating…";
  const ProgressInfo& now = last();
  const std::string pace = format_number(" at this run's pace (%.2g s an iteration)",
                                         now.elapsed_seconds / std::max(1, now.iteration));
  const std::string least = seconds_words(left->least), most = seconds_words(left->most);
  if (least == most) return "about " + least + " s left" + pace;
  return "about " + least + "–" + most + " s left" + pace;
}

std::string RunProgress::objective_line() const {
  return reports_.empty() ? "" : objective_meaning_words(last().stage);
}

}  // namespace saltus::gui
