#pragma once
/// @file
/// `saltus export`, the app's File > Export and the Python module's export: a motion written in
/// the formats other tools read, each declared once in export_formats(): BVH (animation tools),
/// the flight page (a browser), MuJoCo (MJCF and its qpos, qvel, qacc), glTF 2.0 (Blender,
/// three.js) and OpenSim (.osim, .mot, .sto). What each file holds: docs/formats.md.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "saltus/motion/motion.h"

namespace saltus {

/// One format `saltus export --format NAME` writes.
struct ExportFormat {
  std::string name;       ///< the --format value: "bvh", "html", "mujoco", "gltf", "opensim"
  std::string title;      ///< what it is and for whom, for --help and the app's menu
  std::string extension;  ///< of the output file (".bvh", ".glb"); "" when it is a folder
  bool sampled = true;    ///< the motion sampled at --fps (false: the page keeps its samples)
};

/// Every export format, in the order the app's menu lists them.
const std::vector<ExportFormat>& export_formats();

/// The format named `name`; InputError naming --format and the known names otherwise.
const ExportFormat& export_format(const std::string& name);

/// An export holds at most this many segment poses (frames × segments): 60 s at 60 frames per
/// second of a 64-segment model is 230,464, and the largest export (MuJoCo's) stays near 60 MB.
inline constexpr double kMaxExportSegmentPoses = 300000;

struct ExportOptions {
  /// frames per second (sampled formats only), a positive number when given (`--fps 0` is
  /// refused, not taken for the default); none: default_export_fps
  std::optional<double> fps;
  std::string capture;  ///< html: the capture drawn beside the athlete ("" = where it came from)
};

/// One file an export writes: its name (in the output folder, or the output file's own) and its
/// contents.
struct ExportFile {
  std::string name;
  std::string contents;
};

/// What an export wrote.
struct ExportSummary {
  std::string format;  ///< ExportFormat::name
  std::string motion;  ///< the motion's name
  std::string model;   ///< the body model's name
  int frames = 0;
  double frame_time = 0.0;         ///< s (0 for the page)
  std::string description;         ///< one line for people: what the files hold
  std::vector<std::string> files;  ///< the paths written
  std::size_t bytes = 0;           ///< their total size
};

/// The files of a sampled format (every format but html) for `motion`, in memory, sampled at
/// `fps` (> 0): round(T·fps) + 1 frames, the last at T. `source` is recorded in the folder
/// formats' result.json. InputError naming --fps for a rate that would hold more than
/// kMaxExportSegmentPoses; std::invalid_argument for a format that is not sampled.
std::vector<ExportFile> export_files(const MotionFile& motion, const std::string& format,
                                     double fps, const std::string& source);

/// `saltus export SOURCE --format FORMAT --out OUT`: SOURCE is what load_export_source reads
/// (html: what flight_page_data reads), written to `out` (a file, or a folder for the folder
/// formats) atomically, never over a file or folder Saltus did not write (docs/safety.md).
/// Bad input: InputError naming the file or flag.
ExportSummary export_source(const std::string& source, const std::string& format,
                            const std::string& out, const ExportOptions& options = {});

/// The same for a motion in memory (the app's): every sampled format.
ExportSummary export_motion(const MotionFile& motion, const std::string& format,
                            const std::string& out, const ExportOptions& options = {});

}  // namespace saltus
