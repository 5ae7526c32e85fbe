#include "saltus/formats/result_json.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "saltus/base/json_reader.h"
#include "saltus/base/text_format.h"
#include "saltus/formats/finite_check.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/output_folder.h"
#include "saltus/formats/trajectory_csv.h"

namespace saltus {

nlohmann::json force_metrics_to_json(const ForceMetrics& m) {
  return {{"objective", m.objective},     {"avg_root_force", m.avg_root_force},
          {"rms_force_N", m.rms_force_N}, {"rms_moment_Nm", m.rms_moment_Nm},
          {"max_force_N", m.max_force_N}, {"max_moment_Nm", m.max_moment_Nm}};
}

namespace {

nlohmann::json vector_json(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

/// Fields shared by every result.json; optimiser-only ones are null here.
nlohmann::json base_result(const MotionFile& file, const EvaluateOptions& options,
                           const std::string& status) {
  nlohmann::json r;
  r["format"] = "saltus-result/1";
  r["status"] = status;
  r["motion"] = file.motion.name;
  r["motion_file"] = file.path;
  r["model"] = file.model.name;
  r["samples"] = options.samples;
  r["knots_per_interval"] = options.interpolation.knots_per_interval;
  r["flight_time_s"] = file.motion.flight_time();
  r["keyframes"] = file.motion.keyframes.size();
  r["iterations"] = nullptr;
  r["solve_seconds"] = nullptr;
  r["variables"] = nullptr;
  r["constraints"] = nullptr;
  r["after"] = nullptr;
  r["keyframe_times_after"] = nullptr;
  return r;
}

/// Composes the file in memory, then writes it (write_text: the message of a failed write names
/// DIR/file and the system's reason, e.g. a full disk).
void write_text_file(const std::string& path, const std::string& /*what*/,
                     const std::function<void(std::ostream&)>& body) {
  std::ostringstream out;
  body(out);
  write_text(path, out.str());
}

void write_common_files(OutputFolder& folder, const MotionFile& file,
                        const nlohmann::json& result) {
  write_text_file(folder.file("model.json"), "the model",
                  [&](std::ostream& o) { o << body_model_to_json(file.model).dump(2) << '\n'; });
  write_text_file(folder.file("result.json"), "the result",
                  [&](std::ostream& o) { o << result.dump(2) << '\n'; });
}

void write_csv(OutputFolder& folder, const std::string& name, const BodyModel& model,
               const std::vector<SampleRecord>& samples) {
  write_text_file(folder.file(name), "the trajectory",
                  [&](std::ostream& o) { write_trajectory_csv(o, model, samples); });
}

nlohmann::json write_outputs(const std::string& out_dir, const MotionFile& file,
                             const std::vector<SampleRecord>& samples, nlohmann::json result) {
  require_finite(result, file.path);
  require_finite(samples, file.path, "trajectory.csv");
  OutputFolder folder(out_dir);
  write_csv(folder, "trajectory.csv", file.model, samples);
  write_common_files(folder, file, result);
  folder.commit();
  return result;
}

/// How the reported residual figures were computed (DESIGN §6).
nlohmann::json residual_check_json(const DenseCheck& check) {
  return {{"rule", "Simpson's rule on every knot span, " + std::to_string(kCheckPointsPerSpan) +
                       " or more intervals per span, " + format_number("%g", kCheckMaxSpacing) +
                       " s apart or closer, and at least the samples over the flight"},
          {"points", check.points}};
}

void put_keyframe_errors(nlohmann::json& r, const KeyframeErrors& e) {
  r["max_translation_error_m"] = e.max_translation_error_m;
  r["max_quaternion_error"] = e.max_quaternion_error;
  r["max_rotation_error_deg"] = e.max_rotation_error_deg;
}

}  // namespace

nlohmann::json evaluation_result_json(const MotionFile& file, const MotionEvaluation& e,
                                      const EvaluateOptions& options) {
  nlohmann::json r = base_result(file, options, "evaluated");
  r["before"] = force_metrics_to_json(e.metrics);
  r["residual_check"] = residual_check_json(e.check);
  r["keyframe_times_before"] = e.keyframe_times;
  put_keyframe_errors(r, e.keyframe_errors);
  r["takeoff_angular_momentum"] = vector_json(e.samples.front().angular_momentum);
  return r;
}

nlohmann::json simulation_result_json(const MotionFile& file, const SimulationResult& s,
                                      const EvaluateOptions& options) {
  nlohmann::json r = base_result(file, options, "simulated");
  r["before"] = force_metrics_to_json(s.metrics);
  std::vector<double> times;
  for (const Keyframe& k : file.motion.keyframes)
    times.push_back(k.time);
  r["keyframe_times_before"] = times;
  r["max_translation_error_m"] = nullptr;
  r["max_quaternion_error"] = nullptr;
  r["max_rotation_error_deg"] = nullptr;
  r["takeoff_angular_momentum"] = vector_json(s.angular_momentum);
  r["takeoff_angular_momentum_source"] =
      s.angular_momentum_from_file ? "motion file" : "best constant fit to the motion's L(t)";
  r["angular_momentum_spread"] = s.angular_momentum_spread;
  nlohmann::json joints = nlohmann::json::object();
  for (const auto& [name, deg] : s.landing_joint_error_deg)
    joints[name] = deg;
  r["landing"] = {{"root_error_deg", s.landing_root_error_deg},
                  {"joint_error_deg", joints},
                  {"com_error_m", s.landing_com_error_m},
                  {"root_vs_motion_deg", s.landing_vs_motion_deg}};
  return r;
}

nlohmann::json write_evaluation_outputs(const std::string& out_dir, const MotionFile& file,
                                        const MotionEvaluation& evaluation,
                                        const EvaluateOptions& options) {
  return write_outputs(out_dir, file, evaluation.samples,
                       evaluation_result_json(file, evaluation, options));
}

nlohmann::json write_simulation_outputs(const std::string& out_dir, const MotionFile& file,
                                        const SimulationResult& simulation,
                                        const EvaluateOptions& options) {
  return write_outputs(out_dir, file, simulation.samples,
                       simulation_result_json(file, simulation, options));
}

nlohmann::json optimization_result_json(const MotionFile& file, const OptimizationResult& result,
                                        const OptimizeOptions& options) {
  EvaluateOptions evaluate;
  evaluate.samples = options.nlp.samples;
  evaluate.interpolation.knots_per_interval = result.knots_per_interval;  // the one used
  nlohmann::json r = base_result(file, evaluate, result.solve.status);
  r["knots_per_interval_requested"] = options.nlp.knots_per_interval;
  // The knots the optimised motion lives on, and how the automatic resolution got there.
  nlohmann::json levels = nlohmann::json::array();
  for (const OptimizationResult::Level& level : result.levels)
    levels.push_back({{"subdivisions", level.subdivisions},
                      {"avg_root_force", level.avg_root_force},
                      {"iterations", level.iterations},
                      {"status", level.status}});
  r["resolution"] = {{"automatic", options.automatic_resolution &&
                                       options.nlp.formulation == Formulation::kRelaxed},
                     {"subdivisions", result.subdivisions},
                     {"knots", result.after.trajectory.rotations.empty()
                                   ? std::vector<double>{}
                                   : result.after.trajectory.rotations.front().knots()},
                     {"levels", levels}};
  r["ipopt_status"] = result.solve.ipopt_status;
  r["restarts"] = result.solve.restarts;
  r["formulation"] = options.nlp.formulation == Formulation::kRelaxed ? "relaxed" : "strict";
  if (options.nlp.formulation == Formulation::kStrict) r["epsilon"] = options.nlp.epsilon;
  r["timing_optimized"] = options.nlp.optimize_timing;
  r["iterations"] = result.solve.iterations;
  r["solve_seconds"] = result.solve.seconds;
  r["variables"] = result.variables;
  r["constraints"] = result.constraints;
  r["before"] = force_metrics_to_json(result.before.metrics);
  r["after"] = force_metrics_to_json(result.after.metrics);
  // The optimiser's own figure beside the true one (the dense check), so anyone can see that
  // the two agree.
  for (auto [key, objective] :
       {std::pair<const char*, double>{"before", result.optimizer_objective_before},
        {"after", result.optimizer_objective_after}}) {
    r[key]["optimizer_objective"] = objective;
    r[key]["optimizer_avg_root_force"] = std::sqrt(objective / 6.0);
  }
  r["residual_check"] = residual_check_json(result.after.check);
  r["residual_check"]["optimizer_agrees"] = optimizer_agrees_with_check(result);
  r["keyframe_times_before"] = result.before.keyframe_times;
  r["keyframe_times_after"] = result.after.keyframe_times;
  // How far each optimised time could move with the residual within kTimeSpreadForceRise:
  // times beyond kDeterminedTimeSpread are not recovered, only chosen.
  r["keyframe_time_spread_s"] = result.keyframe_time_spreads;
  std::vector<int> undetermined;
  for (std::size_t i = 0; i < result.keyframe_time_spreads.size(); ++i)
    if (result.keyframe_time_spreads[i] > kDeterminedTimeSpread)
      undetermined.push_back(static_cast<int>(i));
  r["keyframe_times_undetermined"] = undetermined;
  put_keyframe_errors(r, result.after.keyframe_errors);
  r["tolerances"] = {{"translation_m", file.motion.tolerances.translation_m},
                     {"quaternion", file.motion.tolerances.quaternion}};
  r["joint_turn_limit_deg"] =
      options.nlp.limits_joint_turns() ? options.nlp.joint_turn_limit * kDegreesPerRadian : 0.0;
  r["largest_joint_turn_deg"] = {
      {"before", largest_control_turn(result.before.trajectory, 1) * kDegreesPerRadian},
      {"after", largest_control_turn(result.after.trajectory, 1) * kDegreesPerRadian}};
  return r;
}

nlohmann::json write_optimization_outputs(const std::string& out_dir, const MotionFile& file,
                                          const OptimizationResult& result,
                                          const OptimizeOptions& options) {
  const nlohmann::json r = optimization_result_json(file, result, options);
  require_finite(r, file.path);
  require_finite(result.before.samples, file.path, "trajectory_before.csv");
  require_finite(result.after.samples, file.path, "trajectory_after.csv");
  OutputFolder folder(out_dir);
  write_csv(folder, "trajectory_before.csv", file.model, result.before.samples);
  write_csv(folder, "trajectory_after.csv", file.model, result.after.samples);
  // The optimised motion names the model copy written beside it, so the folder is
  // self-contained: `saltus evaluate DIR/optimized.motion.json` works wherever DIR goes.
  Motion optimized = result.optimized_motion;
  optimized.model = "model.json";
  write_text_file(
      folder.file("optimized.motion.json"), "the optimised motion",
      [&](std::ostream& o) { o << motion_to_json(optimized, file.model).dump(2) << '\n'; });
  write_common_files(folder, file, r);
  folder.commit();
  return r;
}

}  // namespace saltus
