#pragma once
/// @file
/// What a writer declares about what it writes, read by the one rule that guards outputs
/// (docs/safety.md, "Output folders"): Saltus replaces only what it wrote, never a file the user
/// made or changed.
///
/// A folder writer opens its OutputFolder (output_folder.h) with a FolderKind: the entries it
/// writes. The folder refuses to commit an entry its declaration lacks (a bug, caught by the
/// first run of the writer), and records the declaration inside the folder it writes
/// (kFolderRecordName), so that the next run of any verb knows which entries there are
/// Saltus's without a list kept anywhere else.
///
/// A single-file writer passes a FileKind to write_output_file: where the format has room, the
/// file carries a mark (the kind and a digest of the rest of the file), and an existing file is
/// replaced only when it carries the mark of the same kind and the digest still matches (a file
/// the user wrote, copied from elsewhere or edited since is theirs). A format with no room for
/// a mark (BVH) never replaces a file.

#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <utility>
#include <vector>

namespace saltus {

/// A kind of result folder, as its writer declares it.
struct FolderKind {
  FolderKind() = default;
  FolderKind(std::string kind_name, std::vector<std::string> written_files,
             std::vector<std::string> images = {}, std::vector<std::string> records = {},
             bool results = false)
      : name(std::move(kind_name)),
        files(std::move(written_files)),
        image_folders(std::move(images)),
        record_folders(std::move(records)),
        holds_results(results) {}

  std::string name;                ///< "evaluate", "analyse what-if", "study athletes", ...
  std::vector<std::string> files;  ///< the regular files the writer may write there
  /// Sub-folders that hold only PNG images (a report's figures/, which saltus-gui
  /// --export-figures adds later).
  std::vector<std::string> image_folders;
  /// Sub-folders that hold only a study's case records, NNNN.json (a study's cases/).
  std::vector<std::string> record_folders;
  /// Any other sub-folder is itself a Saltus result folder (a report's M1/, mass/, ...).
  bool holds_results = false;
};

/// The hidden file in every result folder that records its FolderKind (docs/formats.md,
/// "Result folders"), "saltus-folder/1".
inline constexpr const char* kFolderRecordName = ".saltus-folder.json";
inline constexpr const char* kFolderRecordFormat = "saltus-folder/1";

/// The record's text.
std::string folder_record_text(const FolderKind& kind);

/// The FolderKind recorded in `folder`, or "" in `why_not` (and an empty kind) when there is
/// none or it is not a record Saltus wrote, with the reason as a clause ("it holds no record of
/// what Saltus wrote there (.saltus-folder.json)").
FolderKind read_folder_record(const std::string& folder, std::string& why_not);

/// The member of a JSON file's root that holds Saltus's mark (readers accept it and ignore it).
inline constexpr const char* kJsonMark = "written_by_saltus";

/// Whether `document` is an object with the member kJsonMark, and the document without it: a
/// reader of a marked JSON format reads past the mark.
bool has_json_mark(const nlohmann::json& document);
nlohmann::json without_json_mark(nlohmann::json document);

/// How a file of a kind carries Saltus's mark.
enum class FileMark {
  kNone,             ///< no room for one: an existing file is never replaced (BVH)
  kJsonMember,       ///< a member of the JSON document (json_member: a JSON pointer)
  kTrailingComment,  ///< a comment after the document (comment_open ... comment_close)
  kByWriter,         ///< the writer puts it in the bytes itself (a binary format: glTF's .glb)
};

/// A kind of single file, as its writer declares it.
struct FileKind {
  std::string name;  ///< "body model", "flight page", "BVH capture": for messages and the mark
  FileMark mark = FileMark::kNone;
  /// kJsonMember: where the mark lives, e.g. "/written_by_saltus"; a format with a strict
  /// schema puts it where the schema allows extra data (glTF: "/asset/extras/written_by_saltus").
  std::string json_member;
  /// kTrailingComment: the format's comment delimiters, e.g. "<!--" and "-->" (HTML, XML).
  std::string comment_open;
  std::string comment_close;
  /// kByWriter: whether a file's bytes carry the mark its writer puts there.
  std::function<bool(const std::string& bytes)> carries_mark;
  /// Whether the file is a program its user runs (a Slurm script): written with mode 0755,
  /// else 0644 (both less the umask).
  bool executable = false;

  /// A kind whose files have no room for a mark.
  static FileKind unmarked(std::string name);
  /// A JSON kind, marked by an object {"kind", "digest"} at `member`.
  static FileKind json(std::string name, std::string member = std::string("/") + kJsonMark);
  /// A text kind, marked by a last line `open written by saltus: KIND DIGEST close` (no `close`
  /// for a comment that ends with its line, such as a shell's "#").
  static FileKind commented(std::string name, std::string open, std::string close);
  /// A kind whose writer marks the bytes itself; `carries_mark` recognises the mark.
  static FileKind by_writer(std::string name, std::function<bool(const std::string&)> carries_mark);
};

/// `text` as Saltus writes a file of `kind`: with its mark. For kJsonMember `text` must be a
/// JSON object; the result is that object with the mark, indented by 2, ending in a newline.
/// Throws std::invalid_argument when the text does not fit the kind (a bug of the writer).
std::string marked_text(const FileKind& kind, const std::string& text);

/// "" when `text` is a complete file of `kind` as Saltus wrote it (its mark names the kind and
/// its digest matches the rest); else why not, as a predicate for a message about the file
/// ("is not a body model Saltus wrote", "was changed since Saltus wrote it").
std::string unmarked_reason(const FileKind& kind, const std::string& text);

}  // namespace saltus
