#include "saltus/use_cases/motion_exports.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "saltus/base/input_error.h"
#include "saltus/base/text_format.h"
#include "saltus/capture/model_clip.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/formats/bvh_file.h"
#include "saltus/formats/finite_check.h"
#include "saltus/formats/flight_page_assets.h"
#include "saltus/formats/gltf_file.h"
#include "saltus/formats/mujoco_files.h"
#include "saltus/formats/opensim_files.h"
#include "saltus/formats/output_folder.h"
#include "saltus/motion/interpolate.h"
#include "saltus/use_cases/captures.h"
#include "saltus/use_cases/flag_bounds.h"
#include "saltus/use_cases/flight_page.h"

namespace saltus {

namespace {

namespace fs = std::filesystem;

/// The motion sampled for an export: states (positions, rates, accelerations) and what inverse
/// dynamics makes of them (segment poses, CoM, root wrench).
struct ExportSamples {
  std::vector<double> times;
  std::vector<BodyState<double>> states;
  std::vector<SampleRecord> records;
  double frame_time = 0.0;
};

ExportSamples sample_for_export(const MotionFile& motion, double fps, const std::string& source) {
  const double duration = motion.motion.flight_time();
  const double frames = motion_clip_frame_count(duration, fps);
  if (!(fps > 0) || !(frames * motion.model.size() <= kMaxExportSegmentPoses))
    throw InputError("--fps", "",
                     message_number(fps) + " frames per second over " + message_number(duration) +
                         " s would be more than an export holds (" +
                         message_number(kMaxExportSegmentPoses) +
                         " segment poses: frames × segments)");
  ExportSamples out;
  out.times = uniform_times(duration, static_cast<int>(frames));
  out.frame_time = duration / (frames - 1);
  const Trajectory<double> trajectory = motion_trajectory(motion.motion, motion.model);
  out.states.assign(out.times.size(), BodyState<double>(motion.model.size()));
  for (std::size_t k = 0; k < out.times.size(); ++k)
    trajectory.sample(out.times[k], out.states[k]);
  require_finite(out.states, out.times, source, "the exported motion's");
  out.records = evaluate_states(motion.model, out.times, out.states);
  require_finite(out.records, source, "the exported motion's");
  return out;
}

/// The result.json of a folder export: what was exported, from where, and how it was sampled.
nlohmann::json export_result_json(const std::string& format, const MotionFile& motion,
                                  const ExportSamples& samples, const std::string& source) {
  return {{"format", "saltus-export/1"},
          {"export", format},
          {"source", source},
          {"motion", motion.motion.name},
          {"model", motion.model.name},
          {"saltus_version", kSaltusVersion},
          {"frames", samples.times.size()},
          {"frame_time_s", samples.frame_time},
          {"duration_s", samples.times.back()}};
}

std::string result_text(const nlohmann::json& result, const std::string& source) {
  require_finite(result, source);
  return result.dump(2) + "\n";
}

std::vector<ExportFile> mujoco_files(const MotionFile& motion, const ExportSamples& samples,
                                     const std::string& source) {
  nlohmann::json result = export_result_json("mujoco", motion, samples, source);
  result["world"] = "z up: MuJoCo's x = Saltus's z, y = Saltus's x, z = Saltus's y";
  result["qpos"] = mujoco_qpos_names(motion.model);
  result["qvel"] = mujoco_qvel_names(motion.model);
  return {{"model.xml",
           mujoco_model_xml(motion.model, motion.motion.name, samples.times, samples.states)},
          {"trajectory.csv", mujoco_trajectory_csv(motion.model, samples.times, samples.states)},
          {"result.json", result_text(result, source)}};
}

std::vector<ExportFile> gltf_files(const MotionFile& motion, const ExportSamples& samples,
                                   const std::string&) {
  std::vector<Eigen::Vector3d> com;
  for (const SampleRecord& r : samples.records)
    com.push_back(r.com);
  return {{"flight.glb",
           gltf_binary(motion.model, motion.motion.name, samples.times, samples.states, com)}};
}

std::vector<ExportFile> opensim_files(const MotionFile& motion, const ExportSamples& samples,
                                      const std::string& source) {
  std::vector<OpensimFrame> frames;
  for (std::size_t k = 0; k < samples.times.size(); ++k)
    frames.push_back(opensim_frame(motion.model, samples.states[k], samples.records[k]));
  nlohmann::json result = export_result_json("opensim", motion, samples, source);
  result["opensim_format"] = "OpenSim 4.0 (Version 40000); not opened in OpenSim by Saltus's tests";
  nlohmann::json coordinates = nlohmann::json::array();
  for (const OpensimCoordinate& c : opensim_coordinates(motion.model))
    coordinates.push_back(c.name);
  result["coordinates"] = coordinates;
  return {{"model.osim", opensim_model_xml(motion.model, motion.motion.name)},
          {"coordinates.mot", opensim_coordinates_mot(motion.model, samples.times, frames)},
          {"inverse_dynamics.sto", opensim_forces_sto(motion.model, samples.times, frames)},
          {"result.json", result_text(result, source)}};
}

/// A sampled format: its files for a motion, its description for people, and what it writes
/// (output_kind.h): a folder format's FolderKind, recorded in the folder for the next run, or a
/// single-file format's FileKind.
struct SampledExport {
  std::function<std::vector<ExportFile>(const MotionFile&, const ExportSamples&,
                                        const std::string&)>
      files;
  std::function<std::string(const MotionFile&, const ExportSamples&)> description;
  FolderKind folder;
  FileKind file;
};

std::string frames_words(const ExportSamples& samples) {
  return std::to_string(samples.times.size()) + " frames at " + message_number(samples.frame_time) +
         " s (" + format_number("%.4g", 1.0 / samples.frame_time) + " fps)";
}

/// Every format, declared once: what people and flags see, and for the formats sampled here,
/// how they are written (BVH is written by use_cases/captures, the page by use_cases/flight_page).
struct FormatEntry {
  ExportFormat format;
  SampledExport exporter;
};

const std::vector<FormatEntry>& format_table() {
  static const std::vector<FormatEntry> table = {
      {{"bvh", "BVH (Blender and other animation tools)", ".bvh", true}, {}},
      {{"html", "web page (opens offline in any browser)", ".html", false}, {}},
      {{"mujoco", "MuJoCo (MJCF model, qpos/qvel/qacc trajectory)", "", true},
       {mujoco_files,
        [](const MotionFile& m, const ExportSamples& s) {
          return std::to_string(m.model.size()) + " bodies (model " + m.model.name +
                 "), a free joint and " + std::to_string(m.model.size() - 1) +
                 " ball joints, z up; " + frames_words(s) + " as keys and qpos, qvel, qacc";
        },
        {"export mujoco", {"result.json", "model.xml", "trajectory.csv"}},
        {}}},
      {{"gltf", "glTF 2.0 (.glb for Blender, three.js and web viewers)", ".glb", true},
       {gltf_files,
        [](const MotionFile& m, const ExportSamples& s) {
          return std::to_string(m.model.size()) + " nodes with their meshes (model " +
                 m.model.name + "), one animation of " + frames_words(s) +
                 ", the CoM's path; metres, y up";
        },
        {},
        gltf_file_kind()}},
      {{"opensim", "OpenSim 4 (.osim model, .mot coordinates, .sto joint moments)", "", true},
       {opensim_files,
        [](const MotionFile& m, const ExportSamples& s) {
          return std::to_string(m.model.size()) + " bodies (model " + m.model.name + "), " +
                 std::to_string(3 * m.model.size() + 3) +
                 " coordinates (the root free, every joint three rotations); " + frames_words(s) +
                 " in degrees, and the forces that drive them";
        },
        {"export opensim",
         {"result.json", "model.osim", "coordinates.mot", "inverse_dynamics.sto"}},
        {}}},
  };
  return table;
}

/// The writer of a format sampled here, or null (BVH, the page, an unknown name).
const SampledExport* sampled_export(const std::string& format) {
  for (const FormatEntry& entry : format_table())
    if (entry.format.name == format && entry.exporter.files) return &entry.exporter;
  return nullptr;
}

std::size_t file_size(const std::string& path) {
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  return ec ? 0 : static_cast<std::size_t>(size);
}

ExportSummary export_bvh(const MotionFile& motion, const std::string& out, double fps) {
  const MocapClip clip = export_motion_bvh(motion, out, fps);
  ExportSummary s;
  s.frames = clip.frame_count();
  s.frame_time = clip.frame_time;
  s.description = std::to_string(clip.joint_count()) + " joints (model " + motion.model.name +
                  "), " + std::to_string(clip.frame_count()) + " frames at " +
                  message_number(clip.frame_time) + " s (" +
                  format_number("%.4g", 1.0 / clip.frame_time) + " fps), cm, y up, ZXY channels";
  s.files = {out};
  return s;
}

ExportSummary export_sampled(const MotionFile& motion, const ExportFormat& format,
                             const std::string& out, double fps, const std::string& source) {
  const SampledExport* exporter = sampled_export(format.name);
  const ExportSamples samples = sample_for_export(motion, fps, source);
  const std::vector<ExportFile> files = exporter->files(motion, samples, source);
  ExportSummary s;
  s.frames = static_cast<int>(samples.times.size());
  s.frame_time = samples.frame_time;
  s.description = exporter->description(motion, samples);
  if (format.extension.empty()) {
    OutputFolder folder(out, exporter->folder);
    for (const ExportFile& f : files) {
      folder.write(f.name, f.contents);
      s.files.push_back((fs::path(out) / f.name).string());
    }
    folder.commit();
  } else {
    write_output_file(out, files.front().contents, exporter->file);
    s.files = {out};
  }
  return s;
}

/// A sampled format's export of a loaded motion; `source` as given, for result.json.
ExportSummary export_loaded(const MotionFile& motion, const ExportFormat& format,
                            const std::string& out, const ExportOptions& options,
                            const std::string& source) {
  if (!format.sampled)
    throw InputError("--format", "", format.name + " is exported from a file or folder");
  if (!options.capture.empty()) throw InputError("--capture", "", "applies to --format html only");
  if (options.fps) check_flag("--fps", *options.fps, "export");  // NaN, 0 once the default
  const double fps = options.fps ? *options.fps : default_export_fps(motion.motion);
  ExportSummary s = format.name == "bvh" ? export_bvh(motion, out, fps)
                                         : export_sampled(motion, format, out, fps, source);
  s.format = format.name;
  s.motion = motion.motion.name;
  s.model = motion.model.name;
  for (const std::string& f : s.files)
    s.bytes += file_size(f);
  return s;
}

}  // namespace

const std::vector<ExportFormat>& export_formats() {
  static const std::vector<ExportFormat> formats = [] {
    std::vector<ExportFormat> out;
    for (const FormatEntry& entry : format_table())
      out.push_back(entry.format);
    return out;
  }();
  return formats;
}

const ExportFormat& export_format(const std::string& name) {
  std::string known;
  for (const ExportFormat& f : export_formats()) {
    if (f.name == name) return f;
    known += (known.empty() ? "" : ", ") + f.name;
  }
  throw InputError("--format", "",
                   "unknown format \"" + message_text(name) + "\" (known: " + known + ")");
}

std::vector<ExportFile> export_files(const MotionFile& motion, const std::string& format,
                                     double fps, const std::string& source) {
  if (format == "bvh") return {{"flight.bvh", bvh_text(export_motion_clip(motion, fps))}};
  const SampledExport* exporter = sampled_export(format);
  if (!exporter) throw std::invalid_argument("export_files: not a sampled format: " + format);
  return exporter->files(motion, sample_for_export(motion, fps, source), source);
}

ExportSummary export_motion(const MotionFile& motion, const std::string& format_name,
                            const std::string& out, const ExportOptions& options) {
  return export_loaded(motion, export_format(format_name), out, options,
                       motion.path.empty() ? motion.motion.name : motion.path);
}

ExportSummary export_source(const std::string& source, const std::string& format_name,
                            const std::string& out, const ExportOptions& options) {
  const ExportFormat& format = export_format(format_name);
  if (format.sampled) {
    return export_loaded(load_export_source(source), format, out, options, source);
  }
  if (options.fps) throw InputError("--fps", "", "does not apply to --format " + format.name);
  const FlightPageSummary page = export_flight_page(source, out, options.capture);
  ExportSummary s;
  s.format = format.name;
  s.motion = page.motion;
  s.model = page.model;
  s.frames = page.frames;
  s.description = "a web page of " + page.motion + " (model " + page.model + "), " +
                  (page.optimised ? "before and after optimisation" : "as given") + ", " +
                  std::to_string(page.frames) + " frames, " +
                  format_number("%.2f", static_cast<double>(page.bytes) / 1e6) + " MB" +
                  (page.capture.empty() ? "" : "; the motion capture beside it: " + page.capture);
  s.files = {out};
  s.bytes = page.bytes;
  return s;
}

}  // namespace saltus
