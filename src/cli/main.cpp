// `saltus`: command-line front end. Parses arguments, calls the library, prints a summary.
// Exit status: 0 success, 2 bad input (message names file and field), 1 internal error.

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "saltus/analysis/motion_analysis.h"
#include "saltus/io/input_error.h"
#include "saltus/io/result_files.h"
#include "saltus/motion/motion.h"

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 1;

struct CommonArgs {
  std::string motion_path;
  std::string out_dir;
  std::string model_override;
  int samples = 201;
  int knots_per_interval = 1;
  bool quiet = false;
};

void add_common(CLI::App* cmd, CommonArgs& args) {
  cmd->add_option("MOTION", args.motion_path, "motion file (*.motion.json)")->required();
  cmd->add_option("--out", args.out_dir, "output folder (replaced if it holds an earlier result)")
      ->required();
  cmd->add_option("--samples", args.samples, "time samples on [0, T], ends included")
      ->check(CLI::Range(2, 1000000))
      ->capture_default_str();
  cmd->add_option("--knots-per-interval", args.knots_per_interval,
                  "spline knot sub-intervals per keyframe interval (1 = knots at keyframes)")
      ->check(CLI::Range(1, 50))
      ->capture_default_str();
  cmd->add_option("--model", args.model_override,
                  "body model (name under resources/models or path), overrides the motion's");
  cmd->add_flag("--quiet,-q", args.quiet, "print nothing on success");
}

saltus::EvaluateOptions options_from(const CommonArgs& args) {
  saltus::EvaluateOptions o;
  o.samples = args.samples;
  o.interpolation.knots_per_interval = args.knots_per_interval;
  return o;
}

std::string absolute(const std::string& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

void print_header(const char* verb, const saltus::MotionFile& f, const saltus::EvaluateOptions& o) {
  std::printf(
      "saltus %s: %s\n  model %s (%.1f kg), %zu keyframes, flight time %.3f s, %d samples\n", verb,
      f.motion.name.c_str(), f.model.name.c_str(), f.model.total_mass(), f.motion.keyframes.size(),
      f.motion.flight_time(), o.samples);
}

void print_forces(const saltus::ForceMetrics& m) {
  std::printf("  average root force sqrt(J/6): %.4g N   (objective J = %.4g)\n", m.avg_root_force,
              m.objective);
  std::printf("  root force  RMS %.4g N, max %.4g N\n", m.rms_force_N, m.max_force_N);
  std::printf("  root moment RMS %.4g N·m, max %.4g N·m\n", m.rms_moment_Nm, m.max_moment_Nm);
}

void print_outputs(const std::string& out_dir, double seconds) {
  std::printf("  wrote %s/{result.json, trajectory.csv, model.json} in %.3f s\n",
              absolute(out_dir).c_str(), seconds);
}

int run_evaluate(const CommonArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  const saltus::MotionFile file = saltus::load_motion_file(args.motion_path, args.model_override);
  const saltus::EvaluateOptions options = options_from(args);
  const saltus::MotionEvaluation e = saltus::evaluate_motion(file.motion, file.model, options);
  saltus::write_evaluation_outputs(args.out_dir, file, e, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!args.quiet) {
    print_header("evaluate", file, options);
    print_forces(e.metrics);
    std::printf("  keyframes: max root translation error %.3g m, max rotation error %.3g deg\n",
                e.keyframe_errors.max_translation_error_m,
                e.keyframe_errors.max_rotation_error_deg);
    print_outputs(args.out_dir, seconds);
  }
  return 0;
}

int run_simulate(const CommonArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  const saltus::MotionFile file = saltus::load_motion_file(args.motion_path, args.model_override);
  const saltus::EvaluateOptions options = options_from(args);
  const saltus::SimulationResult s = saltus::simulate_motion(file.motion, file.model, options);
  saltus::write_simulation_outputs(args.out_dir, file, s, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!args.quiet) {
    print_header("simulate", file, options);
    std::printf("  free flight, take-off angular momentum (%.3g, %.3g, %.3g) kg·m²/s from the %s\n",
                s.angular_momentum.x(), s.angular_momentum.y(), s.angular_momentum.z(),
                s.angular_momentum_from_file ? "motion file" : "keyframes at t = 0");
    print_forces(s.metrics);
    std::printf(
        "  landing vs last keyframe: whole-body orientation off by %.2f deg, CoM off the "
        "parabola by %.3g m\n",
        s.landing_root_error_deg, s.landing_com_error_m);
    print_outputs(args.out_dir, seconds);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Saltus: physics-based simulation of human aerial motion.\n"
      "Evaluates keyframed somersaults and dives by inverse dynamics and simulates free "
      "flight."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "saltus 0.1.0");

  CommonArgs evaluate_args;
  CLI::App* evaluate = app.add_subcommand(
      "evaluate",
      "Interpolate the keyframes (paper §5) and compute the root force and moment the motion "
      "needs (inverse dynamics); writes result.json, trajectory.csv, model.json");
  add_common(evaluate, evaluate_args);

  CommonArgs simulate_args;
  CLI::App* simulate = app.add_subcommand(
      "simulate",
      "Free flight: the joints follow the keyframed motion, the body's orientation and position "
      "follow Newton's laws; reports how far the landing is from the last keyframe");
  add_common(simulate, simulate_args);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  }

  try {
    if (evaluate->parsed()) return run_evaluate(evaluate_args);
    if (simulate->parsed()) return run_simulate(simulate_args);
  } catch (const saltus::InputError& e) {
    std::fprintf(stderr, "saltus: error: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "saltus: error: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "saltus: error: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "saltus: internal error: %s\n", e.what());
    return kExitInternal;
  }
  return kExitInternal;
}
