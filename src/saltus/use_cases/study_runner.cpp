#include "saltus/use_cases/study_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/formats/output_folder.h"
#include "saltus/use_cases/study_kinds.h"

namespace saltus {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

/// The order in which a shard's cases run: spread over the study (a golden-ratio sequence), so
/// that the first cases done are a fair sample of the rest and the ETA means something.
std::vector<int> spread_order(std::vector<int> cases) {
  auto key = [](int i) {
    const double x = i * 0.6180339887498949;
    return x - std::floor(x);
  };
  std::stable_sort(cases.begin(), cases.end(), [&](int a, int b) { return key(a) < key(b); });
  return cases;
}

/// Writes a complete study folder into `folder`: study.json, the records, and the shard's
/// summary or (whole study) the study's own outputs. Case folders are already in place.
nlohmann::json write_study_outputs(const OutputFolder& folder, const StudyManifest& manifest,
                                   const std::map<int, CaseRecord>& records) {
  write_study_folder(folder.file(""), manifest, records);
  int failed = 0;
  for (const auto& [index, record] : records)
    failed += record.finished() ? 0 : 1;
  if (!manifest.shard.whole()) {
    nlohmann::json result = {
        {"format", "saltus-study-shard/1"}, {"study", manifest.study}, {"status", "completed"},
        {"shard", manifest.shard.text()},   {"cases", records.size()}, {"failed", failed}};
    write_text(folder.file("result.json"), result.dump(2) + "\n");
    return result;
  }
  std::vector<CaseRecord> ordered;
  for (const auto& [index, record] : records)
    ordered.push_back(record);
  return study_kind(manifest.study).write_outputs(folder, manifest.definition, ordered);
}

/// Refuses (InputError) to take into DIR a case's folder in DIR.partial that holds anything
/// Saltus did not write there: the user's files stay where they are.
void require_own_case_folders(const fs::path& partial, const std::map<int, CaseRecord>& records) {
  for (const auto& [index, record] : records) {
    if (record.folder.empty() || !fs::exists(partial / record.folder)) continue;
    const std::string why = foreign_content((partial / record.folder).string());
    if (!why.empty())
      throw InputError((partial / record.folder).string(), "",
                       "is case " + std::to_string(index) +
                           "'s result, which Saltus would move "
                           "into the study, but " +
                           why +
                           ". Move your files away, then run the "
                           "same command with --resume");
  }
}

/// Removes from DIR.partial what the run wrote there (study.json, the case records; the cases'
/// folders were moved into DIR), and the folder once it is empty. Returns what is left: entries
/// Saltus did not write, kept for their owner.
std::vector<std::string> remove_own_partial(const fs::path& partial,
                                            const std::map<int, CaseRecord>& records) {
  std::error_code ec;
  fs::remove(partial / "study.json", ec);
  for (const auto& [index, record] : records)
    fs::remove(partial / case_record_name(index), ec);
  fs::remove(partial / "cases", ec);  // only when empty
  fs::remove(partial, ec);
  std::vector<std::string> kept;
  for (fs::recursive_directory_iterator it(partial, ec), end; !ec && it != end; it.increment(ec))
    if (!it->is_directory()) kept.push_back(fs::relative(it->path(), partial).string());
  std::sort(kept.begin(), kept.end());
  return kept;
}

}  // namespace

std::string study_partial_folder(const std::string& out_dir) {
  fs::path out = fs::absolute(out_dir).lexically_normal();
  if (out.filename().empty()) out = out.parent_path();
  return (out.parent_path() / sibling_name(out.filename().string(), "", ".partial")).string();
}

StudyRunResult run_study(const StudyJob& job, const std::string& out_dir,
                         const StudyRunOptions& options) {
  if (const std::string why = output_name_problem(out_dir); !why.empty())
    throw InputError(out_dir, "", why);
  const int cases = static_cast<int>(job.case_names.size());
  fs::path out = fs::absolute(out_dir).lexically_normal();
  if (out.filename().empty()) out = out.parent_path();
  const fs::path partial = study_partial_folder(out_dir);
  const StudyKind& kind = study_kind(job.study);  // an unknown kind could never be assembled
  StudyManifest manifest;
  manifest.study = job.study;
  manifest.cases = cases;
  manifest.shard = options.shard;
  manifest.definition = job.definition;

  StudyRunResult result;
  result.partial_dir = partial.string();
  if (fs::exists(partial)) {
    if (!fs::exists(partial / "study.json"))
      throw InputError(partial.string(), "",
                       "exists and is not an interrupted study (no study.json); not touching it");
    require_same_study(partial.string(), manifest, false, "this command's study");
    if (!options.resume) {
      const auto kept = read_case_records(partial.string(), cases, &job.case_names);
      throw InputError(partial.string(), "",
                       "holds an interrupted run of this study (" + std::to_string(kept.size()) +
                           " cases done): add --resume to run only the others, or remove the "
                           "folder to start over");
    }
  } else if (options.resume && fs::exists(out / "study.json")) {
    require_same_study(out.string(), manifest, false, "this command's study");
    result.complete = result.already_complete = true;
    result.result = read_json_file((out / "result.json").string());
    return result;
  }
  // Checks DIR before any case runs (an hour of work must not end in "not overwriting it").
  OutputFolder folder(out.string(),
                      options.shard.whole() ? kind.folder() : study_shard_folder_kind());
  write_study_folder(partial.string(), manifest, {});

  std::map<int, CaseRecord> records = read_case_records(partial.string(), cases, &job.case_names);
  require_own_case_folders(partial, records);  // before the work, not after an hour of it
  std::vector<int> todo;
  int in_shard = 0;
  StudyProgress progress;
  for (int i = 0; i < cases; ++i) {
    if (!options.shard.holds(i)) continue;
    ++in_shard;
    const auto found = records.find(i);
    if (found == records.end()) {
      todo.push_back(i);
      continue;
    }
    ++progress.done;
    progress.failed += found->second.finished() ? 0 : 1;
    progress.unsolved += found->second.finished() && !found->second.solved() ? 1 : 0;
  }
  progress.total = in_shard;
  todo = spread_order(todo);

  const Clock::time_point start = Clock::now();
  auto record_path = [&](int index) { return (partial / case_record_name(index)).string(); };
  const auto work = [&](int index) {
    const CaseRecord record = job.run_case(index, partial.string());
    write_case_record(record_path(index), record);
    return 0;
  };
  const auto finished = [&](int index, const WorkerExit& exit) {
    // A child may have written its record and been killed just after: its record stands.
    CaseRecord record;
    bool recorded = false;
    if (fs::exists(record_path(index))) {
      try {
        record = read_case_record(record_path(index));
        recorded = record.index == index;
      } catch (const InputError&) {
      }
    }
    if (!recorded) {
      record = job.unfinished_case(index, exit);
      write_case_record(record_path(index), record);
    }
    ++result.cases_run;
    ++progress.done;
    progress.failed += record.finished() ? 0 : 1;
    progress.unsolved += record.finished() && !record.solved() ? 1 : 0;
    progress.elapsed_s = std::chrono::duration<double>(Clock::now() - start).count();
    progress.eta_s = progress.elapsed_s / result.cases_run * (progress.total - progress.done);
    progress.last = &record;
    if (options.progress) options.progress(progress);
    progress.last = nullptr;
    records[index] = std::move(record);
  };
  IsolatedRunOptions isolation;
  isolation.jobs = options.jobs;
  isolation.time_limit_s = options.case_time_limit_s;
  const IsolatedRunSummary run = run_isolated(todo, isolation, work, finished);
  result.failed = progress.failed;
  if (run.interrupted()) {
    result.interrupt_signal = run.interrupt_signal;
    return result;
  }

  require_own_case_folders(partial, records);
  for (const auto& [index, record] : records)
    if (!record.folder.empty() && fs::exists(partial / record.folder))
      fs::rename(partial / record.folder, folder.file(record.folder));
  result.result = write_study_outputs(folder, manifest, records);
  folder.commit();
  result.partial_kept = remove_own_partial(partial, records);
  result.complete = true;
  return result;
}

nlohmann::json merge_study_folders(const std::vector<std::string>& inputs,
                                   const std::string& out_dir) {
  if (inputs.empty()) throw InputError("merge", "", "no study folders given");
  const StudyManifest first = read_study_manifest(inputs.front());
  std::map<int, CaseRecord> records;
  std::map<int, std::string> source;
  for (const std::string& input : inputs) {
    require_same_study(input, first, true, "the study in " + inputs.front());
    for (auto& [index, record] : read_case_records(input, first.cases, nullptr)) {
      if (records.count(index))
        throw InputError(input, "",
                         "case " + std::to_string(index) + " (" + record.name + ") is also in " +
                             source[index] + ": give each shard once");
      if (!record.folder.empty() && !fs::is_directory(fs::path(input) / record.folder))
        throw InputError(
            input, "",
            "case " + std::to_string(index) + " wrote " + record.folder + "/, which is missing");
      source[index] = input;
      records.emplace(index, std::move(record));
    }
  }
  std::vector<int> missing;
  for (int i = 0; i < first.cases; ++i)
    if (!records.count(i)) missing.push_back(i);
  if (!missing.empty()) {
    std::string list;
    for (std::size_t k = 0; k < missing.size() && k < 5; ++k)
      list += (k ? ", " : "") + std::to_string(missing[k]);
    throw InputError(inputs.front(), "",
                     std::to_string(missing.size()) + " of the study's " +
                         std::to_string(first.cases) + " cases are in none of the folders (" +
                         list + (missing.size() > 5 ? ", ..." : "") +
                         "): run the shards that hold them (with --resume) and merge again");
  }
  OutputFolder folder(out_dir, study_kind(first.study).folder());
  for (const auto& [index, record] : records)
    if (!record.folder.empty())
      fs::copy(fs::path(source[index]) / record.folder, folder.file(record.folder),
               fs::copy_options::recursive);
  StudyManifest whole = first;
  whole.shard = StudyShard{};
  const nlohmann::json result = write_study_outputs(folder, whole, records);
  folder.commit();
  return result;
}

}  // namespace saltus
