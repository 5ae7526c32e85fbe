#pragma once
/// @file
/// `saltus paper` as a study: its cases are the runs of studies/paper_report.h, each in a
/// process of its own (study_runner.h); from their records the report's files are written
/// (formats/paper_report_files.h), all or nothing.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/formats/output_folder.h"
#include "saltus/formats/study_case_file.h"
#include "saltus/studies/paper_report.h"
#include "saltus/use_cases/study_runner.h"

namespace saltus {

/// study.json's "study" for the reproduction report.
inline constexpr const char* kPaperReportStudy = "paper";

/// The motions of a paper folder: M1-…M7-….motion.json (Table 1's skills, in label order) and
/// dive-….motion.json. Throws InputError when the folder does not exist or holds no skill.
struct PaperMotions {
  std::vector<LabelledMotion> skills, dives;
};
PaperMotions load_paper_motions(const std::string& motions_dir);

/// The report as a study for the runner (loads options.motions_dir).
StudyJob paper_report_job(const PaperReportOptions& options);

/// DIR/{report.md, result.json, convergence/} of a whole report from its records (in case
/// order); the cases' own folders (M1/, mass/, ...) are already in place (its StudyKind).
nlohmann::json write_paper_report_outputs(const OutputFolder& folder,
                                          const nlohmann::json& definition,
                                          const std::vector<CaseRecord>& records);

}  // namespace saltus
