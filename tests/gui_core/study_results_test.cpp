// The Study panel's tables and chart (core/study_results.h): the summary is convergence.md's
// first table cell for cell, a case row carries its outcome (and no figures for a case whose
// process did not finish), the bars are the share of cases solved, and the folder line says
// whether the study finished or was stopped.

#include "core/study_results.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace saltus::gui {
namespace {

/// M1: relaxed solved twice, strict ε=50 once solved, once crashed; of `cases` cases.
ConvergenceStudyFolder a_stopped_or_finished_study(int cases = 4) {
  ConvergenceStudyFolder folder;
  folder.cases = cases;
  for (int i = 0; i < 4; ++i) {
    StudyOutcome o;
    o.study_case.motion = "M1";
    o.study_case.mass_segment = "all";
    o.study_case.timing_error_s = i % 2 ? 0.05 : 0.0;
    o.study_case.formulation = i < 2 ? Formulation::kRelaxed : Formulation::kStrict;
    o.study_case.epsilon = i < 2 ? 0.0 : 50.0;
    o.status = i == 3 ? "crashed" : "solved";
    o.solved = i != 3;
    o.iterations = 10 + 2 * i;
    o.seconds = 1.0 * (i + 1);
    o.avg_force_after = 0.01 * (i + 1);
    folder.outcomes.push_back(o);
  }
  folder.unfinished = 1;
  folder.summary = convergence_summary(folder.outcomes);
  return folder;
}

TEST(StudyResults, SummaryIsTheMarkdownTableCellForCell) {
  const ConvergenceStudyFolder folder = a_stopped_or_finished_study();
  const TextTable table = study_summary_table(folder);
  ASSERT_EQ(table.headings.size(), 7u);
  EXPECT_EQ(table.tooltips, convergence_summary_headings());
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0],
            (std::vector<std::string>{"relaxed", "2", "2 (100 %)", "11", "1.50", "0.015", "0.02"}));
  EXPECT_EQ(table.rows[1][0], "strict ε=50");
  EXPECT_EQ(table.rows[1][2], "1 (50 %)");
  // Every row is in convergence.md as written.
  const std::string md = convergence_markdown(folder.outcomes);
  for (const auto& row : table.rows) {
    std::string line = "|";
    for (const std::string& cell : row)
      line += " " + cell + " |";
    EXPECT_NE(md.find(line), std::string::npos) << line << "\n" << md;
  }
}

TEST(StudyResults, CaseRowsCarryEachOutcome) {
  const TextTable table = study_case_table(a_stopped_or_finished_study());
  ASSERT_EQ(table.rows.size(), 4u);
  ASSERT_EQ(table.headings.size(), table.tooltips.size());
  EXPECT_EQ(table.rows[1], (std::vector<std::string>{"relaxed, mass 0 %, timing ±0.05 s", "solved",
                                                     "12", "2.0", "0.02"}));
  // A crashed case has no iterations or force to show.
  EXPECT_EQ(table.rows[3], (std::vector<std::string>{"strict ε=50, mass 0 %, timing ±0.05 s",
                                                     "crashed", "–", "4.0", "–"}));
}

TEST(StudyResults, ChartBarsAreTheShareSolved) {
  const ChartSpec chart = study_solved_chart(a_stopped_or_finished_study());
  ASSERT_EQ(chart.lines.size(), 1u);
  EXPECT_EQ(chart.lines[0].kind, LineKind::kBars);
  EXPECT_EQ(chart.lines[0].y, (std::vector<double>{100.0, 50.0}));
  EXPECT_EQ(chart.x_labels, (std::vector<std::string>{"relaxed", "strict ε=50"}));
}

TEST(StudyResults, FolderLineSaysFinishedOrStopped) {
  EXPECT_EQ(study_folder_line(a_stopped_or_finished_study(4)), "4 of 4 cases, 1 did not finish");
  EXPECT_EQ(study_folder_line(a_stopped_or_finished_study(10)),
            "4 of 10 cases finished before the study was stopped");
}

}  // namespace
}  // namespace saltus::gui
