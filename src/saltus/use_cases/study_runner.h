#pragma once
/// @file
/// Running a study: every case runs in a process of its own (studies/isolated_runner.h),
/// several at once, and leaves one record (formats/study_case_file.h) in DIR.partial/cases/ as
/// it finishes. When the shard's cases are all there, the folder (formats/study_folder.h) is
/// renamed into place as DIR with study.json, cases/, what cases wrote beside their record (the
/// report's M1/, mass/, ...) and result.json: a shard's summary, or, for a whole study, the
/// study's own outputs, assembled from the records alone by its kind (study_kinds.h). Merging
/// shard folders assembles the same outputs from their records, so merged shards and a single
/// run write the same files. An interrupted run keeps DIR.partial; --resume runs only the
/// cases it lacks.

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/formats/study_case_file.h"
#include "saltus/formats/study_folder.h"
#include "saltus/formats/study_progress.h"
#include "saltus/studies/isolated_runner.h"

namespace saltus {

/// A study as the runner sees it.
struct StudyJob {
  std::string study;          ///< its kind (study_kinds.h)
  nlohmann::json definition;  ///< everything that decides the results; compared on resume/merge
  std::vector<std::string> case_names;  ///< one per case, in the study's order
  /// Runs case `index` (in its own process); writes the case's folder, if any, into `dir`.
  std::function<CaseRecord(int index, const std::string& dir)> run_case;
  /// The record of a case whose process failed (exit.describe() says how).
  std::function<CaseRecord(int index, const WorkerExit& exit)> unfinished_case;
};

/// s: a case still running after this is killed and recorded as timed out, unless the user
/// says otherwise (`--case-time-limit`).
inline constexpr double kDefaultCaseTimeLimitS = 900.0;

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
  /// Entries of DIR.partial that Saltus did not write (relative paths): when the study is
  /// complete they are kept there, and only they; empty when DIR.partial was removed.
  std::vector<std::string> partial_kept;
  nlohmann::json result;  ///< DIR/result.json when complete
};

/// The folder that keeps the finished cases of an interrupted study written to `out_dir`: its
/// sibling DIR.partial (the name shortened with a digest where DIR's name leaves no room for
/// ".partial": formats/output_folder.h, sibling_name), absolute.
std::string study_partial_folder(const std::string& out_dir);

/// Runs the shard's missing cases and, when all are there, writes DIR and removes from
/// DIR.partial what the run wrote (a file the user put there stays). Throws InputError when
/// DIR is not replaceable (OutputFolder's rule), when DIR.partial holds a run and `resume` is
/// off, when it holds another study (naming the first field that differs), or when a case's
/// folder there holds files Saltus did not write (checked before any case runs, and again
/// before the folder is moved into DIR).
StudyRunResult run_study(const StudyJob& job, const std::string& out_dir,
                         const StudyRunOptions& options);

/// Writes into `out_dir` exactly what one run of the study writes, from completed study
/// folders (shards, or whole runs) of the same study. Throws InputError naming the folder
/// when one is not a study folder, is of another study, or when cases are missing or twice.
nlohmann::json merge_study_folders(const std::vector<std::string>& inputs,
                                   const std::string& out_dir);

}  // namespace saltus
