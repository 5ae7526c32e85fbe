#pragma once
/// @file
/// Writing a run's result folder (docs/formats.md, "Result folders"): the files of `saltus
/// evaluate`, `simulate`, `optimize`, `analyse twist|what-if` and `study mass`, each composed by
/// its format's writer, checked finite, and committed all or nothing (formats/output_folder.h).

#include <nlohmann/json.hpp>
#include <string>

#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/evaluation/twist_sources.h"
#include "saltus/evaluation/what_if.h"
#include "saltus/formats/motion_file.h"
#include "saltus/optim/optimize.h"
#include "saltus/studies/mass_study.h"

namespace saltus {

/// Writes result.json, trajectory.csv and model.json into `out_dir` atomically.
/// Returns the result.json written.
nlohmann::json write_evaluation_outputs(const std::string& out_dir, const MotionFile& file,
                                        const MotionEvaluation& evaluation,
                                        const EvaluateOptions& options);
nlohmann::json write_simulation_outputs(const std::string& out_dir, const MotionFile& file,
                                        const SimulationResult& simulation,
                                        const EvaluateOptions& options);

/// Writes result.json, trajectory_before.csv, trajectory_after.csv, model.json and
/// optimized.motion.json into `out_dir` atomically. Returns the result.json written.
nlohmann::json write_optimization_outputs(const std::string& out_dir, const MotionFile& file,
                                          const OptimizationResult& result,
                                          const OptimizeOptions& options);

/// DIR/{result.json, twist.csv, twist.md} of `saltus analyse twist`, atomically.
nlohmann::json write_twist_outputs(const std::string& out_dir, const MotionFile& file,
                                   const TwistSources& sources);

/// DIR/{result.json, what_if.csv, trajectory.csv (the what-if flight), model.json} of `saltus
/// analyse what-if`, atomically.
nlohmann::json write_what_if_outputs(const std::string& out_dir, const MotionFile& file,
                                     const WhatIf& prepared, const WhatIfResult& result);

/// DIR/{result.json, mass.csv, mass.md, model.json (given), model_scaled.json} atomically.
nlohmann::json write_mass_outputs(const std::string& out_dir, const MotionFile& file,
                                  const MassStudyResult& study, const MassStudyOptions& options);

}  // namespace saltus
