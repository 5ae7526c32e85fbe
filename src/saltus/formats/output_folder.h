#pragma once
/// @file
/// Output folders that cannot destroy anything (README "What Saltus promises"; docs/safety.md).
///
/// A result is written into a hidden temporary sibling `.DIR.tmp-<pid>-<n>` and swapped into
/// place only when every file is complete, with one atomic renameat2(RENAME_EXCHANGE): at every
/// instant DIR is either the old or the new complete folder. An existing DIR is replaced only
/// when it is recognisably Saltus's own: it holds only what the record its writer left there
/// says Saltus wrote (the writer's FolderKind, output_kind.h). One run at a time
/// writes DIR (a lock on `.DIR.lock`, held from construction to commit); SIGINT, SIGTERM and
/// SIGHUP remove the temporary folder before the process ends, and the temporaries of runs that
/// died anyway (SIGKILL, power loss) are removed by the next run that writes DIR.

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "saltus/formats/output_kind.h"

namespace saltus {

/// The output could not be written for a reason outside the input: another run is writing the
/// same folder (busy()), or the system refused (disk full, no permission, read-only). Nothing was
/// changed. The CLI exits with status 4.
class OutputError : public std::runtime_error {
 public:
  OutputError(const std::string& message, bool busy) : std::runtime_error(message), busy_(busy) {}
  bool busy() const { return busy_; }

 private:
  bool busy_;
};

/// The name Saltus gives a sibling it makes beside the file or folder `name` (a lock, a
/// temporary, a study's DIR.partial): `lead + name + tag`, followed by up to `suffix_bytes` of a
/// run's suffix. Where that would exceed a file name's NAME_MAX (255) bytes, as for the longest
/// legal names, `name` is cut (on a character boundary) and followed by "~" and the digest of
/// the whole name (base/digest.h), so the sibling of one name is always the same, and siblings
/// of names that share their first 200 bytes differ.
std::string sibling_name(const std::string& name, const std::string& lead, const std::string& tag,
                         std::size_t suffix_bytes = 0);

/// Why `path` cannot name an output (a clause for a message naming the path or the flag): a name
/// in it longer than NAME_MAX bytes, which no Linux file system takes. "" when it can.
std::string output_name_problem(const std::string& path);

/// Why `folder` may not be replaced: "" when it is an empty folder or a Saltus result holding only
/// what its record (output_kind.h) says Saltus wrote there; otherwise what makes it someone
/// else's (a clause for a message).
std::string foreign_content(const std::string& folder);

/// Checks, without changing anything, that a result may be written to `final_path` (what the
/// OutputFolder constructor checks): front ends call it before a long computation. Throws
/// InputError saying why and how to proceed.
void check_output_folder(const std::string& final_path);

class OutputFolder {
 public:
  /// Takes the lock of `final_path`, removes temporaries of dead runs, checks the folder may be
  /// replaced and creates the temporary folder for a result of `kind` (what its writer writes).
  /// Creates missing parent folders. Throws InputError (bad --out: a file, a link, someone
  /// else's folder, a path that is not UTF-8), OutputError (busy, or the system refused).
  OutputFolder(std::string final_path, FolderKind kind);
  /// Removes the temporary folder unless commit() succeeded, and releases the lock.
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  /// Path of a file inside the temporary folder (for writers that open files themselves and for
  /// nested OutputFolders).
  std::string file(const std::string& name) const;
  /// Writes `text` to `name` inside the temporary folder. Throws
  /// OutputError naming DIR/name (not the temporary) and the system's reason.
  void write(const std::string& name, const std::string& text) const;
  /// Records the kind in the folder (kFolderRecordName), swaps the temporary folder into place
  /// (see the file comment), removes the old one, releases the lock. Throws InputError if DIR
  /// became someone else's meanwhile, OutputError if the system refused; either way DIR is
  /// unchanged. Throws std::logic_error (a bug of the writer) when the folder holds an entry its
  /// kind does not declare.
  void commit();

  const std::string& final_path() const { return final_path_; }

 private:
  void release();

  std::string final_path_;
  FolderKind kind_;
  std::string temporary_path_;
  std::string lock_path_;
  int lock_fd_ = -1;
  int slot_ = -1;  ///< interrupt-cleanup registration
  bool committed_ = false;
};

/// Writes `text` as the single file `path` of `kind` (export --out FILE, model files, flight
/// pages), with the kind's mark (marked_text, output_kind.h). The text goes to a hidden sibling
/// `.NAME.saltus-tmp-<pid>-<n>` (sibling_name) created with O_EXCL and O_NOFOLLOW (no planted link
/// is followed, no other run's file is reused) and is moved into place when complete, so at every
/// instant `path` is the old or the new complete file. An existing `path` is replaced only when it
/// is a regular file of `kind` as Saltus wrote it (unmarked_reason is ""; asked again just before
/// the move); a kind without a mark (BVH) never replaces a file: the move is renameat2
/// RENAME_NOREPLACE, or link + unlink where the file system lacks it. Missing parent folders are
/// created. Throws InputError when `path` may not be written (exit 2; also a path that is not
/// UTF-8, which Saltus could not read back), OutputError when the
/// system refuses (exit 4); either way nothing is left behind. Returns the bytes written.
std::size_t write_output_file(const std::string& path, const std::string& text,
                              const FileKind& kind);

/// Records `kind` in `dir` (kFolderRecordName): for a sub-folder written inside an OutputFolder
/// without one of its own (a report's convergence/), which the enclosing commit then checks
/// like any result. Throws OutputError as write_text.
void write_folder_record(const std::string& dir, const FolderKind& kind);

/// Writes `text` to `path`. Throws OutputError naming the file as it will
/// be once its OutputFolder is committed (DIR/name, not the hidden temporary) and the reason.
void write_text(const std::string& path, const std::string& text);

}  // namespace saltus
