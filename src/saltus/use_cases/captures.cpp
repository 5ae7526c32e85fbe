#include "saltus/use_cases/captures.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "saltus/base/constants.h"
#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/base/resources.h"
#include "saltus/base/text_format.h"
#include "saltus/capture/model_clip.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/formats/bvh_file.h"
#include "saltus/formats/capture_mapping_file.h"
#include "saltus/formats/finite_check.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/output_folder.h"
#include "saltus/formats/plausible_ranges.h"
#include "saltus/formats/result_json.h"
#include "saltus/formats/trajectory_csv.h"
#include "saltus/motion/interpolate.h"
#include "saltus/use_cases/flag_bounds.h"

namespace saltus {

namespace {

namespace fs = std::filesystem;

nlohmann::json vector_json(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

std::string resolve_model(const std::string& reference, const std::string& relative_to) {
  std::error_code ec;
  if (fs::exists(reference, ec)) return reference;  // the reader says if it is no file
  const std::string path = resolve_model_path(reference, relative_to);
  if (path.empty())
    throw InputError(reference, "",
                     "body model not found (a file, or a name under resources/models)");
  return path;
}

std::string lower(std::string s) {
  for (char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string channel_list(const MocapJoint& joint) {
  std::string out;
  for (MocapChannel c : joint.channels)
    out += std::string(out.empty() ? "" : " ") + mocap_channel_name(c);
  return out;
}

const char* drive_kind(SegmentDrive::Kind kind) {
  switch (kind) {
    case SegmentDrive::Kind::kJoint:
      return "joint";
    case SegmentDrive::Kind::kAverage:
      return "average";
    case SegmentDrive::Kind::kHalfway:
      return "halfway";
    case SegmentDrive::Kind::kFollows:
      return "follows parent";
  }
  return "?";
}

nlohmann::json skeleton_json(const MocapClip& clip) {
  nlohmann::json joints = nlohmann::json::array();
  for (const MocapJoint& joint : clip.joints) {
    nlohmann::json sites = nlohmann::json::array();
    for (const Eigen::Vector3d& site : joint.end_sites)
      sites.push_back(vector_json(site));
    joints.push_back({{"name", joint.name},
                      {"parent", joint.parent < 0 ? nlohmann::json(nullptr)
                                                  : nlohmann::json(clip.joints[joint.parent].name)},
                      {"offset", vector_json(joint.offset)},
                      {"channels", channel_list(joint)},
                      {"end_sites", sites}});
  }
  return joints;
}

Motion named_motion(Motion motion, const std::string& model_field) {
  motion.model = model_field;
  return motion;
}

/// The frame time used must be a capture's (plausible_ranges.h): named at its source, the
/// --frame-time flag or the file's "Frame Time:" line. 1e-300 made every frame coincide (NaN in
/// trajectory.csv), 1e300 overflowed the take-off state, 3600 took 45 s to import.
std::string frame_time_problem(double seconds) {
  const FlagBound& frame_time = flag_bound("--frame-time", "import");
  return bound_problem(frame_time.bound, seconds, frame_time.why);
}

void check_frame_time(const std::optional<double>& flag, double stated, const std::string& path,
                      const BvhSourceLines& lines) {
  const double used = flag.value_or(stated);
  const std::string problem = frame_time_problem(used);
  if (problem.empty()) return;
  if (flag) throw InputError("--frame-time", "", problem);
  throw InputError(path, "line " + std::to_string(lines.frame_time),
                   "Frame Time: " + problem + "; give the right one with --frame-time");
}

/// What in the capture a field of an imported motion comes from, for a message when the motion
/// reader refuses that field.
std::string capture_source_of(const std::string& pointer, const BvhSourceLines& lines,
                              bool frame_time_flag) {
  const std::string frame_time = frame_time_flag
                                     ? "--frame-time"
                                     : "Frame Time (line " + std::to_string(lines.frame_time) + ")";
  const auto has = [&](const char* part) { return pointer.find(part) != std::string::npos; };
  if (has("/root_position") || has("/com_position"))
    return "the root's position channels and OFFSETs in the capture's unit";
  if (has("/com_velocity"))
    return "the root's position channels and OFFSETs in the capture's unit, over the " + frame_time;
  if (has("/angular_momentum")) return "the joint rotations over the " + frame_time;
  if (has("/time")) return "the " + frame_time + " and the frame count";
  if (has("/rotations")) return "the joint rotation channels";
  return "the capture";
}

/// Saltus writes only what it reads back: the two motions of an import go through the motion
/// reader (a take-off CoM 343 km away or at 1357 m/s was written, then refused on reading).
/// A refusal names the capture and what in it caused the value.
void check_capture_readable(const CaptureFile& capture, const BvhSourceLines& lines,
                            bool frame_time_flag) {
  const std::pair<const char*, nlohmann::json> motions[] = {
      {"capture.motion.json", captured_motion_json(capture, "model.json")},
      {"keyframes.motion.json", keyframes_motion_json(capture, "model.json")}};
  for (const auto& [name, document] : motions) {
    require_finite(document, capture.path, name);
    try {
      parse_motion(document, name, capture.model);
    } catch (const InputError& e) {
      throw InputError(
          capture.path, "",
          "the imported flight would be a motion Saltus refuses to read (" + std::string(name) +
              ": " + e.json_path() + ": " + e.problem() + "); it comes from " +
              capture_source_of(e.json_path(), lines, frame_time_flag) + "; nothing was written");
    }
  }
  require_finite(capture_result_json(capture), capture.path);
  require_finite(capture.import.samples, capture.path, "trajectory.csv");
}

/// The InputError for a capture that cannot be imported, naming the part of the input at fault:
/// the line of the BVH file's skeleton or frames, the flag, the model or the mapping file.
InputError capture_input_error(const CaptureError& e, const CaptureFile& capture,
                               const CaptureFileOptions& options, const std::string& path,
                               const BvhSourceLines& lines) {
  const std::string problem = e.what();
  switch (e.part()) {
    case CapturePart::kSkeleton:
      return InputError(path, "line " + std::to_string(lines.skeleton), problem);
    case CapturePart::kFrames:
      return InputError(path, "line " + std::to_string(lines.motion), problem);
    case CapturePart::kFlightOption:
      return InputError("--flight", "", problem + " (" + path + ")");
    case CapturePart::kKeyframesOption:
      return InputError("--keyframes", "", problem + " (" + path + ")");
    case CapturePart::kModel:
      return InputError(capture.model_reference, "", problem + " (importing " + path + ")");
    case CapturePart::kMapping:
      return InputError(options.mapping.empty() ? path : options.mapping,
                        options.mapping.empty() ? "" : "/joints", problem);
  }
  return InputError(path, "", problem);
}

/// import_capture_file and import_capture_text after reading: `capture` holds the path, the
/// model and the clip read from the BVH text (`lines` where its fields were).
CaptureFile import_read_capture(CaptureFile capture, const BvhSourceLines& lines,
                                const CaptureFileOptions& options) {
  const std::string& path = capture.path;
  check_frame_time(options.import.frame_time, capture.clip.frame_time, path, lines);
  SkeletonMapping mapping;
  SkeletonMapping given;
  try {
    if (options.mapping.empty()) {
      mapping = guess_skeleton_mapping(capture.clip);
    } else {
      capture.mapping_path = options.mapping;
      given = load_capture_mapping(options.mapping);
      check_capture_mapping(given, capture.clip, options.mapping, path);
      mapping = merge_skeleton_mapping(capture.clip, given);
    }
    CaptureImportOptions import_options = options.import;
    if (import_options.name.empty()) import_options.name = fs::path(path).stem().string();
    if (!import_options.max_flight_time) import_options.max_flight_time = plausible::kMaxFlightTime;
    if (!import_options.max_flight_frames)
      import_options.max_flight_frames = plausible::kMaxCaptureFlightFrames;
    capture.import = import_capture(capture.clip, capture.model, mapping, import_options);
  } catch (const CaptureError& e) {
    throw capture_input_error(e, capture, options, path, lines);
  } catch (const MappingError& e) {
    // A mapping key the mapping file gave is named there (/joints/<key>); one guessed by name,
    // in the capture.
    if (!options.mapping.empty() && given.joints.count(e.key()))
      throw InputError(options.mapping, "/joints/" + json_pointer_escape(e.key()),
                       printable(e.what()) + " (in " + path + ")");
    throw InputError(path, "", printable(e.what()));
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    // A curve fit refusing its times ("fit_quaternion_spline: the knots must increase...", seen
    // with a frame time of 1e-300 before the range check) is the frames' times, not a bug.
    if (what.rfind("fit_", 0) == 0)
      throw InputError(path, "",
                       "the captured frames cannot be interpolated: their times (frames " +
                           message_number(capture.clip.frame_time) +
                           " s apart as stated, or --frame-time) do not increase");
    throw InputError(path, "", printable(what));
  }
  check_capture_readable(capture, lines, options.import.frame_time.has_value());
  return capture;
}

}  // namespace

CaptureFile import_capture_file(const std::string& path, const CaptureFileOptions& options) {
  CaptureFile capture;
  capture.path = path;
  capture.model_reference = options.model.empty() ? kDefaultCaptureModel : options.model;
  capture.model = load_body_model(resolve_model(capture.model_reference, path));
  BvhSourceLines lines;
  capture.clip = load_bvh_file(path, &lines);
  return import_read_capture(std::move(capture), lines, options);
}

CaptureFile import_capture_text(const std::string& text, const std::string& path,
                                const BodyModel& model, const CaptureFileOptions& options) {
  CaptureFile capture;
  capture.path = path;
  capture.model_reference = options.model.empty() ? kDefaultCaptureModel : options.model;
  capture.model = model;
  BvhSourceLines lines;
  capture.clip = parse_bvh(text, path, &lines);
  return import_read_capture(std::move(capture), lines, options);
}

CaptureFile capture_on_model(const CaptureFile& capture, const BodyModel& model) {
  bool same = model.segments.size() == capture.model.segments.size();
  for (std::size_t i = 0; same && i < model.segments.size(); ++i)
    same = model.segments[i].name == capture.model.segments[i].name;
  if (!same)
    throw std::invalid_argument("model " + model.name + " has other segments than the capture's " +
                                capture.model.name);
  CaptureFile out = capture;
  out.model = model;
  std::vector<double> times;
  times.reserve(capture.import.samples.size());
  for (const SampleRecord& s : capture.import.samples)
    times.push_back(s.time);
  out.import.samples = evaluate_trajectory(model, capture.import.trajectory, times);
  out.import.metrics = force_metrics(out.import.samples);
  return out;
}

nlohmann::json captured_motion_json(const CaptureFile& capture, const std::string& model_field) {
  return motion_to_json(named_motion(capture.import.captured, model_field), capture.model);
}

nlohmann::json keyframes_motion_json(const CaptureFile& capture, const std::string& model_field) {
  return motion_to_json(named_motion(capture.import.keyframes, model_field), capture.model);
}

nlohmann::json capture_result_json(const CaptureFile& capture) {
  const CaptureImport& im = capture.import;
  const Retargeting& rt = im.retargeting;
  const BodyModel& model = capture.model;
  nlohmann::json r;
  r["format"] = "saltus-result/1";
  r["status"] = "imported";
  r["capture_file"] = capture.path;
  r["model"] = model.name;

  const CaptureAxes& axes = rt.axes;
  r["source"] = {{"joints", im.source_joints},
                 {"frames", im.source_frames},
                 {"frame_time_stated_s", im.stated_frame_time},
                 {"frame_time_used_s", im.frame_time},
                 {"duration_s", (im.source_frames - 1) * im.frame_time},
                 {"unit", axes.unit},
                 {"unit_detected", axes.unit_detected},
                 {"metres_per_unit", axes.metres_per_unit},
                 {"rest_height_m", axes.rest_height_m},
                 {"up_axis", axes.up_name},
                 {"up_detected", axes.up_detected},
                 {"skeleton", skeleton_json(capture.clip)}};

  nlohmann::json segments = nlohmann::json::object();
  for (int s = 0; s < model.size(); ++s) {
    const SegmentDrive& drive = rt.drives[s];
    nlohmann::json joints = nlohmann::json::array();
    for (int j : drive.joints)
      joints.push_back(capture.clip.joints[j].name);
    nlohmann::json entry = {{"rule", drive_kind(drive.kind)},
                            {"source_joints", joints},
                            {"weights", drive.weights},
                            {"description", drive.description}};
    if (drive.along_bone) {
      entry["rest"] = "along the source bone";
      entry["rest_bone_to"] = drive.rest_direction_to;
      entry["rest_correction_deg"] =
          rotation_angle_between(drive.rest_correction, Eigen::Quaterniond::Identity()) *
          kDegreesPerRadian;
    } else {
      entry["rest"] = "upright (the source's rest pose)";
    }
    segments[model.segments[s].name] = entry;
  }
  nlohmann::json unused = nlohmann::json::array();
  for (const auto& [name, reason] : rt.unused_joints)
    unused.push_back({{"name", name}, {"reason", reason}});
  r["mapping"] = {
      {"convention", rt.mapping.convention},
      {"mapping_file", capture.mapping_path.empty() ? nlohmann::json(nullptr)
                                                    : nlohmann::json(capture.mapping_path)},
      {"pelvis", capture.clip.joints[rt.pelvis_joint].name},
      {"thorax", capture.clip.joints[rt.thorax_joint].name},
      {"segments", segments},
      {"unused_joints", unused}};
  r["heading"] = {{"yaw_deg", im.heading_yaw_deg}, {"rule", im.heading_rule}};

  const FlightPhase& f = im.flight;
  const double motion_start = f.first_frame * im.frame_time;
  r["flight"] = {
      {"method", f.method},
      {"first_frame", f.first_frame},
      {"last_frame", f.last_frame},
      {"frames", f.frame_count()},
      {"liftoff_s", f.liftoff_time},
      {"touchdown_s", f.touchdown_time},
      {"duration_s", f.touchdown_time - f.liftoff_time},
      {"motion_start_s", motion_start},
      {"motion_duration_s", im.captured.flight_time()},
      {"ground_height_m", {f.ground_height[0], f.ground_height[1]}},
      {"contact_rule",
       "a foot is on the ground when its lowest point (ankle, toes, End Sites) is within " +
           std::to_string(CaptureImportOptions{}.contact.height_tolerance_m) +
           " m of its ground level (the 20th percentile of its heights) in a stretch of low "
           "frames where it stands still at some frame (slower than " +
           std::to_string(CaptureImportOptions{}.contact.speed_tolerance_m_s) +
           " m/s); the flight is the longest stretch with both feet off; lift-off and "
           "touch-down interpolate where the lower foot crosses the contact height"}};

  const AngularMomentumSummary& l = im.angular_momentum;
  r["takeoff"] = {
      {"time_s", motion_start},
      {"com_position", vector_json(im.takeoff_fit.position)},
      {"com_velocity", vector_json(im.takeoff_fit.velocity)},
      {"com_fit",
       "parabola with g = 9.81 m/s² fixed, least squares over the flight frames' "
       "model CoM"},
      {"com_fit_rms_m", im.takeoff_fit.rms_residual_m},
      {"com_fit_max_m", im.takeoff_fit.max_residual_m},
      {"angular_momentum", vector_json(l.mean)},
      {"angular_momentum_std", vector_json(l.standard_deviation)},
      {"angular_momentum_max_deviation", l.max_deviation},
      {"angular_momentum_samples", l.samples},
      {"angular_momentum_rule",
       "time average over the flight of the angular momentum about the CoM from inverse "
       "dynamics of the interpolated capture with the model's masses (the capture's own "
       "trajectory, sampled as trajectory.csv)"}};
  r["gravity"] = {
      {"implied_m_s2", im.implied_gravity},
      {"free_fit_acceleration", vector_json(im.free_fit.acceleration)},
      {"free_fit_rms_m", im.free_fit.rms_residual_m},
      {"suggested_frame_time_s", im.suggested_frame_time ? nlohmann::json(*im.suggested_frame_time)
                                                         : nlohmann::json(nullptr)}};
  r["somersault_deg"] = {{"flight", im.somersault_flight_deg}, {"clip", im.somersault_clip_deg}};

  r["capture"] = {{"keyframes", im.captured.keyframes.size()},
                  {"samples", im.samples.size()},
                  {"residual", force_metrics_to_json(im.metrics)}};
  std::vector<int> clip_frames;
  std::vector<double> times;
  for (int k : im.pick.frames) {
    clip_frames.push_back(f.first_frame + k);
    times.push_back(im.captured.keyframes[k].time);
  }
  r["keyframes"] = {{"count", im.pick.frames.size()},
                    {"clip_frames", clip_frames},
                    {"times", times},
                    {"rule", im.pick.rule},
                    {"max_quaternion_error", im.pick.max_quaternion_error},
                    {"max_rotation_error_deg", im.pick.max_rotation_error_deg},
                    {"tolerances",
                     {{"translation_m", im.keyframes.tolerances.translation_m},
                      {"quaternion", im.keyframes.tolerances.quaternion}}},
                    {"before", force_metrics_to_json(im.keyframes_metrics)}};
  r["warnings"] = im.warnings;
  return r;
}

nlohmann::json write_capture_outputs(const std::string& out_dir, const CaptureFile& capture) {
  // What an import writes (output_kind.h), recorded in the folder for the next run to read.
  static const FolderKind kImportFolder{"import",
                                        {"result.json", "capture.motion.json",
                                         "keyframes.motion.json", "trajectory.csv", "model.json"}};
  const nlohmann::json result = capture_result_json(capture);
  OutputFolder folder(out_dir, kImportFolder);
  write_text(folder.file("capture.motion.json"),
             captured_motion_json(capture, "model.json").dump(2) + "\n");
  write_text(folder.file("keyframes.motion.json"),
             keyframes_motion_json(capture, "model.json").dump(2) + "\n");
  std::ostringstream csv;
  write_trajectory_csv(csv, capture.model, capture.import.samples);
  write_text(folder.file("trajectory.csv"), csv.str());
  write_text(folder.file("model.json"), body_model_to_json(capture.model).dump(2) + "\n");
  write_text(folder.file("result.json"), result.dump(2) + "\n");
  folder.commit();
  return result;
}

bool is_capture_path(const std::string& path) {
  return lower(fs::path(path).extension().string()) == ".bvh";
}

namespace {

/// A whole-string number, or InputError naming the flag.
double flag_number(const std::string& text, const std::string& flag) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v))
    throw InputError(flag, "", "expected a number, found \"" + message_text(text) + "\"");
  return v;
}

}  // namespace

CaptureFileOptions capture_import_options(const std::string& model, const std::string& mapping,
                                          const std::string& keyframes, const std::string& flight,
                                          std::optional<double> frame_time) {
  CaptureFileOptions o;
  o.model = model;
  o.mapping = mapping;
  if (keyframes == "all") {
    o.import.all_keyframes = true;
  } else if (!keyframes.empty()) {
    const double n = flag_number(keyframes, "--keyframes");
    check_flag("--keyframes", n, "import");
    o.import.keyframe_count = static_cast<int>(n);
  }
  if (!flight.empty()) {
    const std::size_t colon = flight.find(':');
    if (colon == std::string::npos)
      throw InputError("--flight", "",
                       "expected START:END in seconds, found \"" + message_text(flight) + "\"");
    const double start = flag_number(flight.substr(0, colon), "--flight");
    const double end = flag_number(flight.substr(colon + 1), "--flight");
    if (!(start < end))
      throw InputError("--flight", "",
                       "START must be before END: \"" + message_text(flight) + "\"");
    o.import.flight = std::make_pair(start, end);
  }
  // Refused before the file is read, as check_frame_time would after (0 was once the file's).
  if (frame_time && !frame_time_problem(*frame_time).empty())
    throw InputError("--frame-time", "", frame_time_problem(*frame_time));
  if (frame_time) o.import.frame_time = *frame_time;
  return o;
}

MotionFile load_motion_or_capture(const std::string& path, const std::string& model_override,
                                  const CaptureFileOptions& capture_options, SpinCheck spin) {
  if (!is_capture_path(path)) return load_motion_file(path, model_override, spin);
  CaptureFileOptions options = capture_options;
  options.model = model_override;
  const CaptureFile capture = import_capture_file(path, options);
  MotionFile out;
  out.path = path;
  out.model = capture.model;
  out.motion = capture.import.keyframes;
  out.motion.model = capture.model_reference;
  return out;
}

MotionFile load_export_source(const std::string& path) {
  if (!fs::is_directory(path)) return load_motion_or_capture(path);
  for (const char* name : {"optimized.motion.json", "capture.motion.json"}) {
    const fs::path candidate = fs::path(path) / name;
    if (fs::is_regular_file(candidate)) return load_motion_file(candidate.string());
  }
  throw InputError(path, "",
                   "the folder holds no optimized.motion.json (saltus optimize) or "
                   "capture.motion.json (saltus import)");
}

double default_export_fps(const Motion& motion) {
  const auto& k = motion.keyframes;
  if (k.size() >= 3) {
    const double step = k[1].time - k[0].time;
    bool even = step > 0;
    for (std::size_t i = 1; even && i < k.size(); ++i)
      even = std::abs((k[i].time - k[i - 1].time) - step) <= 1e-9 * std::max(1.0, step);
    if (even) return 1.0 / step;
  }
  return 60.0;
}

MocapClip export_motion_clip(const MotionFile& motion, double fps) {
  // What Saltus writes it reads back: no more frames than the BVH reader takes (--fps 1e6 wrote
  // 836 MB using 3.6 GB; 1e9 ended in bad_alloc), counted as motion_clip counts them (rounded:
  // a count floored here let 100001 frames through).
  const double frames = motion_clip_frame_count(motion.motion.flight_time(), fps);
  if (!(fps > 0) || !(frames <= kMaxBvhFrames))
    throw InputError("--fps", "",
                     message_number(fps) + " frames per second over " +
                         message_number(motion.motion.flight_time()) + " s would be more than " +
                         std::to_string(kMaxBvhFrames) +
                         " frames, the most a BVH file Saltus reads may hold");
  const Trajectory<double> trajectory = motion_trajectory(motion.motion, motion.model);
  MocapClip clip = motion_clip(motion.model, trajectory, fps);
  // Nor frames further apart or closer than `import` reads (check_frame_time's bounds).
  if (!(clip.frame_time >= plausible::kMinCaptureFrameTime &&
        clip.frame_time <= plausible::kMaxCaptureFrameTime))
    throw InputError("--fps", "",
                     message_number(fps) + " frames per second give frames " +
                         message_number(clip.frame_time) + " s apart, outside the [" +
                         message_number(plausible::kMinCaptureFrameTime) + ", " +
                         message_number(plausible::kMaxCaptureFrameTime) +
                         "] s a BVH file Saltus reads back may have (1 to 1000 frames per second)");
  return clip;
}

MocapClip export_motion_bvh(const MotionFile& motion, const std::string& out_path, double fps) {
  const MocapClip clip = export_motion_clip(motion, fps);
  save_bvh_file(out_path, clip);
  return clip;
}

}  // namespace saltus
