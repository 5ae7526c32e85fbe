#pragma once
/// @file
/// All-or-nothing output folders: files are written into a hidden temporary sibling folder and
/// the folder is renamed into place only when every file is complete, so an error or a crash
/// never leaves a half-written result behind.

#include <string>

namespace saltus {

class OutputFolder {
 public:
  /// Prepares a temporary folder next to `final_path`. Throws InputError if `final_path`
  /// exists and is a file, or a non-empty folder that holds no Saltus result (no result.json):
  /// we replace earlier results, never a user's other files.
  explicit OutputFolder(std::string final_path);
  /// Removes the temporary folder unless commit() succeeded.
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  /// Path of a file inside the temporary folder.
  std::string file(const std::string& name) const;
  /// Moves the temporary folder to the final path (replacing an earlier result there).
  void commit();

  const std::string& final_path() const { return final_path_; }

 private:
  std::string final_path_;
  std::string temporary_path_;
  bool committed_ = false;
};

}  // namespace saltus

namespace saltus {

/// Writes `text` to `path` (inside an OutputFolder); throws std::runtime_error naming the file
/// if it cannot be written completely.
void write_text(const std::string& path, const std::string& text);

}  // namespace saltus
