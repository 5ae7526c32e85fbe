#include "saltus/formats/output_kind.h"

#include <sys/stat.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "saltus/base/digest.h"
#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"

namespace saltus {

namespace {

constexpr const char* kMarkWords = " written by saltus: ";

/// A plain entry name: not empty, no '/', not "." or "..".
bool is_plain_name(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos &&
         name.find('\0') == std::string::npos;
}

std::vector<std::string> plain_names(const JsonNode& node) {
  std::vector<std::string> names;
  node.require_array();
  for (std::size_t i = 0; i < node.size(); ++i) {
    names.push_back(node.at(i).as_string());
    if (!is_plain_name(names.back())) node.at(i).fail("is not the name of an entry of the folder");
  }
  return names;
}

/// What the mark's digest covers: the document's canonical text with null in the mark's place
/// (so that the objects the mark's path needed are covered as written).
std::string unmarked_canonical(nlohmann::json document, const nlohmann::json::json_pointer& at) {
  document[at] = nullptr;
  return document.dump();
}

/// The last line of a kTrailingComment file for `digest`.
std::string comment_line(const FileKind& kind, const std::string& digest) {
  const std::string close = kind.comment_close.empty() ? "" : " " + kind.comment_close;
  return kind.comment_open + kMarkWords + kind.name + " " + digest + close + "\n";
}

}  // namespace

std::string folder_record_text(const FolderKind& kind) {
  const nlohmann::json record = {{"format", kFolderRecordFormat},
                                 {"kind", kind.name},
                                 {"files", kind.files},
                                 {"image_folders", kind.image_folders},
                                 {"record_folders", kind.record_folders},
                                 {"holds_results", kind.holds_results}};
  return record.dump(2) + "\n";
}

FolderKind read_folder_record(const std::string& folder, std::string& why_not) {
  const std::string path = (std::filesystem::path(folder) / kFolderRecordName).string();
  why_not.clear();
  struct stat info {};
  if (::lstat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) {
    why_not =
        std::string("it holds no record of what Saltus wrote there (") + kFolderRecordName + ")";
    return {};
  }
  try {
    const nlohmann::json document = read_json_file(path);
    const JsonNode root(document, path);
    root.require_keys_within(
        {"format", "kind", "files", "image_folders", "record_folders", "holds_results"});
    if (root.at("format").as_string() != kFolderRecordFormat)
      root.at("format").fail(std::string("expected \"") + kFolderRecordFormat + "\"");
    FolderKind kind;
    kind.name = root.at("kind").as_string();
    if (kind.name.empty()) root.at("kind").fail("is empty");
    kind.files = plain_names(root.at("files"));
    kind.image_folders = plain_names(root.at("image_folders"));
    kind.record_folders = plain_names(root.at("record_folders"));
    if (!root.at("holds_results").value().is_boolean())
      root.at("holds_results").fail("expected true or false");
    kind.holds_results = root.at("holds_results").value().get<bool>();
    return kind;
  } catch (const InputError& e) {
    why_not = std::string("its ") + kFolderRecordName + " is not a record Saltus wrote (" +
              e.problem() + ")";
    return {};
  }
}

bool has_json_mark(const nlohmann::json& document) {
  return document.is_object() && document.contains(kJsonMark);
}

nlohmann::json without_json_mark(nlohmann::json document) {
  if (document.is_object()) document.erase(kJsonMark);
  return document;
}

FileKind FileKind::unmarked(std::string name) {
  FileKind kind;
  kind.name = std::move(name);
  return kind;
}

FileKind FileKind::json(std::string name, std::string member) {
  FileKind kind;
  kind.name = std::move(name);
  kind.mark = FileMark::kJsonMember;
  kind.json_member = std::move(member);
  return kind;
}

FileKind FileKind::commented(std::string name, std::string open, std::string close) {
  FileKind kind;
  kind.name = std::move(name);
  kind.mark = FileMark::kTrailingComment;
  kind.comment_open = std::move(open);
  kind.comment_close = std::move(close);
  return kind;
}

FileKind FileKind::by_writer(std::string name, std::function<bool(const std::string&)> carries) {
  FileKind kind;
  kind.name = std::move(name);
  kind.mark = FileMark::kByWriter;
  kind.carries_mark = std::move(carries);
  return kind;
}

std::string marked_text(const FileKind& kind, const std::string& text) {
  switch (kind.mark) {
    case FileMark::kNone:
    case FileMark::kByWriter:
      return text;
    case FileMark::kTrailingComment: {
      const std::string body = text.empty() || text.back() == '\n' ? text : text + "\n";
      return body + comment_line(kind, text_digest(body));
    }
    case FileMark::kJsonMember: {
      nlohmann::json document;
      try {
        document = nlohmann::json::parse(text);
      } catch (const nlohmann::json::exception& e) {
        throw std::invalid_argument("a " + kind.name + " to write is not JSON: " + e.what());
      }
      const nlohmann::json::json_pointer at(kind.json_member);
      if (!document.is_object() || at.empty())
        throw std::invalid_argument("a " + kind.name + " to write is not a JSON object");
      const std::string digest = text_digest(unmarked_canonical(document, at));
      document[at] = {{"kind", kind.name}, {"digest", digest}};
      return document.dump(2) + "\n";
    }
  }
  return text;
}

std::string unmarked_reason(const FileKind& kind, const std::string& text) {
  const std::string theirs = "is not " + with_article(kind.name) + " Saltus wrote";
  const std::string changed = "was changed since Saltus wrote it";
  switch (kind.mark) {
    case FileMark::kNone:
      return "may be the user's: Saltus cannot tell " + with_article(kind.name) +
             " it wrote from one it did not (the format has no room for a mark)";
    case FileMark::kByWriter:
      return kind.carries_mark && kind.carries_mark(text) ? "" : theirs;
    case FileMark::kTrailingComment: {
      if (text.size() < 2 || text.back() != '\n') return theirs;
      const std::size_t start = text.rfind('\n', text.size() - 2) + 1;  // npos + 1 == 0
      const std::string line = text.substr(start);
      const std::string body = text.substr(0, start);
      const std::string prefix = kind.comment_open + kMarkWords;
      if (line.compare(0, prefix.size(), prefix) != 0) return theirs;
      if (line.compare(prefix.size(), kind.name.size() + 1, kind.name + " ") != 0)
        return theirs + " (it is another kind of file Saltus wrote)";
      if (line != comment_line(kind, text_digest(body))) return changed;
      return "";
    }
    case FileMark::kJsonMember: {
      nlohmann::json document;
      try {
        document = parse_json_text(text, kind.name);
      } catch (const InputError&) {
        return theirs + " (it is not JSON)";
      }
      const nlohmann::json::json_pointer at(kind.json_member);
      if (!document.is_object() || !document.contains(at)) return theirs;
      const nlohmann::json mark = document[at];
      if (!mark.is_object() || !mark.contains("kind") || mark["kind"] != kind.name ||
          !mark.contains("digest") || !mark["digest"].is_string())
        return theirs + " (it is another kind of file Saltus wrote)";
      if (mark["digest"] != text_digest(unmarked_canonical(document, at))) return changed;
      return "";
    }
  }
  return theirs;
}

}  // namespace saltus
