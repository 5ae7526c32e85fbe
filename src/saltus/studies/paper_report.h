#pragma once
/// @file
/// The runs behind `saltus paper`, as a list of independent cases: every skill at the paper's
/// resolution (and at K = 3 unless quick), the dives, the mass study on M7 and the convergence
/// study. Computation only; the cases are run, kept and assembled into the report by
/// formats/paper_report_files.h.

#include <optional>
#include <string>
#include <vector>

#include "saltus/studies/convergence_study.h"
#include "saltus/studies/mass_study.h"
#include "saltus/studies/run_summary.h"

namespace saltus {

struct PaperReportOptions {
  /// Folder holding M1-…M7-….motion.json and dive-….motion.json (examples/motions).
  std::string motions_dir;
  /// Reduced settings (the CTest "paper" run): no K = 3 runs, a small convergence study.
  bool quick = false;
  OptimizeOptions optimize;  ///< paper-resolution settings for every run (K is set per run)
  /// The convergence study's early stop of strict runs (ConvergenceStudyOptions).
  std::vector<FeasibilityCheckpoint> strict_checkpoints = kStrictStudyCheckpoints;
};

enum class PaperCaseKind {
  kSkill,         ///< a skill at the paper's resolution (K = 1), written to DIR/<label>
  kRefinedSkill,  ///< the same skill at K = 3 (its figures go into Table 1 only)
  kDive,          ///< a dive at K = 1, written to DIR/<label>
  kMass,          ///< the mass study on M7, written to DIR/mass
  kConvergence,   ///< one case of the convergence study
};

struct PaperCase {
  PaperCaseKind kind = PaperCaseKind::kSkill;
  std::string motion;     ///< LabelledMotion::label
  StudyCase convergence;  ///< kConvergence only
};

/// Every case of the report and the settings of its studies.
struct PaperPlan {
  std::vector<PaperCase> cases;  ///< skills (each followed by its K = 3 run), dives, mass, study
  ConvergenceStudyOptions convergence;
  std::vector<LabelledMotion> convergence_motions;  ///< all skills, or the first and last if quick
  MassStudyOptions mass;
};

/// The report's cases for these skills and dives.
PaperPlan paper_report_plan(const std::vector<LabelledMotion>& skills,
                            const std::vector<LabelledMotion>& dives,
                            const PaperReportOptions& options);

/// The options of a skill or dive run (K = 1, or K = 3 for kRefinedSkill).
OptimizeOptions paper_run_options(const PaperCase& paper_case, const PaperReportOptions& options);

/// "M3, K = 3", "mass study on M7", "M3 strict ε=50 mass -20 % (all) timing ±0.05 s".
std::string paper_case_label(const PaperCase& paper_case);

/// The report assembled from its cases' results.
struct PaperSkillRow {
  std::string label;
  RunSummary paper_resolution;        ///< K = 1
  std::optional<RunSummary> refined;  ///< K = 3, unless quick
};

struct PaperDiveRow {
  std::string label;
  RunSummary run;
};

struct PaperReport {
  std::vector<PaperSkillRow> skills;
  std::vector<PaperDiveRow> dives;
  bool has_mass = false;      ///< the folder had M7
  std::string mass_markdown;  ///< formats' mass-study table, or why it is missing
  std::vector<StudyOutcome> convergence;
};

}  // namespace saltus
