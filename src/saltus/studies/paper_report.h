#pragma once
/// @file
/// The runs behind `saltus paper`: every skill at the paper's resolution (and at K = 3 unless
/// quick), the dives, the mass study on M7 and the convergence study. Computation only; the
/// report and its folders are written by formats/paper_report_files.h.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "saltus/studies/convergence_study.h"
#include "saltus/studies/mass_study.h"

namespace saltus {

struct PaperReportOptions {
  /// Folder holding M1-…M7-….motion.json and dive-….motion.json (examples/motions).
  std::string motions_dir;
  /// Reduced settings (the CTest "paper" run): no K = 3 runs, a small convergence study.
  bool quick = false;
  OptimizeOptions optimize;  ///< paper-resolution settings for every run (K is set per run)
  std::function<void(const std::string&)> log;  ///< one line per step, may be empty
};

/// One skill of Table 1: the run at the paper's resolution and, unless quick, at K = 3.
struct PaperSkillRun {
  LabelledMotion motion;
  OptimizeOptions options;                    ///< of the K = 1 run
  OptimizationResult paper_resolution;        ///< K = 1
  std::optional<OptimizationResult> refined;  ///< K = 3
};

struct PaperDiveRun {
  LabelledMotion motion;
  OptimizeOptions options;
  OptimizationResult result;
};

struct PaperReport {
  std::vector<PaperSkillRun> skills;
  std::vector<PaperDiveRun> dives;
  std::optional<MassStudyResult> mass;  ///< on M7, when the folder has it
  MassStudyOptions mass_options;
  ConvergenceStudyOptions convergence_options;
  std::vector<StudyOutcome> convergence;
};

/// Runs everything, skills in the given order; `options.log` gets a line after each step.
PaperReport run_paper_report(const std::vector<LabelledMotion>& skills,
                             const std::vector<LabelledMotion>& dives,
                             const PaperReportOptions& options);

}  // namespace saltus
