#pragma once
/// @file
/// The convergence study's files: DIR/{result.json, convergence.csv, convergence.md} (with
/// study.json and cases/, study_folder.h), and a study's folder read back from its case records
/// (the app's results view). Running the study: use_cases/convergence_run.h.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/formats/study_folder.h"
#include "saltus/studies/convergence_study.h"

namespace saltus {

/// One row of convergence.md's first table: the cases of one formulation.
struct ConvergenceSummaryRow {
  std::string model;  ///< formulation_label: "relaxed", "strict ε=500"
  int cases = 0;      ///< every case of it, unfinished ones included
  int solved = 0;
  /// Medians over its finished cases (NaN when none finished): iterations, seconds, average
  /// root force after optimisation (N).
  double median_iterations = 0.0;
  double median_seconds = 0.0;
  double median_force_after_N = 0.0;
  double worst_force_after_N = 0.0;  ///< largest over its solved cases; NaN when none solved
};

/// The summary per formulation, in order of first appearance: what convergence.md's first table
/// says, as numbers.
std::vector<ConvergenceSummaryRow> convergence_summary(const std::vector<StudyOutcome>& outcomes);
/// That table's headings ("model", "cases", "solved", ...) and a row's cells as it writes them
/// ("relaxed", "3", "3 (100 %)", "20", "2.00", "0.25", "0.5"; "–" for no worst).
std::vector<std::string> convergence_summary_headings();
std::vector<std::string> convergence_summary_cells(const ConvergenceSummaryRow& row);

/// The study as Markdown: success rate, iterations, time and residual per formulation; success
/// rate per formulation against motion, mass error and timing error.
std::string convergence_markdown(const std::vector<StudyOutcome>& outcomes);

/// CSV, one row per case (header first).
std::string convergence_csv(const std::vector<StudyOutcome>& outcomes);

/// What decides the study's results: the motions (label and digest), the design and every
/// optimiser setting.
nlohmann::json convergence_definition(const std::vector<LabelledMotion>& motions,
                                      const ConvergenceStudyOptions& options);

/// What a convergence study's folder holds (output_kind.h), also as a report's convergence/.
const FolderKind& convergence_folder_kind();

/// DIR/{result.json, convergence.csv, convergence.md} from the outcomes in case order and the
/// study's definition (convergence_definition). Returns result.json.
nlohmann::json write_convergence_files(const std::string& dir,
                                       const std::vector<StudyOutcome>& outcomes,
                                       const nlohmann::json& definition);

/// A convergence study's folder read back from study.json and its case records: a finished
/// study (DIR) or an interrupted one (DIR.partial: the cases finished so far).
struct ConvergenceStudyFolder {
  std::string path;
  int cases = 0;                               ///< the study's, recorded or not
  std::vector<StudyOutcome> outcomes;          ///< the recorded cases, in case order
  std::vector<ConvergenceSummaryRow> summary;  ///< convergence_summary(outcomes)
  int unfinished = 0;         ///< recorded cases whose process crashed or timed out
  std::string markdown_path;  ///< DIR/convergence.md; "" when there is none (DIR.partial)
  std::string csv_path;       ///< DIR/convergence.csv; "" likewise
  bool complete() const { return static_cast<int>(outcomes.size()) == cases; }
};

/// Throws InputError naming the folder or file when it is not a whole convergence study's
/// folder (no study.json, another study, a shard) or a record is malformed or of another kind.
ConvergenceStudyFolder read_convergence_study_folder(const std::string& dir);

}  // namespace saltus
