#include "saltus/use_cases/result_folders.h"

#include <functional>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/formats/finite_check.h"
#include "saltus/formats/mass_files.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/output_folder.h"
#include "saltus/formats/result_json.h"
#include "saltus/formats/trajectory_csv.h"
#include "saltus/formats/twist_files.h"
#include "saltus/formats/what_if_files.h"

namespace saltus {

namespace {

// What each writer here writes (output_kind.h): the rule that guards output folders reads these
// declarations, recorded in every folder written, and nothing else.
const FolderKind kEvaluateFolder{"evaluate", {"result.json", "trajectory.csv", "model.json"}};
const FolderKind kSimulateFolder{"simulate", {"result.json", "trajectory.csv", "model.json"}};
const FolderKind kOptimizeFolder{"optimize",
                                 {"result.json", "trajectory_before.csv", "trajectory_after.csv",
                                  "model.json", "optimized.motion.json"}};
const FolderKind kTwistFolder{"analyse twist", {"result.json", "twist.csv", "twist.md"}};
const FolderKind kWhatIfFolder{"analyse what-if",
                               {"result.json", "what_if.csv", "trajectory.csv", "model.json"}};
const FolderKind kMassFolder{
    "study mass", {"result.json", "mass.csv", "mass.md", "model.json", "model_scaled.json"}};

/// Composes a file in memory, then writes it (write_text: the message of a failed write names
/// DIR/file and the system's reason, e.g. a full disk).
void write_composed(const std::string& path, const std::function<void(std::ostream&)>& body) {
  std::ostringstream out;
  body(out);
  write_text(path, out.str());
}

void write_common_files(OutputFolder& folder, const MotionFile& file,
                        const nlohmann::json& result) {
  write_composed(folder.file("model.json"),
                 [&](std::ostream& o) { o << body_model_to_json(file.model).dump(2) << '\n'; });
  write_composed(folder.file("result.json"), [&](std::ostream& o) { o << result.dump(2) << '\n'; });
}

void write_csv(OutputFolder& folder, const std::string& name, const BodyModel& model,
               const std::vector<SampleRecord>& samples) {
  write_composed(folder.file(name),
                 [&](std::ostream& o) { write_trajectory_csv(o, model, samples); });
}

nlohmann::json write_outputs(const std::string& out_dir, const FolderKind& kind,
                             const MotionFile& file, const std::vector<SampleRecord>& samples,
                             nlohmann::json result) {
  require_finite(result, file.path);
  require_finite(samples, file.path, "trajectory.csv");
  OutputFolder folder(out_dir, kind);
  write_csv(folder, "trajectory.csv", file.model, samples);
  write_common_files(folder, file, result);
  folder.commit();
  return result;
}

}  // namespace

nlohmann::json write_evaluation_outputs(const std::string& out_dir, const MotionFile& file,
                                        const MotionEvaluation& evaluation,
                                        const EvaluateOptions& options) {
  return write_outputs(out_dir, kEvaluateFolder, file, evaluation.samples,
                       evaluation_result_json(file, evaluation, options));
}

nlohmann::json write_simulation_outputs(const std::string& out_dir, const MotionFile& file,
                                        const SimulationResult& simulation,
                                        const EvaluateOptions& options) {
  return write_outputs(out_dir, kSimulateFolder, file, simulation.samples,
                       simulation_result_json(file, simulation, options));
}

nlohmann::json write_optimization_outputs(const std::string& out_dir, const MotionFile& file,
                                          const OptimizationResult& result,
                                          const OptimizeOptions& options) {
  const nlohmann::json r = optimization_result_json(file, result, options);
  require_finite(r, file.path);
  require_finite(result.before.samples, file.path, "trajectory_before.csv");
  require_finite(result.after.samples, file.path, "trajectory_after.csv");
  // The optimised motion names the model copy written beside it, so the folder is
  // self-contained: `saltus evaluate DIR/optimized.motion.json` works wherever DIR goes.
  Motion optimized = result.optimized_motion;
  optimized.model = "model.json";
  const nlohmann::json optimized_json = motion_to_json(optimized, file.model);
  // Saltus writes no motion its own reader refuses (a take-off CoM at the 10 km bound came back
  // a hair past it): the swap does not happen, nothing is written, and the input is named.
  try {
    parse_motion(optimized_json, "optimized.motion.json", file.model);
  } catch (const InputError& e) {
    throw InputError(file.path, "",
                     std::string("its optimised motion would be refused by Saltus's own reader (") +
                         e.what() + "); nothing was written");
  }
  OutputFolder folder(out_dir, kOptimizeFolder);
  write_csv(folder, "trajectory_before.csv", file.model, result.before.samples);
  write_csv(folder, "trajectory_after.csv", file.model, result.after.samples);
  write_composed(folder.file("optimized.motion.json"),
                 [&](std::ostream& o) { o << optimized_json.dump(2) << '\n'; });
  write_common_files(folder, file, r);
  folder.commit();
  return r;
}

nlohmann::json write_twist_outputs(const std::string& out_dir, const MotionFile& file,
                                   const TwistSources& sources) {
  const nlohmann::json result = twist_result_json(file, sources);
  require_finite(result, file.path);
  OutputFolder folder(out_dir, kTwistFolder);
  write_text(folder.file("twist.csv"), twist_csv(sources));
  write_text(folder.file("twist.md"), twist_markdown(file, sources));
  write_text(folder.file("result.json"), result.dump(2) + "\n");
  folder.commit();
  return result;
}

nlohmann::json write_what_if_outputs(const std::string& out_dir, const MotionFile& file,
                                     const WhatIf& prepared, const WhatIfResult& result) {
  const nlohmann::json r = what_if_result_json(file, prepared, result);
  require_finite(r, file.path);
  require_finite(result.flight.samples, file.path, "trajectory.csv");
  OutputFolder folder(out_dir, kWhatIfFolder);
  write_text(folder.file("what_if.csv"), what_if_csv(prepared, result));
  write_csv(folder, "trajectory.csv", file.model, result.flight.samples);
  write_common_files(folder, file, r);
  folder.commit();
  return r;
}

nlohmann::json write_mass_outputs(const std::string& out_dir, const MotionFile& file,
                                  const MassStudyResult& study, const MassStudyOptions& options) {
  const nlohmann::json result = mass_result_json(file, study, options);
  OutputFolder folder(out_dir, kMassFolder);
  write_text(folder.file("mass.csv"), mass_study_csv(study));
  write_text(folder.file("mass.md"),
             "# Mass study: " + file.motion.name + "\n\n" + mass_study_markdown(study));
  write_text(folder.file("model.json"), body_model_to_json(study.runs[0].model).dump(2) + "\n");
  write_text(folder.file("model_scaled.json"),
             body_model_to_json(study.runs[1].model).dump(2) + "\n");
  write_text(folder.file("result.json"), result.dump(2) + "\n");
  folder.commit();
  return result;
}

}  // namespace saltus
