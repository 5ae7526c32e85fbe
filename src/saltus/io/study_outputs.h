#pragma once
/// @file
/// Output folders of `saltus study convergence`, `saltus study mass` and `saltus paper` (the
/// reproduction report), written all or nothing like every other result (OutputFolder).

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/analysis/studies.h"

namespace saltus {

/// DIR/{result.json, convergence.csv, convergence.md}. Returns result.json.
nlohmann::json write_convergence_outputs(const std::string& out_dir,
                                         const std::vector<StudyOutcome>& outcomes,
                                         const ConvergenceStudyOptions& options);

/// DIR/{result.json, mass.csv, mass.md, model.json (given), model_scaled.json}.
nlohmann::json write_mass_outputs(const std::string& out_dir, const MotionFile& file,
                                  const MassStudyResult& study, const MassStudyOptions& options);

/// A row of the paper's Table 1 (Wei, Xia & Wang 2008): keyframes, problem size, objective and
/// average root force before and after their optimisation.
struct PaperTableRow {
  const char* label;  ///< "M1" ... "M7"
  int keyframes, variables, constraints;
  double objective_before, objective_after;
  double force_before, force_after;  ///< N
};
extern const PaperTableRow kPaperTable1[7];

/// The paper's row for a skill label ("M3"), nullptr for any other motion.
const PaperTableRow* paper_table1(const std::string& skill);

struct PaperReportOptions {
  /// Folder holding M1-…M7-….motion.json and dive-….motion.json (examples/motions).
  std::string motions_dir;
  /// Reduced settings (the CTest "paper" run): no K = 3 runs, a small convergence study.
  bool quick = false;
  OptimizeOptions optimize;  ///< paper-resolution settings for every run (K is set per run)
  std::function<void(const std::string&)> log;  ///< one line per step, may be empty
};

/// Runs the paper's experiments and writes DIR/report.md with everything side by side with the
/// paper: Table 1, the optimised M1-M7 (DIR/M1 ... DIR/M7, `saltus optimize` folders), the dive
/// (DIR/dive), the mass study (DIR/mass) and the convergence study (DIR/convergence). Figures
/// are referenced from DIR/figures, which the desktop app's --export-figures fills.
nlohmann::json write_paper_report(const std::string& out_dir, const PaperReportOptions& options);

}  // namespace saltus
