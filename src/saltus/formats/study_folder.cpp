#include "saltus/formats/study_folder.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>

#include "saltus/base/digest.h"
#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/output_folder.h"

namespace saltus {

namespace fs = std::filesystem;

namespace {

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

}  // namespace

FolderKind study_folder_kind(std::string name, std::vector<std::string> outputs) {
  outputs.push_back("study.json");
  return FolderKind{std::move(name), std::move(outputs), {}, {"cases"}, false};
}

const FolderKind& study_shard_folder_kind() {
  static const FolderKind kind{"study shard", {"result.json", "study.json"}, {}, {"cases"}, true};
  return kind;
}

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

nlohmann::json study_manifest_json(const StudyManifest& m) {
  return {{"format", kStudyFolderFormat},
          {"study", m.study},
          {"cases", m.cases},
          {"shard", m.shard.text()},
          {"definition", m.definition}};
}

StudyManifest read_study_manifest(const std::string& folder) {
  const std::string path = (fs::path(folder) / "study.json").string();
  if (!fs::exists(path)) throw InputError(folder, "", "not a study folder (no study.json)");
  const nlohmann::json document = read_json_file(path);
  const JsonNode root(document, path);
  root.require_object();
  if (root.at("format").as_string() != kStudyFolderFormat)
    root.at("format").fail(std::string("expected \"") + kStudyFolderFormat + "\"");
  StudyManifest m;
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

void require_same_study(const std::string& folder, const StudyManifest& expected, bool any_shard,
                        const std::string& why) {
  nlohmann::json found = study_manifest_json(read_study_manifest(folder));
  nlohmann::json wanted = study_manifest_json(expected);
  if (any_shard) {
    found.erase("shard");
    wanted.erase("shard");
  }
  const std::string where = first_difference(wanted, found);
  if (!where.empty())
    throw InputError((fs::path(folder) / "study.json").string(), where,
                     "differs from " + why + " (another study, shard or settings)");
}

std::map<int, CaseRecord> read_case_records(const std::string& folder, int cases,
                                            const std::vector<std::string>* names) {
  std::map<int, CaseRecord> records;
  const fs::path dir = fs::path(folder) / "cases";
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

void write_study_folder(const std::string& folder, const StudyManifest& manifest,
                        const std::map<int, CaseRecord>& records) {
  fs::create_directories(fs::path(folder) / "cases");
  for (const auto& [index, record] : records)
    write_case_record((fs::path(folder) / case_record_name(index)).string(), record);
  write_text((fs::path(folder) / "study.json").string(),
             study_manifest_json(manifest).dump(2) + "\n");
}

std::string motion_digest(const MotionFile& file) {
  // FNV-1a over the motion and the model as Saltus reads them: the same inputs give the same
  // digest wherever the files lie and however they are formatted.
  return text_digest(motion_to_json(file.motion, file.model).dump() +
                     body_model_to_json(file.model).dump());
}

nlohmann::json checkpoints_json(const std::vector<FeasibilityCheckpoint>& checkpoints) {
  nlohmann::json list = nlohmann::json::array();
  for (const FeasibilityCheckpoint& c : checkpoints)
    list.push_back({c.iterations, c.violation});
  return list;
}

}  // namespace saltus
