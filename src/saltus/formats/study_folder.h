#pragma once
/// @file
/// A study's folder as files (docs/formats.md, "Study folders"):
///   study.json   the study's kind, its definition (what decides its results, no paths), the
///                case count and the shard
///   cases/       one record per case (study_case_file.h)
/// Running, resuming and merging studies is use_cases/study_runner.h's.

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/formats/motion_file.h"
#include "saltus/formats/output_kind.h"
#include "saltus/formats/study_case_file.h"
#include "saltus/optim/solve_policy.h"

namespace saltus {

inline constexpr const char* kStudyFolderFormat = "saltus-study-folder/1";

/// Shard I of N holds the cases whose index modulo N is I − 1.
struct StudyShard {
  int index = 1;  ///< 1-based
  int count = 1;
  bool whole() const { return count == 1; }
  bool holds(int case_index) const { return case_index % count == index - 1; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

/// "I/N" with 1 <= I <= N. Throws InputError naming `option` otherwise.
StudyShard parse_study_shard(const std::string& text, const std::string& option = "--shard");

/// The FolderKind of a whole study's folder named `name` ("study convergence"): its own
/// `outputs` (result.json, tables) with study.json and the records' cases/.
FolderKind study_folder_kind(std::string name, std::vector<std::string> outputs);

/// The folder of one shard (--shard I/N): result.json, study.json, cases/, and the folders its
/// cases wrote (a report's runs).
const FolderKind& study_shard_folder_kind();

/// study.json.
struct StudyManifest {
  std::string study;  ///< the study's kind (use_cases/study_kinds.h)
  int cases = 0;
  StudyShard shard;
  nlohmann::json definition;
};

nlohmann::json study_manifest_json(const StudyManifest& manifest);
/// FOLDER/study.json. Throws InputError naming the file and field, or the folder when it has
/// no study.json.
StudyManifest read_study_manifest(const std::string& folder);

/// Throws InputError naming FOLDER/study.json and the first field where it differs from
/// `expected` (the shard too unless `any_shard`: merging joins different shards); `why` names
/// what it was compared with.
void require_same_study(const std::string& folder, const StudyManifest& expected, bool any_shard,
                        const std::string& why);

/// Every record in FOLDER/cases, by case index. A record beyond `cases`, of another case than
/// its index names in `names` (when given), or the same case twice is an InputError.
std::map<int, CaseRecord> read_case_records(const std::string& folder, int cases,
                                            const std::vector<std::string>* names);

/// Writes study.json and the records into `folder` (which exists).
void write_study_folder(const std::string& folder, const StudyManifest& manifest,
                        const std::map<int, CaseRecord>& records);

/// Digest of a motion file's contents (its motion and model as Saltus reads them), so that
/// shards and resumed runs can check they run the same inputs wherever the files lie.
std::string motion_digest(const MotionFile& file);

/// [[iterations, violation], ...].
nlohmann::json checkpoints_json(const std::vector<FeasibilityCheckpoint>& checkpoints);

}  // namespace saltus
