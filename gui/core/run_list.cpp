#include "core/run_list.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <variant>

#include "saltus/base/text_format.h"

namespace saltus::gui {

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

int RunList::add(RunRecord run, const BodyModel& model) {
  run.number = next_number_++;
  if (run.result) run.standing = result_standing(*run.result, model);
  runs_.push_back(std::move(run));
  return size() - 1;
}

void RunList::clear() {
  runs_.clear();
}

bool RunList::showable(int index) const {
  return index >= 0 && index < size() && at(index).result != nullptr;
}

std::vector<int> RunList::ranking() const {
  std::vector<int> order(runs_.size());
  for (int i = 0; i < size(); ++i)
    order[static_cast<std::size_t>(i)] = i;
  std::stable_sort(order.begin(), order.end(), [this](int a, int b) {
    if (showable(a) != showable(b)) return showable(a);
    return showable(a) && ranks_above(at(a).standing, at(b).standing);
  });
  return order;
}

std::optional<int> RunList::preferred() const {
  const std::vector<int> order = ranking();
  if (order.empty() || !showable(order.front())) return std::nullopt;
  const RunRecord& best = at(order.front());
  if (best.standing.solved ||
      best.standing.avg_root_force < best.result->before.metrics.avg_root_force)
    return order.front();
  return std::nullopt;
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

std::string RunList::label(int index, bool with_settings) const {
  const RunRecord& run = at(index);
  std::string out =
      (preferred() == index ? "Best · Run " : "Run ") + std::to_string(run.number) + " · ";
  if (!run.result) return out + "failed: " + run.error;
  const OptimizationResult& r = *run.result;
  // The joints in the words of `saltus optimize` (joint_load_verdict_words).
  const JointLoadRise& rise = run.standing.largest_rise;
  const std::string joints = rise.joint.empty() ? "" : joint_load_verdict_words(rise);
  out += status_text(r.solve.status) + " after " + std::to_string(r.solve.iterations) +
         " iterations · " + format_number("%.3g", r.before.metrics.avg_root_force) + " → " +
         format_number("%.3g", r.after.metrics.avg_root_force) + " N";
  if (!joints.empty()) out += " · " + joints;
  // And the joints the optimised motion asks more of than the athlete's strength (the dense
  // check's largest shares; the run's summary names them as `saltus optimize` does).
  int beyond = 0;
  for (std::size_t k = 1; k < r.after.check.strength_peaks.size(); ++k)
    beyond += r.after.check.strength_peaks[k].coordinate >= 0 &&
              r.after.check.strength_peaks[k].share > 1.0;
  if (beyond > 0)
    out += " · " + std::to_string(beyond) + (beyond == 1 ? " joint" : " joints") +
           " beyond the athlete's strength";
  if (with_settings) out += " · " + settings_summary(run.settings);
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
