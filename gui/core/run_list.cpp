#include "core/run_list.h"

#include <cstdio>
#include <map>
#include <variant>

#include "saltus/base/text_format.h"

namespace saltus::gui {

namespace {

double after_force(const RunRecord& run) {
  return run.result->after.metrics.avg_root_force;
}

}  // namespace

std::string status_text(const std::string& status) {
  static const std::map<std::string, std::string> kWords = {
      {"solved", "solved"},
      {"max_iterations", "stopped at the iteration limit"},
      {"infeasible", "keyframes cannot all be met"},
      {"cancelled", "cancelled"},
      {"diverging", "diverged"},
      {"restoration_failed", "failed (restoration)"},
      {"tiny_step", "stopped (no further progress)"},
      {"stalled", "stopped (no further progress)"},
      {"error", "failed"},
  };
  const auto it = kWords.find(status);
  return it == kWords.end() ? status : it->second;
}

int RunList::add(RunRecord run) {
  run.number = next_number_++;
  runs_.push_back(std::move(run));
  return size() - 1;
}

void RunList::clear() {
  runs_.clear();
}

bool RunList::showable(int index) const {
  return index >= 0 && index < size() && at(index).result != nullptr;
}

std::optional<int> RunList::preferred() const {
  std::optional<int> best_solved, best_improved;
  for (int i = 0; i < size(); ++i) {
    const RunRecord& run = at(i);
    if (!run.result) continue;
    const double after = after_force(run);
    if (run.result->solve.solved) {
      if (!best_solved || after < after_force(at(*best_solved))) best_solved = i;
    } else if (after < run.result->before.metrics.avg_root_force) {
      if (!best_improved || after < after_force(at(*best_improved))) best_improved = i;
    }
  }
  return best_solved ? best_solved : best_improved;
}

int RunList::unsaved() const {
  int count = 0;
  for (const RunRecord& run : runs_)
    count += run.result && !run.saved;
  return count;
}

void RunList::mark_saved(int index) {
  if (index >= 0 && index < size()) runs_[static_cast<std::size_t>(index)].saved = true;
}

std::string RunList::label(int index) const {
  const RunRecord& run = at(index);
  std::string out = "Run " + std::to_string(run.number) + " · ";
  if (!run.result) return out + "failed: " + run.error;
  const OptimizationResult& r = *run.result;
  out += status_text(r.solve.status) + " after " + std::to_string(r.solve.iterations) +
         " iterations · " + format_number("%.3g", r.before.metrics.avg_root_force) + " → " +
         format_number("%.3g", r.after.metrics.avg_root_force) + " N · " +
         settings_summary(run.settings);
  return out;
}

std::string settings_summary(const OptimizeSettings& s) {
  const bool strict = std::get<std::string>(s.get("formulation")) == "strict";
  std::string out = strict ? "strict, ε = " + format_number("%g", s.real("epsilon")) : "relaxed";
  out += s.on("optimize_timing") ? ", times free" : ", times fixed";
  const OptionValue knots = s.get("knots_per_interval");
  out += std::holds_alternative<std::string>(knots)
             ? ", knots " + std::get<std::string>(knots)
             : ", K = " + std::to_string(std::get<int>(knots));
  out += ", " + std::to_string(s.integer("samples")) + " samples";
  if (s.real("max_joint_turn") > 0)
    out += ", joint turn ≤ " + format_number("%g", s.real("max_joint_turn")) + "°";
  return out;
}

}  // namespace saltus::gui
