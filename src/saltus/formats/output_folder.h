#pragma once
/// @file
/// Output folders that cannot destroy anything (README "What Saltus promises"; docs/safety.md).
///
/// A result is written into a hidden temporary sibling `.DIR.tmp-<pid>-<n>` and swapped into
/// place only when every file is complete, with one atomic renameat2(RENAME_EXCHANGE): at every
/// instant DIR is either the old or the new complete folder. An existing DIR is replaced only
/// when it is recognisably Saltus's own: its result.json has a Saltus format tag and it holds
/// only the files Saltus writes for that kind of result (result_kinds()). One run at a time
/// writes DIR (a lock on `.DIR.lock`, held from construction to commit); SIGINT, SIGTERM and
/// SIGHUP remove the temporary folder before the process ends, and the temporaries of runs that
/// died anyway (SIGKILL, power loss) are removed by the next run that writes DIR.

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

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

/// One kind of result folder: how its result.json is recognised and what Saltus writes in it.
struct ResultKind {
  std::string name;    ///< "evaluate", "simulate", "optimize", "study mass", ...
  std::string format;  ///< result.json "format"
  /// A result.json field that tells kinds of one format apart and the values that mean this
  /// kind; an empty value list matches any value (the kind is tried after the others).
  std::string field;
  std::vector<std::string> values;
  std::vector<std::string> files;  ///< regular files Saltus writes there
  /// Sub-folders that may hold only PNG images (the paper report's figures/).
  std::vector<std::string> image_folders;
  /// Sub-folders that may hold only a study's case records, NNNN.json (a study's cases/).
  std::vector<std::string> record_folders;
  /// Any other sub-folder must itself be a Saltus result (the paper report's M1/, mass/, ...).
  bool holds_results = false;
};

/// Every kind of result folder Saltus writes, in one place. A verb that writes a new file adds
/// it here, or its next run refuses to replace the folder.
const std::vector<ResultKind>& result_kinds();

/// Why `folder` may not be replaced: "" when it is an empty folder or a Saltus result holding only
/// files Saltus writes; otherwise what makes it someone else's (a sentence for a message).
std::string foreign_content(const std::string& folder);

/// Checks, without changing anything, that a result may be written to `final_path` (what the
/// OutputFolder constructor checks): front ends call it before a long computation. Throws
/// InputError saying why and how to proceed.
void check_output_folder(const std::string& final_path);

class OutputFolder {
 public:
  /// Takes the lock of `final_path`, removes temporaries of dead runs, checks the folder may be
  /// replaced and creates the temporary folder. Creates missing parent folders. Throws
  /// InputError (bad --out: a file, a link, someone else's folder), OutputError (busy, or the
  /// system refused).
  explicit OutputFolder(std::string final_path);
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
  /// Swaps the temporary folder into place (see the file comment), removes the old one, releases
  /// the lock. Throws InputError if the folder became someone else's meanwhile, OutputError if
  /// the system refused; either way DIR is unchanged.
  void commit();

  const std::string& final_path() const { return final_path_; }

 private:
  void release();

  std::string final_path_;
  std::string temporary_path_;
  std::string lock_path_;
  int lock_fd_ = -1;
  int slot_ = -1;  ///< interrupt-cleanup registration
  bool committed_ = false;
};

/// Says whether the existing regular file `path` is one Saltus wrote and may replace: "" if so,
/// else why not (the problem of the InputError, e.g. "exists and is not a flight page Saltus
/// wrote; ...").
using OwnFileCheck = std::function<std::string(const std::string& path)>;

/// Writes `text` as the single file `path` (export --out FILE, model files, flight pages). The
/// text goes to a hidden sibling `.NAME.saltus-tmp-<pid>-<n>` created with O_EXCL and O_NOFOLLOW
/// (no planted link is followed, no other run's file is reused) and is moved into place when
/// complete, so at every instant `path` is the old or the new complete file. An existing `path`
/// is replaced only when `own` says Saltus wrote it (a regular file; asked again just before the
/// move); without `own` (a BVH has no room for a tag) never: the move is renameat2
/// RENAME_NOREPLACE, or link + unlink where the file system lacks it. Missing parent folders are
/// created. Throws InputError when `path` may not be written (exit 2), OutputError when the
/// system refuses (exit 4); either way nothing is left behind.
void write_output_file(const std::string& path, const std::string& text,
                       const OwnFileCheck& own = {});

/// The check for files of one of Saltus's JSON formats: an existing file may be replaced when
/// it is a regular JSON file whose "format" is `format` (a model or motion file Saltus wrote);
/// otherwise the reason names it, e.g. "exists and is not a Saltus body model (...); Saltus
/// replaces only body models it wrote: ...". `what` is "body model" or "motion".
OwnFileCheck own_saltus_json_file(const std::string& format, const std::string& what);

/// write_output_file that never replaces anything: `path` must not exist.
void write_new_file(const std::string& path, const std::string& text);

/// Writes `text` to `path`. Throws OutputError naming the file as it will
/// be once its OutputFolder is committed (DIR/name, not the hidden temporary) and the reason.
void write_text(const std::string& path, const std::string& text);

}  // namespace saltus
