#include "saltus/formats/study_folder.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <type_traits>
#include <utility>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/formats/convergence_files.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/output_folder.h"
#include "saltus/formats/paper_report_files.h"

namespace saltus {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

nlohmann::json manifest_json(const std::string& study, const nlohmann::json& definition, int cases,
                             const StudyShard& shard) {
  return {{"format", kStudyFolderFormat},
          {"study", study},
          {"cases", cases},
          {"shard", shard.text()},
          {"definition", definition}};
}

struct Manifest {
  std::string study;
  int cases = 0;
  StudyShard shard;
  nlohmann::json definition;
  nlohmann::json document;
};

Manifest read_manifest(const fs::path& folder) {
  const std::string path = (folder / "study.json").string();
  if (!fs::exists(path))
    throw InputError(folder.string(), "", "not a study folder (no study.json)");
  Manifest m;
  m.document = read_json_file(path);
  const JsonNode root(m.document, path);
  root.require_object();
  if (root.at("format").as_string() != kStudyFolderFormat)
    root.at("format").fail(std::string("expected \"") + kStudyFolderFormat + "\"");
  m.study = root.at("study").as_string();
  m.cases = root.at("cases").as_int();
  if (m.cases < 0) root.at("cases").fail("must be >= 0");
  try {
    m.shard = parse_study_shard(root.at("shard").as_string());
  } catch (const InputError& e) {
    root.at("shard").fail(e.problem());
  }
  m.definition = root.at("definition").value();
  return m;
}

/// The JSON pointer of the first place where two documents differ, "" if they are equal.
std::string first_difference(const nlohmann::json& a, const nlohmann::json& b,
                             const std::string& path = "") {
  if (a == b) return "";
  if (a.is_object() && b.is_object()) {
    for (auto it = a.begin(); it != a.end(); ++it) {
      const std::string here = path + "/" + json_pointer_escape(it.key());
      if (!b.contains(it.key())) return here;
      const std::string inner = first_difference(it.value(), b.at(it.key()), here);
      if (!inner.empty()) return inner;
    }
    for (auto it = b.begin(); it != b.end(); ++it)
      if (!a.contains(it.key())) return path + "/" + json_pointer_escape(it.key());
  }
  if (a.is_array() && b.is_array() && a.size() == b.size()) {
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string inner = first_difference(a[i], b[i], path + "/" + std::to_string(i));
      if (!inner.empty()) return inner;
    }
  }
  return path.empty() ? "/" : path;
}

/// Throws InputError naming `folder`/study.json and the first field where its manifest differs
/// from `expected` (the shard too unless `any_shard`: merging joins different shards).
void require_same_study(const fs::path& folder, const nlohmann::json& expected, bool any_shard,
                        const std::string& why) {
  const Manifest found = read_manifest(folder);
  nlohmann::json found_document = found.document;
  nlohmann::json expected_document = expected;
  if (any_shard) {
    found_document.erase("shard");
    expected_document.erase("shard");
  }
  const std::string where = first_difference(expected_document, found_document);
  if (!where.empty())
    throw InputError((folder / "study.json").string(), where,
                     "differs from " + why + " (another study, shard or settings)");
}

/// Every record in folder/cases, by case index. A record of another case than its index names
/// in this study (`names`, when given) is an error; so is the same case twice.
std::map<int, CaseRecord> read_records(const fs::path& folder, int cases,
                                       const std::vector<std::string>* names) {
  std::map<int, CaseRecord> records;
  const fs::path dir = folder / "cases";
  if (!fs::is_directory(dir)) return records;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.size() > 5 && name.substr(name.size() - 5) == ".json")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    CaseRecord r = read_case_record(file.string());
    if (r.index >= cases)
      throw InputError(file.string(), "/index",
                       "case " + std::to_string(r.index) + " is beyond the study's " +
                           std::to_string(cases) + " cases");
    if (names && r.name != (*names)[r.index])
      throw InputError(file.string(), "/case",
                       "is \"" + r.name + "\", but case " + std::to_string(r.index) +
                           " of this study is \"" + (*names)[r.index] + "\"");
    if (records.count(r.index))
      throw InputError(file.string(), "/index",
                       "case " + std::to_string(r.index) + " is recorded twice");
    records.emplace(r.index, std::move(r));
  }
  return records;
}

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
nlohmann::json write_study_outputs(const OutputFolder& folder, const Manifest& manifest,
                                   const std::map<int, CaseRecord>& records) {
  fs::create_directories(folder.file("cases"));
  for (const auto& [index, record] : records)
    write_case_record(folder.file(case_record_name(index)), record);
  write_text(
      folder.file("study.json"),
      manifest_json(manifest.study, manifest.definition, manifest.cases, manifest.shard).dump(2) +
          "\n");
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
  if (manifest.study == "convergence")
    return write_convergence_study_outputs(folder, manifest.definition, ordered);
  if (manifest.study == "paper")
    return write_paper_report_outputs(folder, manifest.definition, ordered);
  throw InputError("study.json", "/study", "unknown study \"" + manifest.study + "\"");
}

std::string hex64(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

}  // namespace

StudyShard parse_study_shard(const std::string& text, const std::string& option) {
  const std::size_t slash = text.find('/');
  StudyShard shard;
  bool ok = slash != std::string::npos && slash > 0 && slash + 1 < text.size();
  if (ok) {
    try {
      std::size_t used = 0;
      shard.index = std::stoi(text.substr(0, slash), &used);
      ok = used == slash;
      shard.count = std::stoi(text.substr(slash + 1), &used);
      ok = ok && used == text.size() - slash - 1;
    } catch (const std::exception&) {
      ok = false;
    }
  }
  if (!ok || shard.count < 1 || shard.index < 1 || shard.index > shard.count)
    throw InputError(option, "", "\"" + text + "\" is not I/N with 1 <= I <= N (e.g. 2/4)");
  return shard;
}

StudyRunResult run_study(const StudyJob& job, const std::string& out_dir,
                         const StudyRunOptions& options) {
  const int cases = static_cast<int>(job.case_names.size());
  fs::path out = fs::absolute(out_dir).lexically_normal();
  if (out.filename().empty()) out = out.parent_path();
  const fs::path partial = out.string() + ".partial";
  Manifest manifest;
  manifest.study = job.study;
  manifest.cases = cases;
  manifest.shard = options.shard;
  manifest.definition = job.definition;
  const nlohmann::json expected = manifest_json(job.study, job.definition, cases, options.shard);

  StudyRunResult result;
  result.partial_dir = partial.string();
  if (fs::exists(partial)) {
    if (!fs::exists(partial / "study.json"))
      throw InputError(partial.string(), "",
                       "exists and is not an interrupted study (no study.json); not touching it");
    require_same_study(partial, expected, false, "this command's study");
    if (!options.resume) {
      const auto kept = read_records(partial, cases, &job.case_names);
      throw InputError(partial.string(), "",
                       "holds an interrupted run of this study (" + std::to_string(kept.size()) +
                           " cases done): add --resume to run only the others, or remove the "
                           "folder to start over");
    }
  } else if (options.resume && fs::exists(out / "study.json")) {
    require_same_study(out, expected, false, "this command's study");
    result.complete = result.already_complete = true;
    result.result = read_json_file((out / "result.json").string());
    return result;
  }
  // Checks DIR before any case runs (an hour of work must not end in "not overwriting it").
  OutputFolder folder(out.string());
  fs::create_directories(partial / "cases");
  write_text((partial / "study.json").string(), expected.dump(2) + "\n");

  std::map<int, CaseRecord> records = read_records(partial, cases, &job.case_names);
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

  for (const auto& [index, record] : records)
    if (!record.folder.empty() && fs::exists(partial / record.folder))
      fs::rename(partial / record.folder, folder.file(record.folder));
  result.result = write_study_outputs(folder, manifest, records);
  folder.commit();
  fs::remove_all(partial);
  result.complete = true;
  return result;
}

nlohmann::json merge_study_folders(const std::vector<std::string>& inputs,
                                   const std::string& out_dir) {
  if (inputs.empty()) throw InputError("merge", "", "no study folders given");
  const Manifest first = read_manifest(inputs.front());
  const nlohmann::json expected =
      manifest_json(first.study, first.definition, first.cases, first.shard);
  std::map<int, CaseRecord> records;
  std::map<int, std::string> source;
  for (const std::string& input : inputs) {
    require_same_study(input, expected, true, "the study in " + inputs.front());
    for (auto& [index, record] : read_records(input, first.cases, nullptr)) {
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
  OutputFolder folder(out_dir);
  for (const auto& [index, record] : records)
    if (!record.folder.empty())
      fs::copy(fs::path(source[index]) / record.folder, folder.file(record.folder),
               fs::copy_options::recursive);
  Manifest whole = first;
  whole.shard = StudyShard{};
  const nlohmann::json result = write_study_outputs(folder, whole, records);
  folder.commit();
  return result;
}

std::string motion_digest(const MotionFile& file) {
  // FNV-1a over the motion and the model as Saltus reads them: the same inputs give the same
  // digest wherever the files lie and however they are formatted.
  const std::string text =
      motion_to_json(file.motion, file.model).dump() + body_model_to_json(file.model).dump();
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hex64(hash);
}

nlohmann::json checkpoints_json(const std::vector<FeasibilityCheckpoint>& checkpoints) {
  nlohmann::json list = nlohmann::json::array();
  for (const FeasibilityCheckpoint& c : checkpoints)
    list.push_back({c.iterations, c.violation});
  return list;
}

namespace {

/// Converts to any member type: T{AnyField{}, ...} compiles for at most T's member count.
struct AnyField {
  template <class T>
  operator T() const;
};

template <class T, class Indices, class = void>
struct BraceInitializable : std::false_type {};
template <class T, std::size_t... I>
struct BraceInitializable<T, std::index_sequence<I...>,
                          std::void_t<decltype(T{(void(I), AnyField{})...})>> : std::true_type {};

/// The number of members of the aggregate T.
template <class T, std::size_t N = 0>
constexpr std::size_t member_count() {
  if constexpr (BraceInitializable<T, std::make_index_sequence<N + 1>>::value)
    return member_count<T, N + 1>();
  else
    return N;
}

// A study's definition must hold every setting that decides its results, or shards and resumed
// runs with different settings would merge silently. A new option changes these counts: add it
// to optimize_options_json below (unless, like verbose and derivative_test_file, it only
// decides what is logged), then update the count.
static_assert(member_count<MotionNlpOptions>() == 18, "new MotionNlpOptions member: add it below");
static_assert(member_count<DampingRule>() == 7, "new DampingRule member: add it below");
static_assert(member_count<SolverOptions>() == 11, "new SolverOptions member: add it below");
static_assert(member_count<OptimizeOptions>() == 4, "new OptimizeOptions member: add it below");

}  // namespace

nlohmann::json optimize_options_json(const OptimizeOptions& o) {
  const MotionNlpOptions& n = o.nlp;
  const SolverOptions& s = o.solver;
  return {{"nlp",
           {{"formulation", n.formulation == Formulation::kRelaxed ? "relaxed" : "strict"},
            {"epsilon", n.epsilon},
            {"optimize_timing", n.optimize_timing},
            {"knots_per_interval", n.knots_per_interval},
            {"subdivisions", n.subdivisions},
            {"samples", n.samples},
            {"quadrature_nodes", n.quadrature_nodes},
            {"quadrature_spacing", n.quadrature_spacing},
            {"min_time_gap", n.min_time_gap},
            {"max_time_shift", n.max_time_shift},
            {"given_keyframe_times", n.given_keyframe_times},
            {"damping",
             {{"initial", n.damping.initial},
              {"minimum", n.damping.minimum},
              {"maximum", n.damping.maximum},
              {"shrink", n.damping.shrink},
              {"grow", n.damping.grow},
              {"good_ratio", n.damping.good_ratio},
              {"poor_ratio", n.damping.poor_ratio}}},
            {"adapt_damping", n.adapt_damping},
            {"regularization", n.regularization},
            {"keyframe_weight", n.keyframe_weight},
            {"joint_turn_limit", n.joint_turn_limit},
            {"joint_turn_weight", n.joint_turn_weight},
            {"threads", n.threads}}},
          {"solver",
           {{"max_iterations", s.max_iterations},
            {"tolerance", s.tolerance},
            {"objective_change_tolerance", s.objective_change_tolerance},
            {"acceptable_iterations", s.acceptable_iterations},
            {"acceptable_constraint_violation", s.acceptable_constraint_violation},
            {"stall_iterations", s.stall_iterations},
            {"max_restarts", s.max_restarts},
            {"feasibility_checkpoints", checkpoints_json(s.feasibility_checkpoints)},
            {"warm_start", s.warm_start}}},
          {"refine_when_keyframes_missed", o.refine_when_keyframes_missed},
          {"automatic_resolution", o.automatic_resolution}};
}

}  // namespace saltus
