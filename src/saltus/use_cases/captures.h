#pragma once
/// @file
/// Motion-capture files in and out: `saltus import` (a BVH file onto the body model, its output
/// folder), the motion verbs' `.bvh` arguments, and `saltus export --format bvh`.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "saltus/capture/capture_import.h"
#include "saltus/formats/motion_file.h"
#include "saltus/motion/motion.h"

namespace saltus {

/// The body model a capture is imported onto when none is given.
inline constexpr const char* kDefaultCaptureModel = "zatsiorsky-66kg";

struct CaptureFileOptions {
  std::string model;    ///< name under resources/models or a path; "" = kDefaultCaptureModel
  std::string mapping;  ///< "saltus-capture-mapping/1" file, "" = by joint names
  CaptureImportOptions import;
};

/// The options of `saltus import` from its flags as text: `model` and `mapping` as given,
/// `keyframes` a count >= 2, "all", or "" (the fewest whose interpolation meets every captured
/// frame within tolerance), `flight` "START:END" in seconds of the clip or "" (found from the
/// feet), `frame_time` seconds per frame within a capture's range (plausible_ranges.h) or none
/// (the file's). InputError naming --keyframes, --flight or --frame-time for anything else.
CaptureFileOptions capture_import_options(const std::string& model, const std::string& mapping,
                                          const std::string& keyframes, const std::string& flight,
                                          std::optional<double> frame_time);

/// A capture file imported onto a model.
struct CaptureFile {
  std::string path;             ///< the BVH file
  std::string mapping_path;     ///< "" when mapped by names
  std::string model_reference;  ///< as given (name or path)
  BodyModel model;
  MocapClip clip;
  CaptureImport import;
};

/// Reads the BVH file, the model and the mapping file and imports. Every problem with the input
/// is an InputError naming the file (and the line of the BVH file or the JSON path of the
/// mapping file).
CaptureFile import_capture_file(const std::string& path, const CaptureFileOptions& options = {});

/// import_capture_file's step after reading the files: `text`, a BVH capture's contents, imported
/// onto `model` with the same checks (messages name `path`, which also names the motion).
/// `options.model` only names the model in the outputs ("" = kDefaultCaptureModel); a mapping
/// file (`options.mapping`) is still read from disk.
CaptureFile import_capture_text(const std::string& text, const std::string& path,
                                const BodyModel& model, const CaptureFileOptions& options = {});

/// The capture's own trajectory on `model` (the model in use after its masses were edited; the
/// same segments), evaluated at the import's sample times: its samples and residual as the app
/// plots them. Everything else (clip, mapping, flight, keyframes) is the import's.
/// std::invalid_argument when the model's segments are not the capture's.
CaptureFile capture_on_model(const CaptureFile& capture, const BodyModel& model);

/// result.json of an import ("format": "saltus-result/1", "status": "imported").
nlohmann::json capture_result_json(const CaptureFile& capture);

/// The two motion files (captured flight, picked keyframes), naming the model by `model_field`.
nlohmann::json captured_motion_json(const CaptureFile& capture, const std::string& model_field);
nlohmann::json keyframes_motion_json(const CaptureFile& capture, const std::string& model_field);

/// Writes result.json, capture.motion.json, keyframes.motion.json, trajectory.csv and
/// model.json (the motion files name it, so the folder is self-contained) into `out_dir`
/// atomically. Returns the result.json written.
nlohmann::json write_capture_outputs(const std::string& out_dir, const CaptureFile& capture);

/// True for a path the motion verbs read as a capture (".bvh", any case).
bool is_capture_path(const std::string& path);

/// A motion file, or a capture imported with `capture_options` (its picked keyframes; the
/// defaults of `saltus import` unless given; their model is `model_override`), with its model.
/// `spin`: whether a motion file's take-off angular momentum is checked on that model
/// (formats/motion_file.h).
MotionFile load_motion_or_capture(const std::string& path, const std::string& model_override = "",
                                  const CaptureFileOptions& capture_options = {},
                                  SpinCheck spin = SpinCheck::kOnLoad);

/// What `saltus export` reads: a motion file, a capture, or a result folder of `optimize`
/// (optimized.motion.json) or `import` (capture.motion.json). InputError when a folder holds
/// neither.
MotionFile load_export_source(const std::string& path);

/// The default frame rate of an export: the keyframes' own rate when they are evenly spaced (a
/// captured flight exports its frames), else 60 frames per second.
double default_export_fps(const Motion& motion);

/// The clip export_motion_bvh writes: the motion's trajectory on the model's skeleton at about
/// `fps` frames per second (motion_clip). InputError naming --fps when fps <= 0 or the clip
/// would have more frames than kMaxBvhFrames (the BVH reader would refuse the file).
MocapClip export_motion_clip(const MotionFile& motion, double fps);

/// Writes the motion's trajectory as a BVH file on the model's skeleton (capture/model_clip.h),
/// atomically. Returns the clip written.
MocapClip export_motion_bvh(const MotionFile& motion, const std::string& out_path, double fps);

}  // namespace saltus
