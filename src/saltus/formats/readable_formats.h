#pragma once
/// @file
/// Everything Saltus reads, one entry per format with its name patterns and, where the format
/// has one, its content check (as F3D declares each reader once with its extensions). File
/// dialogs take their filters from here and drag-and-drop asks identify_readable what a path
/// is. A new format is one ReadableKind and one entry in readable_formats.cpp.

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace saltus {

enum class ReadableKind {
  kModel,            ///< body model, "saltus-model/1" (formats/model_file.h)
  kMotion,           ///< keyframed motion, "saltus-motion/1" (formats/motion_file.h)
  kCapture,          ///< BVH motion capture (use_cases/captures.h: load_motion_or_capture)
  kMassStudyFolder,  ///< `saltus study mass` output folder (formats/mass_files.h)
  kResultFolder,     ///< `saltus evaluate`/`simulate`/`optimize` output folder (result_json.h)
};

struct ReadableFormat {
  ReadableKind kind;
  std::string name;  ///< what a dialog calls it, plural: "Motions"
  /// File-name patterns, the format's own first ("*.motion.json", then "*.json"); none for
  /// folders.
  std::vector<std::string> patterns;
  bool folder = false;  ///< a folder, picked with a folder dialog
  /// Whether `path` holds this format: its name matches and, where the format has a tag, the
  /// file says so. Quick enough to ask while something is dragged over a window.
  std::function<bool(const std::string& path)> recognises;
};

/// Every readable format, in the order identify_readable tries them (a format recognised by
/// its content before one recognised by its name alone).
const std::vector<ReadableFormat>& readable_formats();
const ReadableFormat& readable_format(ReadableKind kind);

/// The first format that recognises `path`; none when Saltus cannot read it.
std::optional<ReadableKind> identify_readable(const std::string& path);

/// "Motions (*.motion.json *.json)": the filter text of an open dialog (Qt, GTK).
std::string dialog_filter(ReadableKind kind);
/// "Motions (*.motion.json)": the format's own pattern only, for a save dialog.
std::string save_dialog_filter(ReadableKind kind);

/// Whether a file name matches a pattern such as "*.motion.json" ('*' any run of characters,
/// letters compared without case).
bool matches_pattern(const std::string& file_name, const std::string& pattern);

}  // namespace saltus
