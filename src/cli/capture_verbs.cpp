#include "capture_verbs.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "saltus/base/input_error.h"
#include "saltus/base/text_format.h"
#include "saltus/use_cases/captures.h"
#include "saltus/use_cases/motion_exports.h"

namespace saltus_cli {

namespace {

std::string absolute(const std::string& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

saltus::CaptureFileOptions import_options(const ImportArgs& args) {
  return saltus::capture_import_options(args.model, args.mapping, args.keyframes, args.flight,
                                        args.frame_time);
}

void print_vector(const char* label, const Eigen::Vector3d& v, const char* unit) {
  std::printf("%s (%.3g, %.3g, %.3g) %s", label, v.x(), v.y(), v.z(), unit);
}

int run_import(const ImportArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  const saltus::CaptureFile capture =
      saltus::import_capture_file(args.capture_path, import_options(args));
  saltus::write_capture_outputs(args.out_dir, capture);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const saltus::CaptureImport& im = capture.import;
  auto print_warnings = [&]() {
    std::fflush(stdout);
    for (const std::string& warning : im.warnings)
      std::fprintf(stderr, "saltus import: warning: %s\n", warning.c_str());
  };
  if (args.quiet) {
    print_warnings();
    return 0;
  }
  const saltus::FlightPhase& f = im.flight;
  std::printf(
      "saltus import: %s\n  %d joints, %d frames at %.6g s (%s names, %s, %s up) onto %s "
      "(%.1f kg)\n",
      capture.path.c_str(), im.source_joints, im.source_frames, im.frame_time,
      im.retargeting.mapping.convention.c_str(), im.retargeting.axes.unit.c_str(),
      im.retargeting.axes.up_name.c_str(), capture.model.name.c_str(), capture.model.total_mass());
  std::printf(
      "  flight (%s): frames %d-%d, lift-off %.3f s, touch-down %.3f s (%.3f s); the motion "
      "starts at frame %d, %.3f s long\n",
      f.method.c_str(), f.first_frame, f.last_frame, f.liftoff_time, f.touchdown_time,
      f.touchdown_time - f.liftoff_time, f.first_frame, im.captured.flight_time());
  std::printf("  take-off CoM");
  print_vector("", im.takeoff_fit.position, "m, velocity");
  print_vector("", im.takeoff_fit.velocity, "m/s");
  std::printf(" (parabola fit RMS %.3g m)\n", im.takeoff_fit.rms_residual_m);
  print_vector("  angular momentum", im.angular_momentum.mean, "kg·m²/s");
  std::printf(" (time average; standard deviation %.3g, max deviation %.3g)\n",
              im.angular_momentum.standard_deviation.norm(), im.angular_momentum.max_deviation);
  std::printf(
      "  implied gravity %.3g m/s²; somersault %.0f deg in the flight, %.0f deg in the clip\n",
      im.implied_gravity, im.somersault_flight_deg, im.somersault_clip_deg);
  std::printf("  the capture's own residual: average root force sqrt(J/6) %.4g N\n",
              im.metrics.avg_root_force);
  std::printf("  %zu keyframes picked (max rotation error %.2f deg); their interpolation: %.4g N\n",
              im.pick.frames.size(), im.pick.max_rotation_error_deg,
              im.keyframes_metrics.avg_root_force);
  std::printf(
      "  wrote %s/{result.json, capture.motion.json, keyframes.motion.json, trajectory.csv, "
      "model.json} in %.3f s\n",
      absolute(args.out_dir).c_str(), seconds);
  print_warnings();
  return 0;
}

int run_export(const ExportArgs& args) {
  saltus::ExportOptions options;
  options.fps = args.fps;
  options.capture = args.capture;
  const saltus::ExportSummary summary =
      saltus::export_source(args.source, args.format, args.out_path, options);
  if (!args.quiet)
    std::printf("saltus export: %s\n  %s\n  wrote %s\n", args.source.c_str(),
                summary.description.c_str(), absolute(args.out_path).c_str());
  return 0;
}

}  // namespace

void add_capture_verbs(CLI::App& app, CaptureVerbs& verbs) {
  ImportArgs& im = verbs.import_args;
  CLI::App* import = app.add_subcommand(
      "import",
      "Import a motion capture (BVH) onto the body model: retargeting, flight phase, take-off "
      "CoM state and angular momentum, the capture's own residual, keyframes picked for "
      "optimisation; writes result.json, capture.motion.json, keyframes.motion.json, "
      "trajectory.csv, model.json");
  import->add_option("CAPTURE", im.capture_path, "motion capture (*.bvh)")->required();
  import->add_option("--out", im.out_dir, "output folder (replaced if it holds an earlier result)")
      ->required();
  import->add_option("--model", im.model,
                     "body model (name under resources/models or path), default zatsiorsky-66kg");
  import->add_option("--mapping", im.mapping,
                     "skeleton mapping file (saltus-capture-mapping/1) for names no built-in "
                     "convention knows");
  import->add_option("--keyframes", im.keyframes,
                     "keyframes for keyframes.motion.json: a count, or 'all'; default: the "
                     "fewest whose interpolation meets every captured frame within tolerance");
  import->add_option("--flight", im.flight,
                     "the flight phase START:END in seconds of the clip, instead of finding it "
                     "from the feet");
  import->add_option("--frame-time", im.frame_time, "seconds per frame, instead of the file's");
  import->add_flag("--quiet,-q", im.quiet,
                   "print nothing on success (warnings still go to stderr)");
  verbs.import_command = import;

  ExportArgs& ex = verbs.export_args;
  std::string formats_help = "output format:";
  std::vector<std::string> format_names;
  for (const saltus::ExportFormat& f : saltus::export_formats()) {
    formats_help += (format_names.empty() ? " " : "; ") + f.name + ": " + f.title;
    format_names.push_back(f.name);
  }
  CLI::App* exp = app.add_subcommand(
      "export",
      "Write a motion in the formats other tools read: BVH for animation tools, a web page that "
      "opens offline in any browser, MuJoCo's MJCF with qpos/qvel/qacc, glTF 2.0 for Blender and "
      "three.js, an OpenSim model with its coordinates");
  exp->add_option("SOURCE", ex.source,
                  "motion file, capture, or result folder of optimize (optimized.motion.json) or "
                  "import (capture.motion.json)")
      ->required();
  exp->add_option("--format", ex.format, formats_help)
      ->required()
      ->check(CLI::IsMember(format_names));
  exp->add_option("--out", ex.out_path,
                  "output file (*.bvh, *.html, *.glb) or folder (mujoco, opensim); an existing "
                  "one is replaced only if Saltus wrote it (a BVH file never)")
      ->required();
  exp->add_option("--fps", ex.fps,
                  "frames per second (all but html); default: the keyframes' rate when they are "
                  "evenly spaced (a captured flight), else 60");
  exp->add_option("--capture", ex.capture,
                  "html: the motion capture drawn beside the athlete (an import folder or a BVH "
                  "file); default: the one SOURCE came from, if any");
  exp->add_flag("--quiet,-q", ex.quiet, "print nothing on success");
  verbs.export_command = exp;
}

std::optional<int> run_capture_verbs(const CaptureVerbs& verbs) {
  if (verbs.import_command && verbs.import_command->parsed()) return run_import(verbs.import_args);
  if (verbs.export_command && verbs.export_command->parsed()) return run_export(verbs.export_args);
  return std::nullopt;
}

}  // namespace saltus_cli
