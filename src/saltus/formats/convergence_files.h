#pragma once
/// @file
/// The convergence study's files: DIR/{result.json, convergence.csv, convergence.md} (with
/// study.json and cases/, formats/study_folder.h), and the study as a StudyJob for the runner.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/formats/output_folder.h"
#include "saltus/formats/study_folder.h"
#include "saltus/studies/convergence_study.h"

namespace saltus {

/// The study as Markdown: success rate, iterations, time and residual per formulation; success
/// rate per formulation against motion, mass error and timing error.
std::string convergence_markdown(const std::vector<StudyOutcome>& outcomes);

/// CSV, one row per case (header first).
std::string convergence_csv(const std::vector<StudyOutcome>& outcomes);

/// What decides the study's results: the motions (label and digest), the design and every
/// optimiser setting.
nlohmann::json convergence_definition(const std::vector<LabelledMotion>& motions,
                                      const ConvergenceStudyOptions& options);

/// The study for formats/study_folder.h's runner: one case per convergence_study_cases entry.
StudyJob convergence_study_job(const std::vector<LabelledMotion>& motions,
                               const ConvergenceStudyOptions& options);

/// The case record of one outcome; `failure` says why its process did not finish ("" if it did).
CaseRecord convergence_case_record(int index, const StudyOutcome& outcome,
                                   const std::string& failure);

/// DIR/{result.json, convergence.csv, convergence.md} from the outcomes in case order and the
/// study's definition (convergence_definition). Returns result.json.
nlohmann::json write_convergence_files(const std::string& dir,
                                       const std::vector<StudyOutcome>& outcomes,
                                       const nlohmann::json& definition);

/// A whole convergence study's outputs from its records, in case order.
nlohmann::json write_convergence_study_outputs(const OutputFolder& folder,
                                               const nlohmann::json& definition,
                                               const std::vector<CaseRecord>& records);

}  // namespace saltus
