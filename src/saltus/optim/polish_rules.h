#pragma once
/// @file
/// The rules by which optimize_motion's polish (least joint effort, kPolishTries in optimize.h)
/// judges each try from its figures alone: whether it lands and may be kept, whether it ends the
/// bounded tries, whether a kept try is solved again with tighter bounds, whether the closest
/// bounded try is solved again on finer knots before the unbounded one, and which bounded try
/// is kept when none holds (the fallback). optimize_motion's ladder runs the solves and asks
/// these; the unit tests hold each rule on its edges without an optimisation.

#include <optional>

#include "saltus/optim/optimize.h"

namespace saltus {

/// What the ladder compares a try with: the motion the polish started from, as the levels left
/// it.
struct PolishBaseline {
  double avg_root_force = 0.0;     ///< N, the levels' dense check
  double landing_drift_deg = 0.0;  ///< the levels' free flight
  /// Whether the levels' motion makes a joint pay for the root force: its largest joint rise
  /// against the input past kJointLoadRiseLimit.
  bool joints_pay = false;
  /// AutomaticResolution::max_landing_drift_deg.
  double max_landing_drift_deg = AutomaticResolution{}.max_landing_drift_deg;
};

/// A try's figures once it has solved and flown.
struct PolishTryFigures {
  bool solved = false;
  double avg_root_force = 0.0;     ///< N, its dense check
  double landing_drift_deg = 0.0;  ///< its own free flight
};

/// Lands as a kept try must: within max_landing_drift_deg, or no farther than the levels.
bool polish_try_lands(const PolishTryFigures& figures, const PolishBaseline& baseline);

/// May be kept: solved, its root force within kPolishMaxRootForce or no larger than the levels'
/// (root_force_within_limit), and landing so.
bool polish_try_holds(const PolishTryFigures& figures, const PolishBaseline& baseline);

/// A bounded try not kept that lands farther than kPolishHopelessDriftFactor times
/// max_landing_drift_deg, and farther than the levels: no later bounded step will land (the
/// ladder skips them and goes on to its unbounded try).
bool polish_bounded_tries_hopeless(const PolishTry& attempt, bool kept,
                                   const PolishTryFigures& figures, const PolishBaseline& baseline);

/// A kept try whose largest joint rise (dense, over the input's peaks) passed kJointLoadRiseLimit
/// between the nodes that bound it: solved once more with those bounds lowered.
bool polish_tightens(bool kept, double joint_rise);

/// Before the unbounded try, over a motion whose joints pay: the bounded try over the limit
/// (polish_over_limit_candidate) solved again on finer knots. Only where the resolution is the
/// optimiser's to choose.
bool polish_refines_before_unbounded(const PolishTry& next, bool automatic,
                                     const PolishBaseline& baseline, bool have_over_limit);

/// A bounded try that solved and landed but is not kept (its root force past the limit): the one
/// with the least root force is the over-limit candidate. True when this try replaces `current`
/// (the candidate's root force, N; none yet: nullopt).
bool polish_over_limit_candidate(const PolishTry& attempt, bool kept,
                                 const PolishTryFigures& figures, const PolishBaseline& baseline,
                                 std::optional<double> current);

/// When no try is kept and the levels' motion makes a joint pay, the bounded try that solved and
/// landed with the least root force up to kPolishMaxRootForceOverPayingJoints is kept instead.
/// True when this try replaces the current fallback (its root force, N; none yet: nullopt).
bool polish_fallback_candidate(const PolishTry& attempt, bool kept, const PolishTryFigures& figures,
                               const PolishBaseline& baseline, std::optional<double> current);

}  // namespace saltus
