#pragma once
/// @file
/// The kinds of study the runner knows (study.json's "study"): for each, what a whole study
/// writes from its case records. A new kind of study is one entry in study_kinds.cpp and the
/// files that build its job and write its outputs.

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/formats/output_folder.h"
#include "saltus/formats/study_case_file.h"

namespace saltus {

struct StudyKind {
  std::string name;  ///< study.json's "study"
  /// What a whole study's folder holds (output_kind.h): its writer's declaration.
  const FolderKind& (*folder)();
  /// Writes the whole study's own outputs (convergence.csv, report.md, ...) into `folder` from
  /// the study's definition and its records in case order; returns result.json.
  std::function<nlohmann::json(const OutputFolder& folder, const nlohmann::json& definition,
                               const std::vector<CaseRecord>& records)>
      write_outputs;
};

/// Every kind, in the order `saltus study` lists them.
const std::vector<StudyKind>& study_kinds();

/// The kind named `name`. Throws InputError naming `file` and /study when there is none.
const StudyKind& study_kind(const std::string& name, const std::string& file = "study.json");

}  // namespace saltus
