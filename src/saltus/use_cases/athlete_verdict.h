#pragma once
/// @file
/// "Can this athlete land it?" as one verdict, so that no one reads success into a failure: the
/// motion's free flight from its take-off (WhatIf's flight as keyframed: simulate's flight,
/// judged in somersault and twist against the keyframed landing with the library's tolerance)
/// and its joints against the athlete's strength (evaluation/strength_demand.h), with a run the
/// warnings of `saltus optimize` on its joints. Green only when it lands and every joint is
/// within the athlete's strength; amber when it lands but asks a joint for more (or the strength
/// is unknown, or the optimiser made a joint pay for the root force); red when it does not land,
/// or when with human joints this body does not fly the keyframes. `saltus evaluate` and
/// `optimize` print it, the app shows it (docs/app.md, "Can this athlete land it?").

#include <string>
#include <vector>

#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/motion/motion.h"
#include "saltus/optim/optimize.h"

namespace saltus {

enum class VerdictLight { kGreen, kAmber, kRed };

/// "green", "amber", "red".
std::string verdict_light_name(VerdictLight light);

struct AthleteVerdict {
  VerdictLight light = VerdictLight::kRed;
  /// One line that leads with the verdict: "Lands it: you land on target (within 15°); every
  /// joint within the athlete's strength (largest: …)", "Lands it, but 2 joints beyond the
  /// athlete's strength (largest: left hip extension, 352 % at t = 0.84 s)", "Does not land it:
  /// you land 91° short in somersault, 180° over in twist (more than 15° off)".
  std::string headline;
  /// The verdict in a few words, for a line with no room (a status bar): "Lands it within the
  /// athlete's strength", "Lands it, but 8 joints beyond the athlete's strength", "Does not
  /// land it".
  std::string summary;
  /// The lines under it, in the CLI's words: each joint beyond the athlete's strength
  /// (over_strength_lines), and with a run joint_load_verdict_words when a joint pays and
  /// human_joints_warning when it applies.
  std::vector<std::string> reasons;
  bool lands = false;  ///< the free flight within tolerance_deg in somersault and twist
  double tolerance_deg = 0.0;
  double somersault_over_deg = 0.0;  ///< WhatIfResult's: > 0 turned past the keyframed landing
  double twist_over_deg = 0.0;
  double landing_error_deg = 0.0;  ///< whole body at landing against the last keyframe
  /// The free flight and the landing it was keyframed to, in Yeadon's words: "Flies 1¾ front
  /// somersaults with 2 twists to the left; keyframed: 2 front somersaults with 1½ twists to
  /// the left".
  std::string flight_words;
  SimulationResult flight;  ///< the free flight (its last sample: the landing pose)
  /// strength_verdict_words of `strength_peaks`.
  std::string strength_words;
  /// Per segment (index 0 unused), of the motion judged (evaluation/strength_demand.h).
  std::vector<JointStrengthPeak> strength_peaks;
};

/// The verdict on `file`'s motion as keyframed on its model; `evaluation` is
/// evaluate_motion(file.motion, file.model, options) (as `saltus evaluate` has it). Throws
/// std::invalid_argument for bad options.
AthleteVerdict athlete_verdict(const MotionFile& file, const EvaluateOptions& options,
                               const MotionEvaluation& evaluation);
/// The same, evaluating the motion.
AthleteVerdict athlete_verdict(const MotionFile& file, const EvaluateOptions& options);
/// The verdict on a run of optimize_motion on `file`: its optimised motion
/// (OptimizationResult::optimized_motion, flown from its own take-off) and its joints, with the
/// run's warnings.
AthleteVerdict athlete_verdict(const MotionFile& file, const EvaluateOptions& options,
                               const OptimizationResult& run);

}  // namespace saltus
