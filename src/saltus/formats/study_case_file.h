#pragma once
/// @file
/// One case of a study, as its process left it: DIR/cases/NNNN.json. A study run, a shard and
/// a resumed run each write one such record per finished case; merging shards and finishing a
/// run read them back and build every output from them alone, so a single run and merged shards
/// write the same files. Numbers round-trip exactly (shortest round-trip doubles; a non-finite
/// number is written as null and read back as NaN).
///
///   {"format": "saltus-study-case/1", "index": 42, "case": "M3 strict ε=50, mass …",
///    "kind": "convergence" | "optimization" | "mass_study" | "athlete", "role": "convergence",
///    "motion": "M3", "folder": null | "M1", "failure": null | "killed by signal 11 (…)",
///    "convergence": {...} | "run": {...} | "mass_markdown": "..." | "athlete": {...}}

#include <nlohmann/json.hpp>
#include <string>

#include "saltus/studies/athlete_study.h"
#include "saltus/studies/convergence_study.h"
#include "saltus/studies/paper_report.h"

namespace saltus {

inline constexpr const char* kStudyCaseFormat = "saltus-study-case/1";

enum class CaseKind {
  kConvergence,   ///< one optimisation of the convergence study: `convergence`
  kOptimization,  ///< an optimisation of the report (a skill, its K = 3 run, a dive): `run`
  kMassStudy,     ///< the report's mass study: `mass_markdown`
  kAthlete,       ///< one athlete of the athletes study: `athlete`
};

struct CaseRecord {
  int index = 0;     ///< in the study's case list (the same on every machine and shard)
  std::string name;  ///< the case in words; a record is only taken for the case of that name
  CaseKind kind = CaseKind::kConvergence;
  std::string role;    ///< the case's part in its study ("convergence", "skill", "dive", ...)
  std::string motion;  ///< the motion's label
  /// Output folder the case wrote beside the cases/ folder ("M1", "mass"); "" for none.
  std::string folder;
  /// Why the case's process did not finish ("killed by signal 11 (Segmentation fault)", "timed
  /// out after 900 s"); "" when it did. Such a case counts as a failure of the study.
  std::string failure;
  StudyOutcome convergence;   ///< kConvergence
  RunSummary run;             ///< kOptimization
  std::string mass_markdown;  ///< kMassStudy: formats/mass_files.h's table
  AthleteOutcome athlete;     ///< kAthlete
  bool finished() const { return failure.empty(); }
  /// Finished and, for an optimisation, solved (a mass study counts as solved when finished).
  bool solved() const;
};

nlohmann::json case_record_to_json(const CaseRecord& record);

/// Throws InputError naming `file` and the JSON pointer of a bad field.
CaseRecord parse_case_record(const nlohmann::json& document, const std::string& file);

/// Writes the record atomically (a temporary file renamed into place): a process killed while
/// writing leaves no half record.
void write_case_record(const std::string& path, const CaseRecord& record);

CaseRecord read_case_record(const std::string& path);

/// "cases/0042.json" (at least four digits).
std::string case_record_name(int index);

}  // namespace saltus
