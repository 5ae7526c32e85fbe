#pragma once
/// @file
/// The athletes study's files: DIR/{result.json, athletes.csv, athletes.md} (with study.json and
/// cases/, study_folder.h), assembled from the case records alone. Running the study:
/// use_cases/athletes_run.h.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/formats/output_kind.h"
#include "saltus/formats/study_case_file.h"
#include "saltus/motion/motion.h"
#include "saltus/optim/optimize.h"

namespace saltus {

/// One athlete's model in the study's definition: its name and the digest of the motion on it.
struct AthleteEntry {
  std::string name;
  std::string digest;  ///< motion_digest of the motion on this athlete (model and take-off)
};

/// What an athletes study's folder holds (output_kind.h).
const FolderKind& athletes_folder_kind();

/// What decides the study's results: the motion (label and digest on its own model), the
/// take-off rule, the athletes (the motion's own model first) and every optimiser setting.
nlohmann::json athletes_definition(const std::string& motion_label, const MotionFile& own,
                                   const std::string& takeoff_rule,
                                   const std::vector<AthleteEntry>& athletes,
                                   const OptimizeOptions& options);

/// The table, one row per athlete in case order; a case whose process failed is a row saying so.
std::string athletes_markdown(const std::vector<CaseRecord>& records);

/// CSV, header first, one row per athlete (failed cases: status "crashed"/"timed_out", numbers
/// empty). Angles in degrees, forces N, moments N·m, L in kg·m²/s.
std::string athletes_csv(const std::vector<CaseRecord>& records);

/// DIR/{result.json, athletes.csv, athletes.md} from the records (kind "athlete", case order) and
/// the definition (athletes_definition). Returns result.json. Throws InputError naming a record
/// of another kind.
nlohmann::json write_athletes_files(const std::string& dir, const std::vector<CaseRecord>& records,
                                    const nlohmann::json& definition);

}  // namespace saltus
