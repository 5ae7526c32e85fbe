#pragma once
/// @file
/// `saltus paper`: the reproduction report's folder. The report is a study
/// (formats/study_folder.h) whose cases are the runs of studies/paper_report.h, each in a process
/// of its own; from their records it writes DIR/report.md with everything side by side with the
/// paper: Table 1, the optimised M1-M7 (DIR/M1 ... DIR/M7, `saltus optimize` folders), the dive
/// (DIR/dive…), the mass study (DIR/mass) and the convergence study (DIR/convergence), all or
/// nothing. Figures are referenced from DIR/figures, which the desktop app's --export-figures
/// fills.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/formats/output_folder.h"
#include "saltus/formats/study_folder.h"
#include "saltus/studies/paper_report.h"

namespace saltus {

/// The motions of a paper folder: M1-…M7-….motion.json (Table 1's skills, in label order) and
/// dive-….motion.json. Throws InputError when the folder does not exist or holds no skill.
struct PaperMotions {
  std::vector<LabelledMotion> skills, dives;
};
PaperMotions load_paper_motions(const std::string& motions_dir);

/// The report as a study for formats/study_folder.h's runner (loads options.motions_dir).
StudyJob paper_report_job(const PaperReportOptions& options);

/// DIR/{report.md, result.json, convergence/} of a whole report from its records (in case
/// order); the cases' own folders (M1/, mass/, ...) are already in place. Returns result.json.
nlohmann::json write_paper_report_outputs(const OutputFolder& folder,
                                          const nlohmann::json& definition,
                                          const std::vector<CaseRecord>& records);

}  // namespace saltus
