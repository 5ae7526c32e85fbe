#pragma once
/// @file
/// "Can this athlete land it?": the open motion's take-off flown by an athlete's body (the motion
/// carried over to it with the same take-off spin, as `saltus simulate --model` flies it), its
/// free flight as the library flies it (WhatIf's flight of the motion as keyframed: simulate's
/// flight, with Yeadon's counts and the landing against the keyframes), the joints' share of
/// that athlete's strength with a traffic light, and after a run on that athlete the warnings of
/// `saltus optimize` in its words. The headline leads with the failure, so that no one reads
/// success into it.

#include <optional>
#include <string>
#include <vector>

#include "core/joint_load_view.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/motion/motion.h"
#include "saltus/optim/optimize.h"

namespace saltus::gui {

/// One joint's peak moment against the athlete's strength.
struct JointStrengthRow {
  std::string joint;            ///< "Left knee", as people name it
  std::optional<double> share;  ///< of the athlete's strength; none without a curve
  StrengthLight light = StrengthLight::kUnknown;
};

struct AthleteLanding {
  std::string athlete;  ///< athlete_label: "junior 1.45 m 38 kg, same take-off spin"
  bool lands = false;   ///< within the library's landing tolerance in somersault and twist
  double tolerance_deg = 0.0;
  /// "Lands it: 3° from the keyframed landing (within 15°)" or "Does not land it: the body is
  /// 171° off the last keyframe at landing (more than 15° off)".
  std::string headline;
  /// The free flight and the landing it was keyframed to, in Yeadon's words: "Flies 1¾ front
  /// somersaults with 2 twists to the left; keyframed: 2 front somersaults with 1½ twists to the
  /// left".
  std::string flight_words;
  /// The library's sentence of that flight: "… 1.75 somersaults, 2.00 twists — you land 91°
  /// short in somersault, 180° over in twist (more than 15° off)."
  std::string sentence;
  double landing_error_deg = 0.0;  ///< whole body at landing against the last keyframe
  SimulationResult flight;         ///< the free flight (its last sample: the landing pose)
  /// The joints' largest shares of this athlete's strength (of the optimised motion with a run,
  /// else of the keyframes' interpolation on this body; evaluation/strength_demand.h).
  std::vector<JointStrengthRow> joints;
  /// strength_verdict_words and over_strength_lines, as `saltus evaluate` and `optimize` print
  /// them: "2 joints beyond the athlete's strength (largest: …)", one line per such joint.
  std::string strength_words;
  std::vector<std::string> over_strength;
  StrengthLight strength_light = StrengthLight::kUnknown;  ///< of the largest share
  /// With a run on this athlete: joint_load_verdict_words when a joint pays, and
  /// human_joints_warning when this body does not fly the keyframes with human joints.
  std::vector<std::string> warnings;
};

/// The check for `on_athlete` (the motion already carried over to the athlete:
/// load_motion_for_athlete or motion_on_athlete; or the motion on its own model); `run`, a
/// result of optimising that motion on that body, adds its joints and warnings. Throws like
/// the library for bad options.
AthleteLanding athlete_landing(const MotionFile& on_athlete, const EvaluateOptions& options,
                               const OptimizationResult* run = nullptr);

}  // namespace saltus::gui
