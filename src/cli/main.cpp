// `saltus`: command-line front end. Parses arguments, calls the library, prints a summary.
// Exit status: 0 success, 2 bad input (message names file and field), 3 optimisation did not
// converge (results written anyway), 4 the output could not be written (another run is writing
// the same folder, or the system refused: disk full, no permission; nothing was changed),
// 1 internal error.

#include <CLI/CLI.hpp>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <stdexcept>

#include "capture_verbs.h"
#include "flags/flag_bound_checks.h"
#include "flags/option_flags.h"
#include "model_verbs.h"
#include "saltus/base/constants.h"
#include "saltus/base/input_error.h"
#include "saltus/base/text_format.h"
#include "saltus/evaluation/clearance.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/force_metrics.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/evaluation/keyframe_spacing.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/evaluation/strength_demand.h"
#include "saltus/evaluation/twist_sources.h"
#include "saltus/evaluation/what_if.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/output_folder.h"
#include "saltus/formats/result_json.h"
#include "saltus/motion/motion.h"
#include "saltus/optim/optimize.h"
#include "saltus/optim/result_standing.h"
#include "saltus/optim/solver_memory.h"
#include "saltus/use_cases/athlete_models.h"
#include "saltus/use_cases/athlete_verdict.h"
#include "saltus/use_cases/captures.h"
#include "saltus/use_cases/result_folders.h"
#include "study_verbs.h"

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 1;
constexpr int kExitNotSolved = 3;
constexpr int kExitOutputNotWritten = 4;

struct CommonArgs {
  std::string motion_path;
  std::string out_dir;
  std::string model_override;
  std::string takeoff = "same-spin";  ///< simulate, analyse twist: with --model
  bool quiet = false;
  saltus::cli::OptionFlags options;  ///< the option table's flags of the verb
};

/// MOTION, --out, --model, --quiet and the option table's flags for runs of `runs` (evaluate and
/// simulate: the evaluation options; optimize: all).
void add_common(CLI::App* cmd, CommonArgs& args, saltus::OptionUse runs) {
  cmd->add_option("MOTION", args.motion_path, "motion file (*.motion.json) or capture (*.bvh)")
      ->required();
  cmd->add_option("--out", args.out_dir, "output folder (replaced if it holds an earlier result)")
      ->required();
  args.options.add(cmd,
                   runs == saltus::OptionUse::kEvaluation
                       ? saltus::cli::option_names(saltus::OptionUse::kEvaluation)
                       : saltus::cli::all_option_names(),
                   runs);
  cmd->add_option("--model", args.model_override,
                  "body model (name under resources/models or path), overrides the motion's");
  cmd->add_flag("--quiet,-q", args.quiet, "print nothing on success");
}

/// --takeoff, for the verbs whose result depends on the take-off angular momentum.
void add_takeoff(CLI::App* cmd, CommonArgs& args) {
  cmd->add_option("--takeoff", args.takeoff,
                  "with --model, how the take-off carries over to that athlete: same-spin (the "
                  "same whole-body spin, so the angular momentum follows the athlete's inertia) "
                  "or keep-momentum (the same angular momentum)")
      ->capture_default_str();
}

/// The motion, on the --model athlete with the --takeoff rule when given.
saltus::MotionFile load_for(const CommonArgs& args) {
  return saltus::load_motion_for_athlete(args.motion_path, args.model_override,
                                         saltus::parse_takeoff_rule(args.takeoff, "--takeoff"));
}

/// One line saying how the take-off was carried over to another athlete, if it was.
void print_takeoff_adaptation(const saltus::MotionFile& f) {
  if (!f.takeoff_adaptation) return;
  const saltus::TakeoffAdaptation& a = *f.takeoff_adaptation;
  std::printf(
      "  flown by %s instead of %s: %s at take-off, angular momentum (%.3g, %.3g, %.3g) -> "
      "(%.3g, %.3g, %.3g) kg·m²/s\n",
      f.model.name.c_str(), a.own_model.c_str(), a.rule.c_str(), a.own_angular_momentum.x(),
      a.own_angular_momentum.y(), a.own_angular_momentum.z(), a.angular_momentum.x(),
      a.angular_momentum.y(), a.angular_momentum.z());
}

saltus::EvaluateOptions options_from(const CommonArgs& args) {
  return args.options.values().evaluate_options();
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

/// "1½ back somersaults with 2 twists to the left (tilt up to 24°, twisting at up to 2.1 rev/s)"
/// from a result.json rotation block, as written.
std::string rotation_words(const nlohmann::json& r) {
  std::string out = r.at("description").get<std::string>();
  char more[96];
  const double rate = r.at("peak_twist_rate_rev_s").get<double>();
  if (rate > 0)
    std::snprintf(more, sizeof more, " (tilt up to %.0f deg, twisting at up to %.2g rev/s)",
                  r.at("max_tilt_deg").get<double>(), rate);
  else
    std::snprintf(more, sizeof more, " (tilt up to %.0f deg)", r.at("max_tilt_deg").get<double>());
  return out + more;
}

/// One line on the body's closest pass to the apparatus, from result.json's "clearance", e.g.
/// "closest to the platform: inside its space by 0.21 m (left toes at 1.531 s, 0.57 m behind
/// its edge, 1.30 m below its top): the body would strike the platform".
void print_clearance(const nlohmann::json& c) {
  const double d = c.at("min_distance_m").get<double>();
  const bool collision = c.at("collision").get<bool>();
  const std::string where = collision ? "inside its space by" : "clear by";
  const std::string who = c.at("point").get<std::string>();
  const double t = c.at("time_s").get<double>();
  if (c.at("apparatus").get<std::string>() == "platform") {
    const double behind = c.at("behind_edge_m").get<double>();
    const double below = c.at("below_top_m").get<double>();
    std::printf(
        "  closest to the platform: %s %.2f m (%s at %.3f s, %.2f m %s its edge, %.2f m %s "
        "its top)%s\n",
        where.c_str(), std::abs(d), who.c_str(), t, std::abs(behind),
        behind >= 0 ? "behind" : "ahead of", std::abs(below), below >= 0 ? "below" : "above",
        collision ? ": the body would strike the platform" : "");
  } else {
    const double inside = c.at("inside_bed_edge_m").get<double>();
    const double above = c.at("above_frame_m").get<double>();
    std::printf(
        "  closest to the trampoline frame: %s %.2f m (%s at %.3f s, %.2f m %s the bed's "
        "edge, %.2f m %s the frame)%s\n",
        where.c_str(), std::abs(d), who.c_str(), t, std::abs(inside),
        inside >= 0 ? "inside" : "beyond", std::abs(above), above >= 0 ? "above" : "below",
        collision ? ": the body would strike the frame" : "");
  }
}

/// One line on a dive's entry, from result.json's "entry", e.g. "entry: right hand first at
/// 1.490 s, body 1.1 deg from vertical, head first: vertical (tolerance 10 deg); CoM 1.05 m above
/// the water".
void print_entry(const nlohmann::json& e) {
  const double angle = e.at("angle_to_vertical_deg").get<double>();
  std::printf(
      "  entry: %s first at %.3f s, body %.1f deg from vertical, %s: %s (tolerance %.0f deg); "
      "CoM %.2f m above the water\n",
      e.at("first_contact").get<std::string>().c_str(), e.at("time_s").get<double>(), angle,
      e.at("head_first").get<bool>() ? "head first" : "feet first",
      e.at("vertical").get<bool>() ? "vertical" : "not vertical",
      saltus::kVerticalEntryToleranceDeg, e.at("com_height_m").get<double>());
}

void print_apparatus(const nlohmann::json& written) {
  if (written.contains("clearance")) print_clearance(written.at("clearance"));
  if (written.contains("entry")) print_entry(written.at("entry"));
}

void print_outputs(const std::string& out_dir, double seconds) {
  std::printf("  wrote %s/{result.json, trajectory.csv, model.json} in %.3f s\n",
              absolute(out_dir).c_str(), seconds);
}

/// The keyframe intervals too far apart for the motion's twist (evaluation/keyframe_spacing.h),
/// one line each, in result.json's words.
void print_sparse_twist(const nlohmann::json& written) {
  for (const nlohmann::json& interval : written.at("sparse_twist_intervals"))
    std::printf("  %s\n", interval.at("words").get<std::string>().c_str());
}

/// The motion against the athlete's strength, then "can this athlete land it?" as the app says
/// it (use_cases/athlete_verdict.h): the one verdict, then its reasons (each joint beyond the
/// athlete's strength, with a run the joints' warnings).
void print_verdict(const saltus::AthleteVerdict& verdict) {
  std::printf("  strength: %s\n", verdict.strength_words.c_str());
  std::printf("  can this athlete land it? %s: %s\n",
              saltus::verdict_light_name(verdict.light).c_str(), verdict.headline.c_str());
  for (const std::string& line : verdict.reasons)
    std::printf("    %s\n", line.c_str());
}

int run_evaluate(const CommonArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  saltus::check_output_folder(args.out_dir);
  const saltus::MotionFile file =
      saltus::load_motion_or_capture(args.motion_path, args.model_override);
  const saltus::EvaluateOptions options = options_from(args);
  const saltus::MotionEvaluation e = saltus::evaluate_motion(file.motion, file.model, options);
  const nlohmann::json written = saltus::write_evaluation_outputs(args.out_dir, file, e, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!args.quiet) {
    print_header("evaluate", file, options);
    print_forces(e.metrics);
    std::printf("  keyframes: max root translation error %.3g m, max rotation error %.3g deg\n",
                e.keyframe_errors.max_translation_error_m,
                e.keyframe_errors.max_rotation_error_deg);
    std::printf("  Yeadon's angles: %s\n",
                rotation_words(written.at("rotation").at("before")).c_str());
    print_sparse_twist(written);
    print_verdict(saltus::athlete_verdict(file, options, e));
    print_apparatus(written);
    print_outputs(args.out_dir, seconds);
  }
  return 0;
}

int run_simulate(const CommonArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  saltus::check_output_folder(args.out_dir);
  const saltus::MotionFile file = load_for(args);
  const saltus::EvaluateOptions options = options_from(args);
  const saltus::SimulationResult s = saltus::simulate_motion(file.motion, file.model, options);
  const nlohmann::json written = saltus::write_simulation_outputs(args.out_dir, file, s, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!args.quiet) {
    print_header("simulate", file, options);
    print_takeoff_adaptation(file);
    std::printf("  free flight, take-off angular momentum (%.3g, %.3g, %.3g) kg·m²/s from the %s\n",
                s.angular_momentum.x(), s.angular_momentum.y(), s.angular_momentum.z(),
                s.angular_momentum_from_file
                    ? "motion file"
                    : "motion itself (the constant nearest its L(t) over the flight)");
    std::printf("  the motion's own L(t) strays from that constant by %.3g kg·m²/s RMS\n",
                s.angular_momentum_spread);
    print_forces(s.metrics);
    std::printf("  Yeadon's angles of the free flight: %s\n",
                rotation_words(written.at("rotation").at("before")).c_str());
    std::printf(
        "  landing vs last keyframe: whole-body orientation off by %.2f deg, CoM off the "
        "parabola by %.3g m\n",
        s.landing_root_error_deg, s.landing_com_error_m);
    std::printf("  landing vs the motion's own end: whole-body orientation off by %.2f deg\n",
                s.landing_vs_motion_deg);
    print_apparatus(written);
    print_outputs(args.out_dir, seconds);
  }
  return 0;
}

int run_optimize(const CommonArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  saltus::check_output_folder(args.out_dir);
  const saltus::MotionFile file =
      saltus::load_motion_or_capture(args.motion_path, args.model_override);
  const saltus::OptionValues& values = args.options.values();
  const saltus::OptimizeOptions options = values.optimize_options();

  const bool quiet = args.quiet;
  const saltus::ProgressCallback progress = [quiet](const saltus::ProgressInfo& p) {
    if (quiet) return;
    std::fprintf(stderr, "  iter %3d  objective %.6e  constraint violation %.2e  %.3f s\n",
                 p.iteration, p.objective, p.constraint_violation, p.elapsed_seconds);
  };
  // Said before the solve (a twist the keyframes lose is the user's to key; the solve starts
  // there from the free flight's way round).
  if (!quiet)
    for (const saltus::SparseTwistInterval& interval :
         saltus::sparse_twist_intervals(file.motion, file.model))
      std::fprintf(stderr, "  warning: %s\n", saltus::sparse_twist_words(interval).c_str());
  const saltus::OptimizationResult result =
      saltus::optimize_motion(file.motion, file.model, options, progress);
  const nlohmann::json written =
      saltus::write_optimization_outputs(args.out_dir, file, result, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!quiet) {
    print_header("optimize", file, values.evaluate_options());
    std::printf("  %s model, %d variables, %d constraints: %s (%s) after %d iterations, %.3f s\n",
                std::get<std::string>(values.get("formulation")).c_str(), result.variables,
                result.constraints, result.solve.status.c_str(), result.solve.ipopt_status.c_str(),
                result.solve.iterations, result.solve.seconds);
    if (options.automatic_resolution) {
      std::printf("  automatic resolution:");
      for (const auto& level : result.levels) {
        std::printf(" [");
        for (std::size_t i = 0; i < level.subdivisions.size(); ++i)
          std::printf("%s%d", i ? "," : "", level.subdivisions[i]);
        std::printf("] %.3g N, %.1f deg", level.avg_root_force, level.landing_drift_deg);
        if (level.root_moment_weight != 1.0)
          std::printf(" (root moment weighed %.3gx)", level.root_moment_weight);
        std::printf(";");
      }
      std::printf(
          " knot spans per keyframe interval, true average root force, free flight's landing "
          "from the motion\n");
    } else if (result.knots_per_interval != options.nlp.knots_per_interval) {
      std::printf(
          "  knots refined to %d per keyframe interval: on %d the interpolation misses the "
          "keyframes by more than their tolerance (a turn of more than 180 deg between control "
          "points)\n",
          result.knots_per_interval, options.nlp.knots_per_interval);
    }
    if (const auto& polish = result.joint_load_polish) {
      std::string bound = "joints not bounded";
      if (polish->joint_bound > 0)
        bound = saltus::format_number("each joint's moment and force within %.2gx its peak before",
                                      polish->joint_bound);
      if (polish->bounds_tightened) bound += ", then lower where a load rose past it between nodes";
      if (polish->knots_refined) bound += ", on finer knots";
      std::printf(
          "  least joint effort at these times (weight %.3g, root moment weighed %.3gx, %s%s): "
          "%.3g N -> %.3g N average root force, free flight landing %.1f -> %.1f deg from the "
          "motion, %s\n",
          polish->weight, polish->root_moment_weight, bound.c_str(),
          polish->attempts > 1 ? (", try " + std::to_string(polish->attempts) + " of " +
                                  std::to_string(saltus::kPolishAttempts) +
                                  (polish->bounded_tries_skipped > 0
                                       ? " (" + std::to_string(polish->bounded_tries_skipped) +
                                             " bounded skipped: a bounded try had landed far off)"
                                       : std::string()))
                                     .c_str()
                               : "",
          polish->avg_root_force_before, polish->avg_root_force_after,
          polish->landing_drift_before_deg, polish->landing_drift_after_deg,
          !polish->kept ? ("not kept (" + polish->status + ")").c_str()
          : !saltus::root_force_within_limit(polish->avg_root_force_after,
                                             polish->avg_root_force_before)
              ? (saltus::format_number(
                     "kept (no try held the root force; the motion before it loaded a joint at "
                     "%.3gx its input peak, so a bounded try is kept up to ",
                     polish->joint_rise_before) +
                 saltus::format_number("%.3g N)", saltus::kPolishMaxRootForceOverPayingJoints))
                    .c_str()
              : "kept");
    }
    if (result.landing_drift_deg)
      std::printf(
          "  free flight of the optimised motion (its own take-off state): lands %.2f deg from "
          "it\n",
          *result.landing_drift_deg);
    if (result.solve.restarts > 0)
      std::printf("  the solver restarted %d time(s) from its best feasible iterate\n",
                  result.solve.restarts);
    std::printf(
        "  average root force sqrt(J/6): %.4g N before, %.4g N after (checked on %d points; "
        "the optimiser's own integral: %.4g N)\n",
        result.before.metrics.avg_root_force, result.after.metrics.avg_root_force,
        result.after.check.points, std::sqrt(result.optimizer_objective_after / 6.0));
    if (result.after.metrics.avg_root_force > saltus::kPolishMaxRootForce)
      std::printf("  above %.3g N: %s\n", saltus::kPolishMaxRootForce,
                  saltus::residual_location_words(
                      written.at("residual_check").at("share_by_keyframe_interval"),
                      result.after.keyframe_times)
                      .c_str());
    std::printf("  root force  RMS %.4g -> %.4g N, max %.4g -> %.4g N\n",
                result.before.metrics.rms_force_N, result.after.metrics.rms_force_N,
                result.before.metrics.max_force_N, result.after.metrics.max_force_N);
    std::printf("  root moment RMS %.4g -> %.4g N·m, max %.4g -> %.4g N·m\n",
                result.before.metrics.rms_moment_Nm, result.after.metrics.rms_moment_Nm,
                result.before.metrics.max_moment_Nm, result.after.metrics.max_moment_Nm);
    std::printf("  keyframe times:");
    int undetermined = 0;
    for (std::size_t i = 0; i < result.after.keyframe_times.size(); ++i) {
      const double spread = result.keyframe_time_spreads[i];
      std::printf(" %.3f->%.3f", result.before.keyframe_times[i], result.after.keyframe_times[i]);
      if (spread > saltus::kDeterminedTimeSpread) {
        std::printf("(±%.2f)", spread);
        ++undetermined;
      }
    }
    if (undetermined > 0)
      std::printf(
          "\n  (±s: %d time(s) the keyframes and their tolerances leave undetermined: each could "
          "move so far before the objective (root force and keyframe prior) rises by what %.1f N "
          "more average root force costs)",
          undetermined, saltus::kTimeSpreadForceRise);
    std::printf(
        "\n  keyframes: max root translation error %.3g m (tolerance %.3g), max quaternion "
        "error %.3g (tolerance %.3g)\n",
        result.after.keyframe_errors.max_translation_error_m, file.motion.tolerances.translation_m,
        result.after.keyframe_errors.max_quaternion_error, file.motion.tolerances.quaternion);
    std::printf(
        "  largest joint turn between two control points: %.0f deg before, %.0f deg after",
        saltus::largest_control_turn(result.before.trajectory, 1) * saltus::kDegreesPerRadian,
        saltus::largest_control_turn(result.after.trajectory, 1) * saltus::kDegreesPerRadian);
    if (values.real("max_joint_turn") > 0)
      std::printf(" (soft limit %.0f deg, or the interpolation's own turn)",
                  values.real("max_joint_turn"));
    std::printf("\n");
    std::printf("  Yeadon's angles: %s before; %s after\n",
                rotation_words(written.at("rotation").at("before")).c_str(),
                rotation_words(written.at("rotation").at("after")).c_str());
    print_sparse_twist(written);
    if (!result.twist_guided_intervals.empty()) {
      std::printf("  started there from the free flight's way round, not the short way: keyframes");
      for (std::size_t i = 0; i < result.twist_guided_intervals.size(); ++i)
        std::printf("%s %d-%d", i ? "," : "", result.twist_guided_intervals[i] + 1,
                    result.twist_guided_intervals[i] + 2);
      std::printf("\n");
    }
    const saltus::JointLoadRise rise =
        saltus::largest_joint_load_rise(file.model, result.before.check, result.after.check);
    if (!rise.joint.empty())
      std::printf("  joint loads: %s; largest rise at %s\n",
                  saltus::joint_load_verdict_words(rise).c_str(),
                  saltus::joint_load_rise_words(rise, saltus::body_weight_N(file.model)).c_str());
    print_verdict(saltus::athlete_verdict(file, values.evaluate_options(), result));
    std::printf(
        "  wrote %s/{result.json, trajectory_before.csv, trajectory_after.csv, model.json, "
        "optimized.motion.json} in %.3f s\n",
        absolute(args.out_dir).c_str(), seconds);
  }
  return result.solve.solved ? 0 : kExitNotSolved;
}

int run_analyse_twist(const CommonArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  saltus::check_output_folder(args.out_dir);
  const saltus::MotionFile file = load_for(args);
  const saltus::EvaluateOptions options = options_from(args);
  const saltus::TwistSources sources = saltus::twist_sources(file.motion, file.model, options);
  const nlohmann::json written = saltus::write_twist_outputs(args.out_dir, file, sources);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!args.quiet) {
    print_header("analyse twist", file, options);
    print_takeoff_adaptation(file);
    std::printf("  %s\n", written.at("sentence").get<std::string>().c_str());
    for (const nlohmann::json& share : written.at("shares"))
      std::printf("  %-10s %7.1f deg of tilt at mid-flight (%.0f %%)\n",
                  share.at("source").get<std::string>().c_str(), share.at("tilt_deg").get<double>(),
                  share.at("percent").get<double>());
    std::printf("  wrote %s/{result.json, twist.csv, twist.md} in %.3f s\n",
                absolute(args.out_dir).c_str(), seconds);
  }
  return 0;
}

/// --tuck-later, --open-later and --tuck-scale of `analyse what-if`: the library's WhatIfChange,
/// its ranges checked by the library (they depend on the motion).
void add_what_if_change(CLI::App* cmd, saltus::WhatIfChange& change) {
  cmd->add_option("--tuck-later", change.tuck_later_s,
                  "the tuck-in this much later, s (< 0: earlier); the motion's range is printed")
      ->capture_default_str();
  cmd->add_option("--open-later", change.open_later_s,
                  "the opening this much later, s (< 0: earlier)")
      ->capture_default_str();
  cmd->add_option("--tuck-scale", change.tuck_scale,
                  "the hips' and knees' turn from their take-off pose times this (> 1: a "
                  "tighter tuck)")
      ->capture_default_str();
}

int run_analyse_what_if(const CommonArgs& args, const saltus::WhatIfChange& change) {
  const auto start = std::chrono::steady_clock::now();
  saltus::check_output_folder(args.out_dir);
  const saltus::MotionFile file = load_for(args);
  const saltus::EvaluateOptions options = options_from(args);
  const saltus::WhatIf prepared(file.motion, file.model, options);
  const saltus::WhatIfResult result = prepared.fly(change);
  const nlohmann::json written =
      saltus::write_what_if_outputs(args.out_dir, file, prepared, result);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!args.quiet) {
    print_header("analyse what-if", file, options);
    print_takeoff_adaptation(file);
    const saltus::TuckPhases& t = prepared.tuck();
    if (t.found) {
      std::printf("  the tuck: in %.3f-%.3f s, ", t.tuck_start_s, t.tucked_s);
      if (t.opens)
        std::printf("opens %.3f-%.3f s", t.open_start_s, t.opened_s);
      else
        std::printf("lands in it");
      std::printf(", hips and knees bend up to %.0f deg; --tuck-later %+.3f..%+.3f s",
                  t.peak_bend_deg, t.tuck_later_min_s, t.tuck_later_max_s);
      if (t.opens)
        std::printf(", --open-later %+.3f..%+.3f s", t.open_later_min_s, t.open_later_max_s);
      std::printf("\n");
    } else {
      std::printf("  %s\n", t.reason.c_str());
    }
    std::printf("  %s\n", result.sentence.c_str());
    std::printf(
        "  keyframed: %.3f somersaults, %.3f twists; flown as it is: %.3f, %.3f; this flight: "
        "%.3f, %.3f\n",
        prepared.target().somersaults, prepared.target().twists,
        prepared.unchanged_landing().somersaults, prepared.unchanged_landing().twists,
        result.landing.somersaults, result.landing.twists);
    std::printf("  wrote %s/{result.json, what_if.csv, trajectory.csv, model.json} in %.3f s\n",
                absolute(args.out_dir).c_str(), seconds);
  }
  return 0;
}

/// Calls `add` on every option of every verb.
void for_every_option(CLI::App& app, const std::function<void(CLI::Option&)>& add) {
  for (CLI::Option* option : app.get_options())
    add(*option);
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; }))
    for_every_option(*command, add);
}

/// Checks every verb's flags share. CLI11 reads "" as 0 for a number (`--height ""` became a
/// height of 0 m, `--open-later ""` no change): every number flag refuses an empty value. An
/// output path (--out, --emit-slurm) with a name longer than a file system takes is refused
/// naming the flag before any work (the library refuses it too, naming the path).
void add_shared_checks(CLI::App& app) {
  const CLI::Validator not_empty(
      [](std::string& text) { return text.empty() ? "is empty: give a number" : std::string(); },
      "", "");
  const CLI::Validator writable_name(
      [](std::string& text) { return saltus::output_name_problem(text); }, "", "");
  for_every_option(app, [&](CLI::Option& option) {
    const std::string type = option.get_type_name();
    if (type == "FLOAT" || type == "INT" || type == "UINT" || type == "NUMBER")
      option.check(not_empty);
    if (option.check_name("--out") || option.check_name("--emit-slurm"))
      option.check(writable_name);
  });
}

}  // namespace

int main(int argc, char** argv) {
  saltus::keep_solver_memory_in_heap();
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
  add_common(evaluate, evaluate_args, saltus::OptionUse::kEvaluation);

  CommonArgs simulate_args;
  CLI::App* simulate = app.add_subcommand(
      "simulate",
      "Free flight: the joints follow the keyframed motion, the body's orientation and position "
      "follow Newton's laws; reports how far the landing is from the last keyframe");
  add_common(simulate, simulate_args, saltus::OptionUse::kEvaluation);
  add_takeoff(simulate, simulate_args);

  CommonArgs optimize_args;
  CLI::App* optimize = app.add_subcommand(
      "optimize",
      "Optimise the motion so it obeys Newton's laws as nearly as possible while keeping the "
      "keyframes within tolerance (paper eqs. 1-4), keyframe times included; writes before/after "
      "trajectories, result.json and optimized.motion.json. Exit status 3 if Ipopt does not "
      "converge (results are still written)");
  add_common(optimize, optimize_args, saltus::OptionUse::kOptimization);

  CLI::App* analyse = app.add_subcommand(
      "analyse",
      "Analyses of a motion: `analyse twist` (where the twist comes from), `analyse what-if` "
      "(the same take-off, another tuck)");
  analyse->require_subcommand(1);
  CommonArgs twist_args;
  CLI::App* twist = analyse->add_subcommand(
      "twist",
      "Where the twist comes from: the tilt at mid-flight of the motion's free flight split into "
      "the take-off's share and each aerial movement's (left arm, right arm, legs, trunk), by "
      "Yeadon's counterfactual free flights; writes result.json, twist.csv, twist.md");
  add_common(twist, twist_args, saltus::OptionUse::kEvaluation);
  add_takeoff(twist, twist_args);

  CommonArgs what_if_args;
  saltus::WhatIfChange what_if_change;
  CLI::App* what_if = analyse->add_subcommand(
      "what-if",
      "The same take-off with the tuck moved earlier or later, the opening moved, or the tuck "
      "tighter or looser, flown again: somersaults and twists at landing and how far short or "
      "over the landing the motion was keyframed to; writes result.json, what_if.csv, "
      "trajectory.csv, model.json");
  add_common(what_if, what_if_args, saltus::OptionUse::kEvaluation);
  add_takeoff(what_if, what_if_args);
  add_what_if_change(what_if, what_if_change);

  saltus::cli::StudyVerbs study_verbs(app, argc, argv);  // study convergence|mass|merge, paper

  saltus_cli::CaptureVerbs capture_verbs;
  saltus_cli::add_capture_verbs(app, capture_verbs);

  saltus_cli::ModelVerbs model_verbs;
  saltus_cli::add_model_verbs(app, model_verbs);
  add_shared_checks(app);
  saltus::cli::add_flag_bound_checks(app, "saltus");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ValidationError& e) {
    // A value a flag does not take: one line, as the library's refusals (docs/safety.md).
    std::fprintf(stderr, "saltus: error: %s\n", saltus::printable(e.what()).c_str());
    return kExitBadInput;
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  }

  // One printable line whatever the message quotes (a path with a newline, an ESC).
  const auto report = [](const char* kind, const std::exception& e, int status) {
    std::fprintf(stderr, "saltus: %s: %s\n", kind, saltus::printable(e.what()).c_str());
    return status;
  };
  try {
    if (evaluate->parsed()) return run_evaluate(evaluate_args);
    if (simulate->parsed()) return run_simulate(simulate_args);
    if (optimize->parsed()) return run_optimize(optimize_args);
    if (twist->parsed()) return run_analyse_twist(twist_args);
    if (what_if->parsed()) return run_analyse_what_if(what_if_args, what_if_change);
    if (const auto status = study_verbs.run()) return *status;
    if (auto status = saltus_cli::run_capture_verbs(capture_verbs)) return *status;
    if (auto status = saltus_cli::run_model_verbs(model_verbs)) return *status;
  } catch (const saltus::InputError& e) {
    return report("error", e, kExitBadInput);
  } catch (const saltus::OutputError& e) {
    return report("error", e, kExitOutputNotWritten);
  } catch (const std::invalid_argument& e) {
    return report("error", e, kExitBadInput);
  } catch (const std::filesystem::filesystem_error& e) {
    return report("error", e, kExitBadInput);
  } catch (const std::exception& e) {
    return report("internal error", e, kExitInternal);
  }
  return kExitInternal;
}
