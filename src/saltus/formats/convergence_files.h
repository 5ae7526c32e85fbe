#pragma once
/// @file
/// The convergence study's files: DIR/{result.json, convergence.csv, convergence.md} (with
/// study.json and cases/, study_folder.h). Running the study: use_cases/convergence_run.h.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

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

/// DIR/{result.json, convergence.csv, convergence.md} from the outcomes in case order and the
/// study's definition (convergence_definition). Returns result.json.
nlohmann::json write_convergence_files(const std::string& dir,
                                       const std::vector<StudyOutcome>& outcomes,
                                       const nlohmann::json& definition);

}  // namespace saltus
