#pragma once
/// @file
/// The convergence study (studies/convergence_study.h) as a job for the study runner: one case
/// per convergence_study_cases entry, each recorded as it finishes, and the study's files
/// (formats/convergence_files.h) written from the records.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/formats/output_folder.h"
#include "saltus/formats/study_case_file.h"
#include "saltus/studies/convergence_study.h"
#include "saltus/use_cases/study_runner.h"

namespace saltus {

/// study.json's "study" for a convergence study.
inline constexpr const char* kConvergenceStudy = "convergence";

/// The study for the runner (study_runner.h). InputError naming the motion's file when a
/// mass segment other than "all" is not a segment of its model.
StudyJob convergence_study_job(const std::vector<LabelledMotion>& motions,
                               const ConvergenceStudyOptions& options);

/// The case record of one outcome; `failure` says why its process did not finish ("" if it did).
CaseRecord convergence_case_record(int index, const StudyOutcome& outcome,
                                   const std::string& failure);

/// A whole convergence study's outputs from its records, in case order (its StudyKind).
nlohmann::json write_convergence_study_outputs(const OutputFolder& folder,
                                               const nlohmann::json& definition,
                                               const std::vector<CaseRecord>& records);

}  // namespace saltus
