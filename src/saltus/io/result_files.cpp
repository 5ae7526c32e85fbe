#include "saltus/io/result_files.h"

#include <fstream>
#include <stdexcept>

#include "saltus/io/json_reader.h"
#include "saltus/io/output_folder.h"
#include "saltus/io/trajectory_csv.h"

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

void write_text_file(const std::string& path, const std::string& what,
                     const std::function<void(std::ostream&)>& body) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot open for writing " + what);
  body(out);
  out.flush();
  if (!out) throw std::runtime_error(path + ": writing " + what + " failed");
}

nlohmann::json write_outputs(const std::string& out_dir, const MotionFile& file,
                             const std::vector<SampleRecord>& samples, nlohmann::json result) {
  OutputFolder folder(out_dir);
  write_text_file(folder.file("trajectory.csv"), "the trajectory",
                  [&](std::ostream& o) { write_trajectory_csv(o, file.model, samples); });
  write_text_file(folder.file("model.json"), "the model",
                  [&](std::ostream& o) { o << body_model_to_json(file.model).dump(2) << '\n'; });
  write_text_file(folder.file("result.json"), "the result",
                  [&](std::ostream& o) { o << result.dump(2) << '\n'; });
  folder.commit();
  return result;
}

}  // namespace

nlohmann::json evaluation_result_json(const MotionFile& file, const MotionEvaluation& e,
                                      const EvaluateOptions& options) {
  nlohmann::json r = base_result(file, options, "evaluated");
  r["before"] = force_metrics_to_json(e.metrics);
  r["keyframe_times_before"] = e.keyframe_times;
  r["max_translation_error_m"] = e.keyframe_errors.max_translation_error_m;
  r["max_quaternion_error"] = e.keyframe_errors.max_quaternion_error;
  r["max_rotation_error_deg"] = e.keyframe_errors.max_rotation_error_deg;
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
  r["takeoff_angular_momentum_source"] = s.angular_momentum_from_file ? "motion file" : "keyframes";
  nlohmann::json joints = nlohmann::json::object();
  for (const auto& [name, deg] : s.landing_joint_error_deg)
    joints[name] = deg;
  r["landing"] = {{"root_error_deg", s.landing_root_error_deg},
                  {"joint_error_deg", joints},
                  {"com_error_m", s.landing_com_error_m}};
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

}  // namespace saltus
