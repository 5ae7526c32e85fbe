#pragma once
/// @file
/// A study's folder and how it is filled: every case runs in a process of its own
/// (studies/isolated_runner.h), several at once, and leaves one record (study_case_file.h)
/// in DIR.partial/cases/ as it finishes. When the shard's cases are all there, the folder is
/// renamed into place as DIR with
///   study.json   the study's definition (what decides its results, no paths), case count, shard
///   cases/       one record per case of the shard
///   <folders>    what cases wrote beside their record (the report's M1/, mass/, ...)
///   result.json  a shard's summary, or, for a whole study, the study's own outputs (assembled
///                from the records alone: convergence.csv/.md, report.md, ...)
/// Merging shard folders assembles the same outputs from their records, so merged shards and a
/// single run write the same files. An interrupted run keeps DIR.partial; --resume runs only
/// the cases it lacks. Shard I of N holds the cases whose index modulo N is I − 1.

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/formats/study_case_file.h"
#include "saltus/studies/isolated_runner.h"

namespace saltus {

inline constexpr const char* kStudyFolderFormat = "saltus-study-folder/1";

struct StudyShard {
  int index = 1;  ///< 1-based
  int count = 1;
  bool whole() const { return count == 1; }
  bool holds(int case_index) const { return case_index % count == index - 1; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

/// "I/N" with 1 <= I <= N. Throws InputError naming `option` otherwise.
StudyShard parse_study_shard(const std::string& text, const std::string& option = "--shard");

/// A study as the runner sees it.
struct StudyJob {
  std::string study;          ///< "convergence" or "paper"
  nlohmann::json definition;  ///< everything that decides the results; compared on resume/merge
  std::vector<std::string> case_names;  ///< one per case, in the study's order
  /// Runs case `index` (in its own process); writes the case's folder, if any, into `dir`.
  std::function<CaseRecord(int index, const std::string& dir)> run_case;
  /// The record of a case whose process failed (exit.describe() says how).
  std::function<CaseRecord(int index, const WorkerExit& exit)> unfinished_case;
};

struct StudyProgress {
  int done = 0;            ///< cases of the shard with a record, those kept from before included
  int total = 0;           ///< cases of the shard
  int failed = 0;          ///< records whose process crashed or timed out
  int unsolved = 0;        ///< records that finished without solving
  double elapsed_s = 0.0;  ///< since this run started
  double eta_s = -1.0;     ///< remaining time at this run's pace; −1 before the first case
  const CaseRecord* last = nullptr;  ///< the record just written
};

struct StudyRunOptions {
  int jobs = 1;
  double case_time_limit_s = 0.0;  ///< 0: none
  StudyShard shard;
  bool resume = false;
  std::function<void(const StudyProgress&)> progress;  ///< after every case, may be empty
};

struct StudyRunResult {
  bool complete = false;          ///< DIR was written
  bool already_complete = false;  ///< --resume found DIR complete for this study: nothing ran
  int interrupt_signal = 0;       ///< the signal that stopped the run (DIR.partial kept)
  int cases_run = 0;
  int failed = 0;           ///< records of the shard whose process crashed or timed out
  std::string partial_dir;  ///< DIR.partial
  nlohmann::json result;    ///< DIR/result.json when complete
};

/// Runs the shard's missing cases and, when all are there, writes DIR. Throws InputError when
/// DIR is not replaceable (OutputFolder's rule), when DIR.partial holds a run and `resume` is
/// off, or when it holds another study (naming the first field that differs).
StudyRunResult run_study(const StudyJob& job, const std::string& out_dir,
                         const StudyRunOptions& options);

/// Writes into `out_dir` exactly what one run of the study writes, from completed study
/// folders (shards, or whole runs) of the same study. Throws InputError naming the folder
/// when one is not a study folder, is of another study, or when cases are missing or twice.
nlohmann::json merge_study_folders(const std::vector<std::string>& inputs,
                                   const std::string& out_dir);

/// Digest of a motion file's contents (its motion and model as Saltus reads them), so that
/// shards and resumed runs can check they run the same inputs wherever the files lie.
std::string motion_digest(const MotionFile& file);

/// Every optimiser setting that decides a result, for a study's definition.
nlohmann::json optimize_options_json(const OptimizeOptions& options);

/// [[iterations, violation], ...].
nlohmann::json checkpoints_json(const std::vector<FeasibilityCheckpoint>& checkpoints);

}  // namespace saltus
