#pragma once
/// @file
/// What the Study panel shows of a convergence study's folder once it has ended (finished, or
/// stopped with its finished cases in DIR.partial): the library's summary per formulation
/// (convergence.md's first table, cell for cell), one row per recorded case, a chart of the
/// share of cases solved per formulation and a line saying how complete the folder is. The
/// numbers are the library's (read_convergence_study_folder); this file only picks, labels and
/// formats them.

#include <string>
#include <vector>

#include "core/chart_spec.h"
#include "saltus/formats/convergence_files.h"

namespace saltus::gui {

/// A table of text: column headings, each heading's tooltip, rows of cells.
struct TextTable {
  std::vector<std::string> headings;
  std::vector<std::string> tooltips;
  std::vector<std::vector<std::string>> rows;
};

/// convergence.md's first table: short headings (its own as tooltips), its cells as it writes
/// them (convergence_summary_cells).
TextTable study_summary_table(const ConvergenceStudyFolder& folder);

/// One row per recorded case in case order: the case in words (without the motion, which is
/// the same for every case of a study of one motion), its status, iterations, seconds and
/// average root force after optimisation (N, three significant digits; "–" for a case whose
/// process did not finish).
TextTable study_case_table(const ConvergenceStudyFolder& folder);

/// Bars: the percentage of cases solved per formulation, labelled with the formulation.
ChartSpec study_solved_chart(const ConvergenceStudyFolder& folder);

/// "4 of 4 cases, 0 did not finish" or, for DIR.partial, "2 of 6 cases finished before the
/// study was stopped".
std::string study_folder_line(const ConvergenceStudyFolder& folder);

}  // namespace saltus::gui
