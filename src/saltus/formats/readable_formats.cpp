#include "saltus/formats/readable_formats.h"

#include <cctype>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "saltus/base/json_reader.h"
#include "saltus/formats/mass_files.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/result_json.h"

namespace saltus {

namespace {

namespace fs = std::filesystem;

bool name_matches(const std::string& path, const std::vector<std::string>& patterns) {
  const std::string name = fs::path(path).filename().string();
  for (const std::string& pattern : patterns)
    if (matches_pattern(name, pattern)) return true;
  return false;
}

/// The "format" tag of a JSON file, "" when it has none or is not JSON.
std::string json_format_tag(const std::string& path) {
  try {
    const nlohmann::json document = read_json_file(path);
    if (document.is_object() && document.contains("format") && document["format"].is_string())
      return document["format"].get<std::string>();
  } catch (const std::exception&) {
  }
  return "";
}

/// The list. For a file format the last field is a content check (null: the name decides, and
/// the format's reader then says what is wrong inside); for a folder, the whole test.
std::vector<ReadableFormat> make_formats() {
  std::vector<ReadableFormat> formats{
      {ReadableKind::kModel,
       "Body models",
       {"*.json"},
       false,
       [](const std::string& path) { return json_format_tag(path) == kModelFormatTag; }},
      // Any other JSON file is offered as a motion.
      {ReadableKind::kMotion, "Motions", {"*.motion.json", "*.json"}, false, nullptr},
      // Both cases for the file dialogs, whose filters are case-sensitive on Linux.
      {ReadableKind::kCapture, "Motion captures", {"*.bvh", "*.BVH"}, false, nullptr},
      {ReadableKind::kMassStudyFolder,
       "Mass study folders",
       {},
       true,
       [](const std::string& path) { return is_mass_study_folder(path); }},
      {ReadableKind::kResultFolder,
       "Result folders",
       {},
       true,
       [](const std::string& path) {
         const fs::path result = fs::path(path) / "result.json";
         return fs::is_directory(path) && fs::is_regular_file(result) &&
                json_format_tag(result.string()) == kResultFormatTag;
       }},
  };
  for (ReadableFormat& f : formats)
    if (!f.folder)
      f.recognises = [patterns = f.patterns, content = f.recognises](const std::string& path) {
        return fs::is_regular_file(path) && name_matches(path, patterns) &&
               (!content || content(path));
      };
  return formats;
}

}  // namespace

const std::vector<ReadableFormat>& readable_formats() {
  static const std::vector<ReadableFormat> formats = make_formats();
  return formats;
}

const ReadableFormat& readable_format(ReadableKind kind) {
  for (const ReadableFormat& f : readable_formats())
    if (f.kind == kind) return f;
  throw std::logic_error("readable format without an entry in readable_formats()");
}

std::optional<ReadableKind> identify_readable(const std::string& path) {
  for (const ReadableFormat& f : readable_formats())
    if (f.recognises(path)) return f.kind;
  return std::nullopt;
}

std::string dialog_filter(ReadableKind kind) {
  const ReadableFormat& f = readable_format(kind);
  std::string patterns;
  for (const std::string& p : f.patterns)
    patterns += (patterns.empty() ? "" : " ") + p;
  return f.name + " (" + patterns + ")";
}

std::string save_dialog_filter(ReadableKind kind) {
  const ReadableFormat& f = readable_format(kind);
  return f.name + " (" + (f.patterns.empty() ? std::string() : f.patterns.front()) + ")";
}

bool matches_pattern(const std::string& file_name, const std::string& pattern) {
  // Backtracking over the last '*': patterns are short ("*.motion.json").
  std::size_t n = 0, p = 0, star = std::string::npos, resume = 0;
  auto same = [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) ==
           std::tolower(static_cast<unsigned char>(b));
  };
  while (n < file_name.size()) {
    if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = n;
    } else if (p < pattern.size() && same(pattern[p], file_name[n])) {
      ++p, ++n;
    } else if (star != std::string::npos) {
      p = star + 1;
      n = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*')
    ++p;
  return p == pattern.size();
}

}  // namespace saltus
