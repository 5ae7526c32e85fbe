#include "core/study_results.h"

#include "saltus/base/text_format.h"

namespace saltus::gui {

namespace {

/// Short headings for a 340-pixel panel, in the order of convergence_summary_headings.
const std::vector<std::string>& short_summary_headings() {
  static const std::vector<std::string> headings{"Model",    "Cases",         "Solved",   "Iter.",
                                                 "Time (s)", "|F| after (N)", "Worst (N)"};
  return headings;
}

bool case_finished(const StudyOutcome& o) {
  return o.status != "crashed" && o.status != "timed_out";
}

}  // namespace

TextTable study_summary_table(const ConvergenceStudyFolder& folder) {
  TextTable table;
  table.headings = short_summary_headings();
  table.tooltips = convergence_summary_headings();
  for (const ConvergenceSummaryRow& row : folder.summary)
    table.rows.push_back(convergence_summary_cells(row));
  return table;
}

TextTable study_case_table(const ConvergenceStudyFolder& folder) {
  TextTable table;
  table.headings = {"Case", "Status", "Iter.", "Time (s)", "|F| after (N)"};
  table.tooltips = {"model, mass-parameter error and keyframe-timing error",
                    "how the optimisation ended (solved, max_iterations, stopped_infeasible, ...; "
                    "crashed or timed_out when its process did not finish)",
                    "optimiser iterations", "wall time of the case",
                    "average root force after optimisation"};
  for (const StudyOutcome& o : folder.outcomes) {
    std::string label = study_case_label(o.study_case);
    const std::string motion = o.study_case.motion + " ";
    if (label.rfind(motion, 0) == 0) label = label.substr(motion.size());
    const bool done = case_finished(o);
    table.rows.push_back({label, o.status, done ? std::to_string(o.iterations) : "–",
                          format_number("%.1f", o.seconds),
                          done ? format_number("%.3g", o.avg_force_after) : "–"});
  }
  return table;
}

ChartSpec study_solved_chart(const ConvergenceStudyFolder& folder) {
  ChartSpec chart;
  chart.title = "Cases solved";
  chart.x_title = "model";
  chart.y_title = "solved (%)";
  chart.legend = false;
  LineSpec bars;
  bars.label = "solved";
  bars.kind = LineKind::kBars;
  bars.colour = {0.20, 0.55, 0.30};
  for (std::size_t i = 0; i < folder.summary.size(); ++i) {
    const ConvergenceSummaryRow& row = folder.summary[i];
    bars.x.push_back(static_cast<double>(i));
    bars.y.push_back(row.cases > 0 ? 100.0 * row.solved / row.cases : 0.0);
    chart.x_labels.push_back(row.model);
  }
  chart.lines = {bars};
  return chart;
}

std::string study_folder_line(const ConvergenceStudyFolder& folder) {
  const std::string recorded = std::to_string(folder.outcomes.size());
  const std::string cases = std::to_string(folder.cases);
  if (!folder.complete())
    return recorded + " of " + cases + " cases finished before the study was stopped";
  return recorded + " of " + cases + " cases, " + std::to_string(folder.unfinished) +
         " did not finish";
}

}  // namespace saltus::gui
