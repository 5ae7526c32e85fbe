#pragma once
/// @file
/// The result folders of `saltus evaluate`, `saltus simulate` and `saltus optimize` (DESIGN §6):
/// result.json, the trajectory CSVs, model.json and optimized.motion.json, all or nothing
/// (OutputFolder).

#include <nlohmann/json.hpp>
#include <string>

#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/optim/optimize.h"

namespace saltus {

/// before/after block of result.json.
nlohmann::json force_metrics_to_json(const ForceMetrics& metrics);

/// result.json of an evaluation ("before" filled; optimiser-only fields null).
nlohmann::json evaluation_result_json(const MotionFile& file, const MotionEvaluation& evaluation,
                                      const EvaluateOptions& options);

/// result.json of a free-flight simulation: the evaluation fields for the simulated flight plus
/// "takeoff_angular_momentum" and "landing".
nlohmann::json simulation_result_json(const MotionFile& file, const SimulationResult& simulation,
                                      const EvaluateOptions& options);

/// Writes result.json, trajectory.csv and model.json into `out_dir` atomically.
/// Returns the result.json written.
nlohmann::json write_evaluation_outputs(const std::string& out_dir, const MotionFile& file,
                                        const MotionEvaluation& evaluation,
                                        const EvaluateOptions& options);
nlohmann::json write_simulation_outputs(const std::string& out_dir, const MotionFile& file,
                                        const SimulationResult& simulation,
                                        const EvaluateOptions& options);

/// result.json of an optimisation: before and after, solver figures, keyframe times before and
/// after, keyframe errors of the optimised motion.
nlohmann::json optimization_result_json(const MotionFile& file, const OptimizationResult& result,
                                        const OptimizeOptions& options);

/// Writes result.json, trajectory_before.csv, trajectory_after.csv, model.json and
/// optimized.motion.json into `out_dir` atomically. Returns the result.json written.
nlohmann::json write_optimization_outputs(const std::string& out_dir, const MotionFile& file,
                                          const OptimizationResult& result,
                                          const OptimizeOptions& options);

}  // namespace saltus
