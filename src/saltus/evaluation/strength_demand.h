#pragma once
/// @file
/// What a motion asks of the athlete's strength: at each instant, each joint's moment split into
/// its anatomical coordinates (body/joint_coordinates.h) and set against the athlete's capacity
/// in that direction at that angle and speed (body/joint_strength.h). A share of 1 is everything
/// the athlete's muscles can give there; the report names, per joint, the instant of its largest
/// share (docs/method.md, "Strength").

#include <Eigen/Core>
#include <string>
#include <vector>

#include "saltus/body/joint_strength.h"
#include "saltus/dynamics/body_state.h"

namespace saltus {

/// One joint's largest demand at one instant, over its directions with a strength curve.
struct StrengthDemand {
  double share = 0.0;      ///< moment / capacity; 0 where no direction has a curve
  int coordinate = -1;     ///< Cardan index of the direction's coordinate; -1: none covered
  bool positive = true;    ///< the coordinate's positive direction (JointCoordinate::positive)
  double moment_Nm = 0.0;  ///< the generalised moment in that direction, >= 0
  double capacity_Nm = 0.0;
  double angle_rad = 0.0;         ///< the coordinate's value
  double shortening_speed = 0.0;  ///< rad/s in that direction; negative: lengthening
  bool extrapolated = false;      ///< the capacity used a curve's floor (joint_strength.h)
};

/// The demand at the joint of `segment` (>= 1) in state `joint` carrying `moment_child` (the
/// moment the parent exerts on the child at the joint, child frame, N·m).
StrengthDemand strength_demand(const AthleteStrength& strength, int segment,
                               const JointState<double>& joint,
                               const Eigen::Vector3d& moment_child);

/// A joint's largest demand over a flight, and when.
struct JointStrengthPeak : StrengthDemand {
  double time_s = 0.0;
};

/// "left hip flexion" for the peak's direction ("lower back extension", "right ankle plantar
/// flexion"); "" where no direction is covered.
std::string strength_direction_words(const BodyModel& model, int segment,
                                     const StrengthDemand& demand);

/// The joints whose largest share exceeds 1, one line each, largest first: "left hip flexion
/// would need 130 % of her strength at t = 0.42 s (142 of 109 N·m at 95°, shortening at
/// 3.1 rad/s)". `peaks` per segment (index 0 ignored); "her"/"his" from the model's strength.
std::vector<std::string> over_strength_lines(const BodyModel& model,
                                             const std::vector<JointStrengthPeak>& peaks);

/// One sentence for the largest share: "every joint within the athlete's strength (largest:
/// right knee extension, 64 % at t = 0.31 s)", or "2 joints beyond the athlete's strength
/// (largest: left hip flexion, 130 % at t = 0.42 s)".
std::string strength_verdict_words(const BodyModel& model,
                                   const std::vector<JointStrengthPeak>& peaks);

/// The segment whose peak share is largest (>= 1), or 0 when no joint is covered.
int largest_strength_share(const std::vector<JointStrengthPeak>& peaks);

}  // namespace saltus
