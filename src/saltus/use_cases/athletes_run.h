#pragma once
/// @file
/// The athletes study (`saltus study athletes`, studies/athlete_study.h) as a job for the study
/// runner: one case per athlete, the motion's own model first, each recorded as it finishes, and
/// the study's files (formats/athletes_files.h) written from the records.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/formats/output_folder.h"
#include "saltus/formats/study_case_file.h"
#include "saltus/optim/optimize.h"
#include "saltus/use_cases/study_runner.h"

namespace saltus {

/// study.json's "study" for an athletes study.
inline constexpr const char* kAthletesStudy = "athletes";

/// The study for the runner: the motion (or capture) at `motion_path` on its own model, then on
/// each of `models` (model files or bundled names, load_motion_for_athlete with `takeoff`,
/// "same-spin" or "keep-momentum"), each optimised with `options`. Every model is read before
/// anything runs: a bad one is InputError naming it; two athletes of one name are InputError
/// naming --models.
StudyJob athletes_study_job(const std::string& motion_path, const std::vector<std::string>& models,
                            const std::string& takeoff, const OptimizeOptions& options);

/// A whole athletes study's outputs from its records, in case order (its StudyKind).
nlohmann::json write_athletes_study_outputs(const OutputFolder& folder,
                                            const nlohmann::json& definition,
                                            const std::vector<CaseRecord>& records);

}  // namespace saltus
