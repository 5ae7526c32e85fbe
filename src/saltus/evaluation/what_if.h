#pragma once
/// @file
/// What if the athlete tucked earlier, opened later or tucked tighter? The same take-off (CoM
/// position and velocity, angular momentum, body orientation and pose at t = 0), other timing or
/// shape of the tuck, flown again as a free flight (simulate.h): somersaults and twists at landing
/// against the flight as keyframed and against the landing the motion was keyframed to.
///
/// **The tuck** (or pike: any closing of the legs) is read off the legs' bend, the mean over the
/// hips and knees of each joint's rotation angle away from straight (the identity, the standing
/// pose), sampled at least every 2.5 ms. A motion has a tuck when the bend rises at least
/// kMinTuckBendDeg above its take-off value; straight and layout motions (M1, the twisting
/// layouts) have none, and what_if says so instead of inventing one. With rise = peak − take-off
/// bend and fall = peak − landing bend:
///  - the tuck-in runs from the last time before the peak that the bend is within 10 % of the
///    rise above its take-off value to the first time it reaches 90 % of the rise ("tucked");
///  - the opening runs from the last time the bend is within 10 % of the fall of its peak
///    ("opens") to the first time after that it is within 10 % of the fall above its landing
///    value ("open"). A motion whose bend falls less than kMinTuckBendDeg lands in its tuck and
///    has no opening to move.
///
/// **Shifting** the tuck (or the opening) by d moves both its times by d: the movement keeps its
/// speed and happens earlier or later, while the phases between (before the tuck, the hold in
/// the tuck, after the opening) are stretched or compressed. A tuck-in that begins within
/// kMinPhaseS of take-off keeps beginning at take-off (only "tucked" moves, the tuck-in itself
/// gets faster or slower); an opening that ends within kMinPhaseS of landing likewise. It is a
/// time warp of the joint movements, not of the root, which the free flight moves: every joint
/// follows its curve at w(t), where w maps the new clock to the motion's. On the tuck-in and the
/// opening w′ = 1 (they are moved whole); on each phase between, w′ = p, the ratio that fits its
/// old length into its new one, easing by a smoothstep from 1 at a moved time to p over δ (at
/// most kWarpBlendS, a quarter of the phase), so that the moved times land exactly where asked
/// and the joints' velocity and acceleration stay continuous: ω(t) = ω(w)·w′,
/// α(t) = α(w)·w′² + ω(w)·w″. No phase is made
/// more than kMaxPhaseSpeedUp times faster; each shift's range (TuckPhases) holds whatever the
/// other shift is.
///
/// **Tightness** s scales how far the hips and knees turn away from their take-off pose:
/// every control point c_j of their curves becomes c_0·exp(s·log(c_0⁻¹·c_j)), c_0 the take-off
/// rotation, so the take-off pose stays and a joint that only flexes (one axis) turns s times as
/// far at every instant.

#include <Eigen/Geometry>
#include <functional>
#include <string>
#include <vector>

#include "saltus/base/number_bound.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/evaluation/yeadon_angles.h"

namespace saltus {

/// The least rise of the legs' bend above take-off that counts as a tuck or pike, degrees.
inline constexpr double kMinTuckBendDeg = 45.0;
/// The share of the rise (fall) that marks the start and end of the tuck-in (opening).
inline constexpr double kTuckPhaseLevel = 0.1;
/// A tuck-in starting (an opening ending) closer than this to take-off (landing) is taken to
/// start (end) there, s.
inline constexpr double kMinPhaseS = 0.05;
/// No phase between the tuck's times is played more than this many times faster.
inline constexpr double kMaxPhaseSpeedUp = 2.0;
/// The time warp eases from a moved phase's speed to a stretched one's over at most this, s.
inline constexpr double kWarpBlendS = 0.03;
/// Tuck tightness: the range of the scale of the hips' and knees' turn.
inline constexpr double kMinTuckScale = 0.8;
inline constexpr double kMaxTuckScale = 1.2;
inline constexpr NumberBound kTuckScaleBound{kMinTuckScale, kMaxTuckScale};
/// What a refused --tuck-scale is told beside the bound.
inline constexpr char kTuckScaleWhy[] = "the tuck's tightness: 80 to 120 % of the motion's";
/// A landing within this of the keyframed one, in somersault and in twist, is on target, °.
inline constexpr double kDefaultLandingToleranceDeg = 15.0;

/// What a coach changes: the same take-off, other timing or shape of the tuck.
struct WhatIfChange {
  double tuck_later_s = 0.0;  ///< the tuck-in this much later (< 0: earlier), s
  double open_later_s = 0.0;  ///< the opening this much later (< 0: earlier), s
  double tuck_scale = 1.0;    ///< the hips' and knees' turn from take-off × this (1: as is)
  bool unchanged() const { return tuck_later_s == 0.0 && open_later_s == 0.0 && tuck_scale == 1.0; }
};

/// A motion's tuck by the rule above, and how far it can move.
struct TuckPhases {
  bool found = false;
  std::string reason;  ///< without a tuck: why, in words ("The legs bend at most 9° ...")
  double takeoff_bend_deg = 0.0;
  double peak_bend_deg = 0.0;
  double peak_time_s = 0.0;
  double landing_bend_deg = 0.0;
  double tuck_start_s = 0.0;  ///< the tuck-in begins
  double tucked_s = 0.0;      ///< the tuck is reached
  bool opens = false;         ///< false: lands in the tuck (open_start_s = opened_s = T)
  double open_start_s = 0.0;  ///< the opening begins
  double opened_s = 0.0;      ///< the legs are open
  /// Whether the tuck-in starts at take-off and the opening ends at landing (kMinPhaseS).
  bool starts_at_takeoff = false;
  bool opened_at_landing = false;
  /// The shifts this motion allows, s (0 and 0 for a shift it does not have).
  double tuck_later_min_s = 0.0;
  double tuck_later_max_s = 0.0;
  double open_later_min_s = 0.0;
  double open_later_max_s = 0.0;
  /// The bend over time the rule read: degrees at `times`.
  std::vector<double> times;
  std::vector<double> bend_deg;
};

/// A joint's rotation relative to its parent (segment index ≥ 1) at a time.
using JointRotationAt = std::function<Eigen::Quaterniond(int segment, double t)>;

/// The tuck of joint movements over [0, duration] (the rule above); found == false, with the
/// reason, without one.
TuckPhases find_tuck(const JointRotationAt& rotation_at, double duration, const BodyModel& model);
/// The same of a trajectory's joint curves.
TuckPhases find_tuck(const Trajectory<double>& trajectory, const BodyModel& model);

/// One what-if flight and how it lands.
struct WhatIfResult {
  WhatIfChange change;
  /// "opening 0.05 s later, tuck 10 % tighter", or "as keyframed".
  std::string change_words;
  TuckPhases tuck;          ///< of the changed joint movements
  SimulationResult flight;  ///< its free flight from the unchanged take-off
  YeadonSummary landing;    ///< Yeadon's counts of `flight`
  /// Landing against the motion as keyframed (its root curve, which ends at its last keyframe),
  /// degrees in the direction of its rotation: > 0 turned past it ("over"), < 0 short of it.
  double somersault_over_deg = 0.0;
  double twist_over_deg = 0.0;
  /// The same against the flight of the unchanged motion (0 for no change).
  double somersault_vs_unchanged_deg = 0.0;
  double twist_vs_unchanged_deg = 0.0;
  double tolerance_deg = kDefaultLandingToleranceDeg;
  bool within_tolerance = false;  ///< both |over| within tolerance_deg
  /// "you land 14° over in somersault, 3° short in twist"
  std::string verdict;
  /// "Same take-off, opening 0.05 s later: 2.04 somersaults, 1.52 twists — you land 14° over in
  /// somersault, 3° short in twist (more than 15° off)."
  std::string sentence;
};

/// A motion prepared for what-if flights: its trajectory, take-off, tuck, the flight as it is
/// and the landing it was keyframed to, worked out once; each fly() is one free flight. fly() is
/// const and may run on several threads at once.
class WhatIf {
 public:
  /// The take-off angular momentum is simulate_motion's: the motion file's, or the constant that
  /// best fits the motion's own L(t). Throws std::invalid_argument for bad options.
  WhatIf(const Motion& motion, const BodyModel& model, const EvaluateOptions& options = {},
         double tolerance_deg = kDefaultLandingToleranceDeg);

  const TuckPhases& tuck() const { return tuck_; }
  /// The motion's free flight as it is, from the same take-off: what each change is against.
  const SimulationResult& unchanged() const { return unchanged_; }
  const YeadonSummary& unchanged_landing() const { return unchanged_landing_; }
  /// The motion as keyframed (its root curve): the landing it aims at.
  const YeadonSummary& target() const { return target_; }
  const Eigen::Vector3d& angular_momentum() const { return takeoff_.value; }

  /// The flight with `change`. No change gives exactly the unchanged flight. Throws InputError
  /// naming the flag (--tuck-later, --open-later, --tuck-scale) for a change the motion does
  /// not allow: a number that is not finite, a tuck change without a tuck (the reason), an
  /// opening moved without one, a shift outside its range, a tightness outside
  /// kMinTuckScale..kMaxTuckScale.
  WhatIfResult fly(const WhatIfChange& change) const;

 private:
  Motion motion_;
  BodyModel model_;
  EvaluateOptions options_;
  double tolerance_deg_;
  Trajectory<double> trajectory_;
  TakeoffMomentum takeoff_;
  TuckPhases tuck_;
  SimulationResult unchanged_;
  YeadonSummary unchanged_landing_;
  YeadonSummary target_;
};

/// One what-if flight: WhatIf(motion, model, options).fly(change).
WhatIfResult what_if(const Motion& motion, const BodyModel& model, const WhatIfChange& change,
                     const EvaluateOptions& options = {});

/// "opening 0.05 s later, tuck 10 % tighter"; "as keyframed" for no change.
std::string what_if_change_words(const WhatIfChange& change);

}  // namespace saltus
