#pragma once
/// @file
/// The result folders of `saltus evaluate`, `saltus simulate` and `saltus optimize`
/// (docs/formats.md): result.json, the trajectory CSVs, model.json and optimized.motion.json,
/// written all or nothing (OutputFolder) and read back here. result.json records the options of the
/// option table (optim/option_table.h) under their result keys.

#include <Eigen/Core>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "saltus/evaluation/clearance.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/keyframe_spacing.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/evaluation/strength_demand.h"
#include "saltus/evaluation/yeadon_angles.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/trajectory_csv.h"
#include "saltus/optim/optimize.h"
#include "saltus/optim/option_table.h"

namespace saltus {

/// result.json's "format".
inline constexpr const char* kResultFormatTag = "saltus-result/1";

/// result.json as data: what the writers below put in it and read_result_json reads back.
/// Keys added after the first release (restarts, tolerances, ...) may be missing from older
/// files; they read as empty.
struct ResultJson {
  enum class Kind { kEvaluation, kSimulation, kOptimization };
  Kind kind = Kind::kEvaluation;
  std::string format = kResultFormatTag;
  std::string status;          ///< "evaluated", "simulated", or the solver's ("solved", ...)
  std::string motion;          ///< the motion's name
  std::string motion_file;     ///< the motion file as given
  std::string model;           ///< the body model's name
  int knots_per_interval = 1;  ///< the refinement K used
  double flight_time_s = 0.0;
  int keyframes = 0;
  /// The options recorded (OptionSpec::result_key and value), in table order.
  std::vector<std::pair<std::string, OptionValue>> options;
  ForceMetrics before;  ///< the evaluated, simulated or interpolated ("before") motion
  std::vector<double> keyframe_times_before;
  /// How the residual figures were computed (the dense check); evaluations and optimisations.
  struct ResidualCheck {
    std::string rule;
    int points = 0;
    /// Times the check halved its spacing, and whether J then changed by no more than its
    /// tolerance; missing from files before the halving.
    std::optional<int> halvings;
    std::optional<bool> converged;
    std::optional<bool> optimizer_agrees;  ///< optimisations: its quadrature agrees with it
    /// Each keyframe interval's share of the check's ∫ΣF² dt, at the motion's keyframe times
    /// (evaluation/force_metrics.h residual_shares); empty in files before it.
    std::vector<double> share_by_keyframe_interval;
  };
  std::optional<ResidualCheck> residual_check;
  /// Of the evaluated or the optimised motion; none for simulations (null in the file).
  std::optional<KeyframeErrors> keyframe_errors;
  std::optional<Eigen::Vector3d> takeoff_angular_momentum;  ///< evaluations and simulations
  /// The motion flown by another athlete than its own: how its take-off was carried over
  /// (MotionFile::takeoff_adaptation); missing otherwise.
  std::optional<TakeoffAdaptation> takeoff_adaptation;
  /// Body weight m·g (N), the scale of "% of body weight"; missing from files before it.
  std::optional<double> body_weight_N;
  /// The peak load at each joint on the dense check's points (force N, moment N·m about the
  /// joint centre, and when): of the evaluated or interpolated ("before") motion and, for
  /// optimisations, of the optimised one; in model order, the root left out. Evaluations and
  /// optimisations; missing from files before it.
  struct JointLoad {
    std::string joint;
    JointLoadPeak before;
    std::optional<JointLoadPeak> after;
  };
  std::vector<JointLoad> joint_loads;
  /// Each joint's largest share of the athlete's strength and when (evaluation/
  /// strength_demand.h), over the dense check's points: of the evaluated or interpolated
  /// ("before") motion and, for optimisations, of the optimised one ("after"); joints with a
  /// strength curve, model order. Missing from files before it.
  struct JointStrength {
    std::string joint;       ///< "hip_l"
    std::string coordinate;  ///< "hip_flexion_l" (body/joint_coordinates.h)
    std::string direction;   ///< "flexion"
    std::string words;       ///< "left hip flexion"
    double share = 0.0;
    double time_s = 0.0;
    double moment_Nm = 0.0;
    double capacity_Nm = 0.0;
    double angle_deg = 0.0;
    double shortening_speed_rad_s = 0.0;
    bool extrapolated = false;
    std::string source;  ///< the curve's ("Anderson et al. 2007, men 18-25")
  };
  std::vector<JointStrength> strength_before, strength_after;
  /// strength_verdict_words of each, and whose strength it is ("population, male, 21 years").
  std::string strength_verdict_before, strength_verdict_after, strength_reference;
  /// Yeadon's somersaults, twists, largest tilt and peak twist rate (evaluation/yeadon_angles.h)
  /// of the evaluated, simulated or interpolated motion and of the optimised one; missing from
  /// files before them. A simulation's peak rate is not known (its samples hold no ω): 0.
  std::optional<YeadonSummary> rotation_before, rotation_after;
  /// The keyframe intervals of the evaluated or input motion too far apart for its twist
  /// (evaluation/keyframe_spacing.h), as "sparse_twist_intervals"; empty when every interval
  /// holds, for simulations and in files before it.
  std::vector<SparseTwistInterval> sparse_twist_intervals;
  /// The closest pass of the body to the apparatus (evaluation/clearance.h; its per-sample series
  /// is not written: times and distance read back empty) and, for dives, the entry into the
  /// water; of the evaluated or simulated motion, missing from optimisations and older files.
  std::optional<ApparatusClearance> clearance;
  std::optional<DiveEntry> entry;

  struct Simulation {
    /// "motion file", or "best constant fit to the motion's L(t)" ("keyframes" in older files)
    std::string angular_momentum_source;
    std::optional<double> angular_momentum_spread;  ///< kg·m²/s, RMS of L(t) about it
    double landing_root_error_deg = 0.0;
    std::map<std::string, double> landing_joint_error_deg;  ///< joint name -> degrees
    double landing_com_error_m = 0.0;
    std::optional<double> landing_root_vs_motion_deg;
  };
  std::optional<Simulation> simulation;

  struct Optimization {
    int iterations = 0;
    double solve_seconds = 0.0;
    int variables = 0;
    int constraints = 0;
    ForceMetrics after;
    /// J by the optimiser's own quadrature at the start and the end, written into "before"
    /// and "after" with its average root force.
    std::optional<double> optimizer_objective_before, optimizer_objective_after;
    std::vector<double> keyframe_times_after;
    /// Per keyframe, how far its optimised time could move (s) before the residual rises by
    /// kTimeSpreadForceRise, and the keyframes whose spread exceeds kDeterminedTimeSpread
    /// (OptimizationResult::keyframe_time_spreads); missing from files before them.
    std::optional<std::vector<double>> keyframe_time_spreads;
    std::vector<int> keyframe_times_undetermined;
    std::optional<std::string> ipopt_status;
    std::optional<int> restarts;
    std::optional<Tolerances> tolerances;
    /// Largest joint turn between two control points (°), before and after.
    std::optional<std::pair<double, double>> largest_joint_turn_deg;
    /// The knots the optimised motion lives on and how the automatic resolution chose them
    /// (OptimizationResult::subdivisions, levels); missing from files before it.
    struct Resolution {
      bool automatic = false;         ///< chosen automatically (relaxed model, `auto` knots)
      std::vector<int> subdivisions;  ///< knot spans per keyframe interval
      std::vector<double> knots;      ///< of the optimised motion's splines (s)
      std::vector<OptimizationResult::Level> levels;  ///< each level tried, in order
      /// The last solve with least joint effort, when there was one.
      std::optional<JointLoadPolish> joint_load_polish;
      /// OptimizationResult::landing_drift_deg, when measured.
      std::optional<double> landing_drift_deg;
      /// OptimizationResult::twist_guided_intervals; empty in files before it.
      std::vector<int> twist_guided_intervals;
    };
    std::optional<Resolution> resolution;
  };
  std::optional<Optimization> optimization;

  /// The value recorded for `result_key`, if any.
  std::optional<OptionValue> option(const std::string& result_key) const;
};

/// The document to write; `parse_result_json(result_to_json(r)) == r`.
nlohmann::json result_to_json(const ResultJson& result);
/// Reads a result.json document. Throws InputError naming `file` and the JSON field.
ResultJson parse_result_json(const nlohmann::json& document, const std::string& file);
ResultJson read_result_json(const std::string& path);

/// before/after block of result.json.
nlohmann::json force_metrics_to_json(const ForceMetrics& metrics);
/// Yeadon's summary of a flight as result.json's "rotation" blocks write it (somersaults,
/// twists, description, max_tilt_deg, peak twist rate and its time).
nlohmann::json rotation_json(const YeadonSummary& summary);
/// One joint's peak load as result.json writes it: force (N, % of `body_weight` N, time) and
/// moment (N·m, time).
nlohmann::json joint_peak_json(const JointLoadPeak& peak, double body_weight);

/// What result.json records of an evaluation, a simulation and an optimisation.
ResultJson evaluation_result(const MotionFile& file, const MotionEvaluation& evaluation,
                             const EvaluateOptions& options);
ResultJson simulation_result(const MotionFile& file, const SimulationResult& simulation,
                             const EvaluateOptions& options);
ResultJson optimization_result(const MotionFile& file, const OptimizationResult& result,
                               const OptimizeOptions& options);

/// result.json of an evaluation ("before" filled; optimiser-only fields null).
nlohmann::json evaluation_result_json(const MotionFile& file, const MotionEvaluation& evaluation,
                                      const EvaluateOptions& options);

/// result.json of a free-flight simulation: the evaluation fields for the simulated flight plus
/// "takeoff_angular_momentum" and "landing".
nlohmann::json simulation_result_json(const MotionFile& file, const SimulationResult& simulation,
                                      const EvaluateOptions& options);

/// result.json of an optimisation: before and after, solver figures, keyframe times before and
/// after, keyframe errors of the optimised motion.
nlohmann::json optimization_result_json(const MotionFile& file, const OptimizationResult& result,
                                        const OptimizeOptions& options);

/// A result folder read back: result.json and its trajectories.
struct ResultFolder {
  std::string path;
  std::string name;  ///< the folder's own name
  ResultJson result;
  /// trajectory.csv, or an optimisation's trajectory_before.csv.
  TrajectoryCsv before;
  std::optional<TrajectoryCsv> after;  ///< an optimisation's trajectory_after.csv
};

/// Reads a `saltus evaluate`, `simulate` or `optimize` output folder. Throws InputError naming
/// the file (and field) that is missing or malformed.
ResultFolder read_result_folder(const std::string& dir);

/// The folder's own name ("out" for "a/out" and "a/out/").
std::string folder_name(const std::string& dir);
/// DIR/name, which must exist; throws InputError naming the folder or the file as not `what`
/// ("a `saltus study mass` folder").
std::string output_file(const std::string& dir, const std::string& name, const std::string& what);
/// Whether DIR/result.json parses as an object whose string `key` is `value` ("study": "mass",
/// "analysis": "twist"). Anything else is false, so that another reader can say what is wrong.
bool result_json_says(const std::string& dir, const std::string& key, const std::string& value);

}  // namespace saltus
