#pragma once
/// @file
/// What a run of optimize_motion comes to, as the optimiser itself judges its solves and tries:
/// solved before not, a run whose joints keep to the joint policy (no joint's peak load past
/// kJointLoadRiseLimit times its input's: the bar the least-joint-effort tries are held to)
/// before one whose joints pay for the root force, then the least average root force. The app
/// ranks its runs by it, so that no run is shown as the best by root force alone; and the
/// warning the CLI prints when this body does not fly the keyframes with human joints.

#include <string>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/optim/optimize.h"

namespace saltus {

/// A run's standing.
struct ResultStanding {
  bool solved = false;  ///< SolveReport::solved: false for a cancelled or stopped run too
  /// Every joint's peak load after within kJointLoadRiseLimit of its peak before (the
  /// interpolated input's, on the dense check).
  bool joints_within_policy = false;
  double avg_root_force = 0.0;  ///< N, after (the dense check)
  JointLoadRise largest_rise;   ///< the joint that rose most
};

ResultStanding result_standing(const OptimizationResult& result, const BodyModel& model);

/// Whether `a` ranks above `b`: solved first, then the joints within the policy, then the
/// smaller average root force. Neither above the other when all three tie.
bool ranks_above(const ResultStanding& a, const ResultStanding& b);

/// The CLI's warning when the run made a joint pay (its largest rise past kJointLoadRiseLimit)
/// and the least-joint-effort try that kept the joints within their bound flies off
/// (JointLoadPolish::bounded_alternative landing more than
/// AutomaticResolution::max_landing_drift_deg from it): "with human joints instead: the
/// polish's bounded try closest to flying as shown (every joint within 1.21x its input peak,
/// 0.53 N) has a free flight that lands 171 deg from it: with the joints its input needs, this
/// body does not fly these keyframes". Empty when it does not apply.
std::string human_joints_warning(const OptimizationResult& result, const JointLoadRise& rise);

}  // namespace saltus
