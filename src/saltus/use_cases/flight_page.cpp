#include "saltus/use_cases/flight_page.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <optional>

#include "saltus/base/constants.h"
#include "saltus/base/input_error.h"
#include "saltus/base/resources.h"
#include "saltus/body/drawn_parts.h"
#include "saltus/evaluation/apparatus.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/formats/finite_check.h"
#include "saltus/formats/flight_page.h"
#include "saltus/formats/flight_page_assets.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/result_json.h"
#include "saltus/formats/trajectory_csv.h"
#include "saltus/motion/interpolate.h"
#include "saltus/use_cases/captures.h"

namespace saltus {

namespace {

namespace fs = std::filesystem;

/// Points of the drawn CoM parabola.
constexpr int kParabolaPoints = 81;

/// `value` rounded to `digits` significant digits: the page's trajectories need no more (0.1 mm
/// at 5 m for 6 digits), and short numbers keep the page small. The figures of the title block
/// are copied from result.json unrounded.
double rounded(double value, int digits) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return std::strtod(text, nullptr);
}

nlohmann::json page_vector(const Eigen::Vector3d& v, int digits = 17) {
  return {rounded(v.x(), digits), rounded(v.y(), digits), rounded(v.z(), digits)};
}

/// Height of the body standing with every joint at rest (rotations identity): from the lowest
/// to the highest point of the drawing shapes, m. The page's cameras frame this height.
double standing_height(const BodyModel& model) {
  std::vector<Eigen::Vector3d> origin(model.segments.size(), Eigen::Vector3d::Zero());
  double top = -1e9, bottom = 1e9;
  auto extend = [&](double y) {
    top = std::max(top, y);
    bottom = std::min(bottom, y);
  };
  for (std::size_t i = 0; i < model.segments.size(); ++i) {
    const Segment& s = model.segments[i];
    if (s.parent >= 0) origin[i] = origin[static_cast<std::size_t>(s.parent)] + s.joint_position;
    const double y = origin[i].y();
    if (s.shape.parts.empty()) {
      extend(y + std::min(0.0, s.shape.length) - s.shape.radius);
      extend(y + std::max(0.0, s.shape.length) + s.shape.radius);
    }
    for (const ShapePart& p : s.shape.parts) {
      const double half = p.type == "capsule" ? 0.5 * std::abs(p.length) + p.radius : p.radii.y();
      extend(y + p.center.y() - half);
      extend(y + p.center.y() + half);
    }
  }
  return top > bottom ? top - bottom : 1.8;
}

/// Every segment's drawing as a list of parts (a segment without parts is one capsule from its
/// origin along y, as the app draws it), each with its colour.
nlohmann::json model_json(const BodyModel& model) {
  nlohmann::json segments = nlohmann::json::array();
  for (const Segment& s : model.segments) {
    nlohmann::json parts = nlohmann::json::array();
    for (const DrawnPart& drawn : drawn_parts(s)) {
      const ShapePart& part = drawn.shape;
      nlohmann::json p = {{"name", part.name},
                          {"type", part.type},
                          {"center", page_vector(part.center)},
                          {"colour", hex_colour(drawn.colour)}};
      if (part.type == "capsule") {
        p["length"] = std::abs(part.length);
        p["radius"] = part.radius;
      } else {
        p["radii"] = page_vector(part.radii);
      }
      parts.push_back(p);
    }
    segments.push_back({{"name", s.name}, {"parent", s.parent}, {"parts", parts}});
  }
  return {{"name", model.name},
          {"mass_kg", model.total_mass()},
          {"standing_height_m", standing_height(model)},
          {"segments", segments}};
}

/// The indices of at most kFlightPageMaxFrames samples, evenly spread, first and last kept.
std::vector<std::size_t> kept_frames(std::size_t count) {
  std::vector<std::size_t> out;
  const std::size_t limit = static_cast<std::size_t>(kFlightPageMaxFrames);
  if (count <= limit) {
    for (std::size_t i = 0; i < count; ++i)
      out.push_back(i);
    return out;
  }
  for (std::size_t k = 0; k < limit; ++k)
    out.push_back((k * (count - 1)) / (limit - 1));
  return out;
}

/// One trajectory: per frame its time, every segment's origin (x, y, z) and world-from-segment
/// rotation (w, x, y, z), the CoM, the residual (world force and moment about the CoM, for the
/// arrows), and |F1..3| and |F4..6| of the root wrench (root frame, root origin: what the app
/// plots); all flat arrays, frame after frame.
nlohmann::json stage_json(const std::string& label, const std::vector<SampleRecord>& samples,
                          const std::vector<double>& keyframe_times) {
  nlohmann::json t = nlohmann::json::array(), pos = nlohmann::json::array(),
                 quat = nlohmann::json::array(), com = nlohmann::json::array(),
                 res = nlohmann::json::array(), force = nlohmann::json::array(),
                 moment = nlohmann::json::array();
  for (std::size_t i : kept_frames(samples.size())) {
    const SampleRecord& s = samples[i];
    t.push_back(s.time);
    for (std::size_t k = 0; k < s.segment_position.size(); ++k) {
      for (int c = 0; c < 3; ++c)
        pos.push_back(rounded(s.segment_position[k][c], 6));
      const Eigen::Quaterniond& q = s.segment_rotation[k];
      for (double v : {q.w(), q.x(), q.y(), q.z()})
        quat.push_back(rounded(v, 6));
    }
    for (int c = 0; c < 3; ++c)
      com.push_back(rounded(s.com[c], 6));
    for (int c = 0; c < 6; ++c)
      res.push_back(rounded(s.residual[c], 5));
    force.push_back(rounded(s.root_wrench.head<3>().norm(), 6));
    moment.push_back(rounded(s.root_wrench.tail<3>().norm(), 6));
  }
  return {{"label", label},
          {"t", t},
          {"pos", pos},
          {"quat", quat},
          {"com", com},
          {"res", res},
          {"force_N", force},
          {"moment_Nm", moment},
          {"keyframes", keyframe_times}};
}

nlohmann::json parabola_json(const Takeoff& takeoff, double duration) {
  nlohmann::json points = nlohmann::json::array();
  for (int i = 0; i < kParabolaPoints; ++i) {
    const double t = duration * i / (kParabolaPoints - 1);
    for (double v : page_vector(ballistic_com(takeoff, t), 6))
      points.push_back(v);
  }
  return points;
}

nlohmann::json apparatus_json(const BodyModel& model, const Takeoff& takeoff,
                              const std::vector<SampleRecord>& samples) {
  const Apparatus a = apparatus_for(model, takeoff, samples);
  return {{"kind", a.kind == ApparatusKind::kPlatform ? "platform" : "trampoline"},
          {"takeoff_height_m", a.takeoff_height},
          {"landing_height_m", a.landing_height},
          {"takeoff_point", page_vector(a.takeoff_point)},
          {"direction", page_vector(a.direction)},
          // The sizes the app draws and the clearances are measured against, so the page cannot
          // draw another apparatus.
          {"sizes",
           {{"bed_length", kBedLength},
            {"bed_width", kBedWidth},
            {"bed_thickness", kBedThickness},
            {"frame_length", kFrameLength},
            {"frame_width", kFrameWidth},
            {"frame_thickness", kFrameThickness},
            {"frame_top", kFrameTop},
            {"platform_width", kPlatformWidth},
            {"platform_length", kPlatformLength},
            {"platform_thickness", kPlatformThickness},
            {"platform_edge_ahead", kPlatformEdgeAhead},
            {"pillar_side", kPillarSide}}}};
}

/// The settings of result.json the title block lists, those present.
nlohmann::json settings_json(const nlohmann::json& result) {
  nlohmann::json out = nlohmann::json::object();
  for (const char* key :
       {"status", "formulation", "epsilon", "knots_per_interval", "timing_optimized", "samples",
        "keyframes", "flight_time_s", "iterations", "solve_seconds"})
    if (result.contains(key) && !result[key].is_null()) out[key] = result[key];
  return out;
}

nlohmann::json read_result_document(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot be read");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path, "", std::string("not JSON: ") + e.what());
  }
}

/// True when `dir` is a folder `saltus import` wrote: result.json with "status": "imported",
/// trajectory.csv and capture.motion.json.
bool is_import_folder(const fs::path& dir) {
  if (!fs::is_regular_file(dir / "result.json") || !fs::is_regular_file(dir / "trajectory.csv") ||
      !fs::is_regular_file(dir / "capture.motion.json"))
    return false;
  std::ifstream in(dir / "result.json");
  const nlohmann::json result = nlohmann::json::parse(in, nullptr, false);
  return result.is_object() && result.value("status", "") == "imported";
}

/// The capture a motion file came from: a capture itself, or the `import` folder it lies in;
/// "" when neither.
std::string capture_of_motion_file(const std::string& path) {
  if (is_capture_path(path)) return fs::is_regular_file(path) ? path : "";
  const fs::path folder = fs::path(path).parent_path();
  return is_import_folder(folder.empty() ? fs::path(".") : folder) ? folder.string() : "";
}

/// A capture's own trajectory (its residual evaluated densely, as trajectory.csv holds it) and
/// its residual figures.
struct CaptureTrajectory {
  std::string source;  ///< the `import` folder or the BVH file
  std::string file;    ///< what errors name: trajectory.csv or the BVH file
  std::vector<std::string> segments;
  std::vector<SampleRecord> samples;
  nlohmann::json residual;
};

CaptureTrajectory capture_from_import(const std::string& source, const CaptureFile& capture) {
  CaptureTrajectory out;
  out.source = source;
  out.file = source;
  for (const Segment& s : capture.model.segments)
    out.segments.push_back(s.name);
  out.samples = capture.import.samples;
  out.residual = force_metrics_to_json(capture.import.metrics);
  return out;
}

/// The capture at `source` (an `import` folder, or a BVH file imported onto `model_reference`
/// with the default options). InputError naming `what_names` when it is neither.
CaptureTrajectory load_capture(const std::string& source, const std::string& model_reference,
                               const std::string& what_names) {
  if (fs::is_directory(source)) {
    if (!is_import_folder(source))
      throw InputError(what_names, "",
                       source +
                           " is not a folder saltus import wrote (result.json with \"status\": "
                           "\"imported\", trajectory.csv, capture.motion.json)");
    CaptureTrajectory out;
    out.source = source;
    out.file = (fs::path(source) / "trajectory.csv").string();
    TrajectoryCsv csv = read_trajectory_csv(out.file);
    out.segments = std::move(csv.segments);
    out.samples = std::move(csv.samples);
    const std::string result_path = (fs::path(source) / "result.json").string();
    const nlohmann::json result = read_result_document(result_path);
    const nlohmann::json* residual =
        result.contains("capture") ? &result["capture"] : static_cast<nlohmann::json*>(nullptr);
    if (!residual || !residual->contains("residual") || !(*residual)["residual"].is_object())
      throw InputError(result_path, "/capture/residual", "is missing");
    out.residual = (*residual)["residual"];
    return out;
  }
  if (is_capture_path(source)) {
    CaptureFileOptions options;
    options.model = model_reference;
    return capture_from_import(source, import_capture_file(source, options));
  }
  throw InputError(what_names, "",
                   source + " is neither an import folder nor a motion capture (.bvh)");
}

/// The page's "capture": the capture's trajectory as a stage (thinned as the athlete's) with
/// its source and residual figures. Its segments must be the athlete's.
nlohmann::json capture_json(const CaptureTrajectory& capture, const BodyModel& model) {
  bool same = capture.segments.size() == model.segments.size();
  for (std::size_t i = 0; same && i < model.segments.size(); ++i)
    same = capture.segments[i] == model.segments[i].name;
  if (!same)
    throw InputError(capture.file, "",
                     "its segments are not those of the athlete's model " + model.name);
  if (capture.samples.size() < 2) throw InputError(capture.file, "", "holds fewer than 2 samples");
  nlohmann::json out = stage_json("capture", capture.samples, {});
  out["source"] = capture.source;
  out["residual"] = capture.residual;
  return out;
}

/// The page's data from a `saltus optimize` folder: its files as written; the capture `capture`
/// names, else the one its motion came from.
nlohmann::json optimize_folder_data(const std::string& dir, const std::string& capture) {
  const ResultFolder folder = read_result_folder(dir);
  if (!folder.after)
    throw InputError((fs::path(dir) / "result.json").string(), "/after",
                     "the folder holds no optimised motion");
  const std::string motion_path = (fs::path(dir) / "optimized.motion.json").string();
  const MotionFile after = load_motion_file(motion_path);
  const nlohmann::json result = read_result_document((fs::path(dir) / "result.json").string());
  for (const TrajectoryCsv* csv : {&folder.before, &*folder.after})
    if (csv->segments.size() != after.model.segments.size())
      throw InputError((fs::path(dir) / "trajectory_before.csv").string(), "",
                       "its segments are not those of the folder's model.json");
  nlohmann::json data;
  data["kind"] = "optimize";
  data["motion"] = folder.result.motion;
  data["model"] = model_json(after.model);
  data["settings"] = settings_json(result);
  data["residual"] = {{"before", result.at("before")}, {"after", result.at("after")}};
  data["body_weight_N"] =
      folder.result.body_weight_N.value_or(after.model.total_mass() * kStandardGravity);
  data["duration_s"] = folder.result.flight_time_s;
  data["stages"] = nlohmann::json::array(
      {stage_json("before", folder.before.samples, folder.result.keyframe_times_before),
       stage_json("after", folder.after->samples,
                  folder.result.optimization->keyframe_times_after)});
  data["parabola"] = parabola_json(after.motion.takeoff, folder.result.flight_time_s);
  data["apparatus"] = apparatus_json(after.model, after.motion.takeoff, folder.after->samples);
  const std::string found =
      capture.empty() ? capture_of_motion_file(folder.result.motion_file) : capture;
  if (!found.empty())
    data["capture"] = capture_json(
        load_capture(found, (fs::path(dir) / "model.json").string(),
                     capture.empty() ? (fs::path(dir) / "result.json").string() : "--capture"),
        after.model);
  return data;
}

/// The model a capture is imported onto beside `file`: the one its motion names, found as the
/// motion verbs find it, else the model's name.
std::string motion_model_reference(const MotionFile& file) {
  const std::string path =
      file.path.empty() ? "" : resolve_model_path(file.motion.model, file.path);
  return path.empty() ? file.model.name : path;
}

/// The page's data from a motion, a capture (its picked keyframes) or an `import` folder (its
/// keyframes.motion.json), evaluated as `evaluate` does, with the capture `capture` names, else
/// the one the source came from.
nlohmann::json motion_data(const std::string& source, const std::string& capture) {
  MotionFile file;
  std::optional<CaptureTrajectory> own;
  if (fs::is_directory(source) && is_import_folder(source)) {
    file = load_motion_file((fs::path(source) / "keyframes.motion.json").string());
  } else if (!fs::is_directory(source) && is_capture_path(source)) {
    // As load_motion_or_capture reads it, keeping the import for the capture's figure.
    const CaptureFile imported = import_capture_file(source);
    file.path = source;
    file.model = imported.model;
    file.motion = imported.import.keyframes;
    file.motion.model = imported.model_reference;
    if (capture.empty()) own = capture_from_import(source, imported);
  } else {
    file = load_export_source(source);
  }
  const MotionEvaluation evaluation = evaluate_motion(file.motion, file.model);
  nlohmann::json data;
  data["kind"] = "motion";
  data["motion"] = file.motion.name;
  data["model"] = model_json(file.model);
  data["settings"] = {{"status", "evaluated"},
                      {"knots_per_interval", EvaluateOptions{}.interpolation.knots_per_interval},
                      {"samples", evaluation.samples.size()},
                      {"keyframes", file.motion.keyframes.size()},
                      {"flight_time_s", file.motion.flight_time()}};
  data["residual"] = {{"before", force_metrics_to_json(evaluation.metrics)}, {"after", nullptr}};
  data["body_weight_N"] = file.model.total_mass() * kStandardGravity;
  data["duration_s"] = file.motion.flight_time();
  // json::array explicitly: a braced list of one json is a copy of it under clang, an array
  // under GCC.
  data["stages"] =
      nlohmann::json::array({stage_json("before", evaluation.samples, evaluation.keyframe_times)});
  data["parabola"] = parabola_json(file.motion.takeoff, file.motion.flight_time());
  data["apparatus"] = apparatus_json(file.model, file.motion.takeoff, evaluation.samples);
  if (own) {
    data["capture"] = capture_json(*own, file.model);
  } else {
    const std::string found = !capture.empty()           ? capture
                              : fs::is_directory(source) ? (is_import_folder(source) ? source : "")
                                                         : capture_of_motion_file(source);
    if (!found.empty())
      data["capture"] = capture_json(
          load_capture(found, motion_model_reference(file), capture.empty() ? source : "--capture"),
          file.model);
  }
  return data;
}

std::string today_utc() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm parts{};
  gmtime_r(&now, &parts);
  char text[16];
  std::strftime(text, sizeof text, "%Y-%m-%d", &parts);
  return text;
}

}  // namespace

nlohmann::json flight_page_data(const std::string& source, const std::string& date,
                                const std::string& capture) {
  const bool optimize_folder =
      fs::is_directory(source) && fs::is_regular_file(fs::path(source) / "optimized.motion.json");
  nlohmann::json data =
      optimize_folder ? optimize_folder_data(source, capture) : motion_data(source, capture);
  data["format"] = kFlightPageFormat;
  data["source"] = source;
  data["date"] = date;
  data["saltus_version"] = kSaltusVersion;
  return data;
}

FlightPageSummary export_flight_page(const std::string& source, const std::string& out_path,
                                     const std::string& capture) {
  const nlohmann::json data = flight_page_data(source, today_utc(), capture);
  require_finite(data, source);
  const std::string html = flight_page_html(data);
  const std::size_t bytes = save_flight_page(out_path, html);
  FlightPageSummary summary;
  summary.motion = data["motion"].get<std::string>();
  summary.model = data["model"]["name"].get<std::string>();
  summary.optimised = data["stages"].size() > 1;
  summary.frames = static_cast<int>(data["stages"][0]["t"].size());
  summary.bytes = bytes;
  if (data.contains("capture")) summary.capture = data["capture"]["source"].get<std::string>();
  return summary;
}

}  // namespace saltus
