#pragma once
/// @file
/// `optimize_motion`: interpolation ("before"), the NLP, Ipopt, and the optimised motion
/// ("after") evaluated on the same grid — the one call behind `saltus optimize` and the GUI.

#include <atomic>
#include <iterator>
#include <optional>
#include <string>

#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/keyframe_spacing.h"
#include "saltus/optim/automatic_resolution.h"
#include "saltus/optim/motion_nlp.h"
#include "saltus/optim/solve_policy.h"

namespace saltus {

struct OptimizeOptions {
  MotionNlpOptions nlp;
  SolverOptions solver;
  /// Refine the knots (K = 2, 3, ... up to kMaxAutomaticKnotsPerInterval) when the interpolation
  /// on the requested knots misses the keyframes by more than their tolerances, or turns a
  /// segment by nearly a full turn between two control points (kMaxControlTurn); see
  /// optimize_motion.
  bool refine_when_keyframes_missed = true;
  /// Automatic resolution (`--knots-per-interval auto`, AutomaticResolution): start from knots
  /// chosen from how far each keyframe interval turns the body, then add knots where the
  /// residual lives until it is near zero or more knots stop paying. Off: the uniform
  /// nlp.knots_per_interval (or nlp.subdivisions). Relaxed model only: the strict model's
  /// objective is the keyframe distance, not the residual.
  bool automatic_resolution = true;

  /// The automatic resolution acts: asked for, and the relaxed model. The one statement of
  /// that rule; the option table, the writers and the app ask here.
  bool resolution_is_automatic() const {
    return automatic_resolution && nlp.formulation == Formulation::kRelaxed;
  }
};

/// Keyframes optimize_motion takes: each interior keyframe's time is a variable that couples
/// with every other variable, so the Hessian, and with it time and memory, grows with the
/// square of their count (M7 with 13 keyframes: 3.2 s; with 100: 3 min 37 s and 1 GB).
inline constexpr int kMaxOptimizedKeyframes = 64;

/// The paper's protocol, which the studies and `saltus paper` keep so that their tables compare
/// with the paper's: knots at the keyframes (no automatic resolution) and no keyframe prior.
inline void use_paper_protocol(OptimizeOptions& options) {
  options.automatic_resolution = false;
  options.nlp.keyframe_weight = 0.0;
}
inline OptimizeOptions paper_protocol_options() {
  OptimizeOptions options;
  use_paper_protocol(options);
  return options;
}

/// See OptimizationResult::keyframe_time_spreads.
inline constexpr double kTimeSpreadForceRise = 0.1;    ///< N
inline constexpr double kDeterminedTimeSpread = 0.02;  ///< s

/// The finest knot refinement optimize_motion picks on its own.
inline constexpr int kMaxAutomaticKnotsPerInterval = 4;

/// The largest turn between consecutive control points of one segment's interpolated curve that
/// the optimiser starts from (rad); beyond it the knots are refined. Near 2π the curve's
/// derivatives with respect to its controls blow up like 1/sin(turn/2)
/// (QuaternionSpline::largest_control_turn); at 1.75π they are 2.6 times those at π.
/// Why 1.75π: docs/optimizer.md, "Measurement history".
inline constexpr double kMaxControlTurn = 1.75 * 3.14159265358979323846;

/// The largest turn between consecutive control points (rad) over the curves of segments
/// `first_segment` onwards: 0 counts the root, whose turns are the somersault's own; 1 the joints
/// alone (what MotionNlpOptions::joint_turn_limit bounds).
double largest_control_turn(const Trajectory<double>& trajectory, int first_segment = 0);

/// N: the least-joint-effort polish may trade root force for joint loads up to this average
/// root force (a flight's true residual is held to it: docs/optimizer.md, "Joint loads").
inline constexpr double kPolishMaxRootForce = 0.5;
/// N: when no polish try meets kPolishMaxRootForce (or the levels' force) and the motion the
/// polish started from makes a joint pay for the root force (its largest joint rise against the
/// input past kJointLoadRiseLimit), the bounded try with the least root force up to this one is
/// kept, if it solved and lands as a kept try must. 0.34 N bought with an elbow at 190 times its
/// input (the imported MASS backflip's levels) is not a motion a biomechanist can use; its
/// bounded try's 0.53 N with every joint within its bound is. Only then: a flight whose
/// unbounded try holds 0.5 N keeps it (docs/optimizer.md, "Joint loads bought by the levels").
inline constexpr double kPolishMaxRootForceOverPayingJoints = 1.0;

/// Whether a solve that trades root force for something else (the polish for joint loads, the
/// second pass for the landing) may keep its motion: its average root force `after` (N) is
/// within kPolishMaxRootForce or no larger than the motion it replaces (`before`). A kept polish
/// that fails it was kept over paying joints (kPolishMaxRootForceOverPayingJoints).
inline bool root_force_within_limit(double after, double before) {
  return after <= kPolishMaxRootForce || after <= before;
}
/// Iterations a polish try may take: kept tries take 20-80; one that has not converged by then
/// is not going to be kept, and each iteration costs several of a level's (the joint bounds).
inline constexpr int kPolishMaxIterations = 150;

/// The polish's MotionNlpOptions::root_moment_weight: it may trade root force for joint loads,
/// not root moment, which a twisting body turns into degrees at landing (with 1, M7's free flight
/// ended 70° from the polished motion; with 100, 1.8°: docs/optimizer.md, "Landing drift").
inline constexpr double kPolishRootMomentWeight = 100.0;

/// The root_moment_weight of the levels' second pass: when the motion made by the levels and the
/// polish still flies off (its free flight lands more than
/// AutomaticResolution::max_landing_drift_deg from it), the levels run again from the start
/// weighing the root moment as the polish does, then the polish, and the motion that lands closer
/// is kept (docs/optimizer.md, "Landing drift on other athletes").
inline constexpr double kLandingRootMomentWeight = kPolishRootMomentWeight;

/// One try of the polish: its joint-load weight (a multiple of MotionNlpOptions::
/// joint_load_weight), its root_moment_weight, whether it bounds the joints (kPolishJointBound),
/// and where it starts: from the levels' optimum, or from the last bounded try that solved
/// (which keeps within the same bounds, so only the weights move: fewer iterations and, for the
/// dive, less root force than from a motion whose joints pay).
struct PolishTry {
  double weight_factor;
  double root_moment_weight;
  bool joints_bounded;
  bool from_levels;
};
/// The polish's tries, in order, until one is kept: bounded at the full and half weight; then,
/// for a flight whose first two tries land off (the dive), bounded at a quarter of the weight with
/// the root moment weighed 3 times more, then 10 times more (M6 on a 2 m, 120 kg man); last
/// without bounds (least joint effort alone then holds the joints). The second and third bounded
/// tries start from the one before; the fourth from the levels again, so that a first try that
/// settled where its free flight lands off does not hold every step there (M6 on that man: 3.29
/// deg from the third, 2.67 from the levels). Why these: docs/optimizer.md, "Joint bounds",
/// "Joint loads on other athletes" and "A bounded step from the try before it".
inline constexpr PolishTry kPolishTries[] = {{1.0, kPolishRootMomentWeight, true, true},
                                             {0.5, kPolishRootMomentWeight, true, false},
                                             {0.25, 3.0 * kPolishRootMomentWeight, true, false},
                                             {0.25, 10.0 * kPolishRootMomentWeight, true, true},
                                             {0.25, kPolishRootMomentWeight, false, true}};
/// A bounded try whose free flight lands farther from it than this multiple of
/// AutomaticResolution::max_landing_drift_deg, and farther than the motion it would replace,
/// ends the bounded tries; the polish goes on to its unbounded one. On small athletes M6's and
/// M7's bounded tries land 17-177 deg off and no later bounded step landed within 3 deg; the
/// dive's land 7-10 deg off before its third step lands within 3 (docs/optimizer.md).
inline constexpr double kPolishHopelessDriftFactor = 5.0;
inline constexpr int kPolishAttempts = static_cast<int>(std::size(kPolishTries));

/// The polish bounds each joint's moment and force by this multiple of the input's peak there
/// (the smaller of the paper's interpolation's and the optimiser's starting point's; at least
/// kJointMomentFloorNm and kJointForceFloorN), at nodes on every span: a joint may not
/// pay for the root residual (our bar is 1.5 times the input's peak on the dense grid; a load
/// rises a little between nodes, and a finer grid than ours finds a little more).
inline constexpr double kPolishJointBound = 1.3;

/// Least joint effort (MotionNlpOptions::joint_load_weight > 0): a last solve at the keyframe
/// times the levels found, with the joint loads in the objective; kept when it solved with an
/// average root force within kPolishMaxRootForce, or no larger than before, and its free flight
/// lands within AutomaticResolution::max_landing_drift_deg of it, or no farther than before;
/// otherwise tried again as kPolishTries say, and when none is kept, a bounded try over a motion
/// whose joints pay may be (kPolishMaxRootForceOverPayingJoints). A bounded try that falls short
/// of the joint bar is solved once more (bounds_tightened, knots_refined). The figures are the
/// kept try's, or the last try's.
struct JointLoadPolish {
  double weight = 0.0;  ///< the last try's joint-load weight, N²/(N·m)²
  /// The last try's MotionNlpOptions::root_moment_weight.
  double root_moment_weight = 0.0;
  /// The last try's joint bound, a multiple of the input's peaks (kPolishJointBound); 0: none.
  double joint_bound = 0.0;
  /// The last try's step on the ladder, 1-based (kPolishTries[attempts - 1]); bounded steps
  /// skipped after a hopeless one (kPolishHopelessDriftFactor) count.
  int attempts = 0;
  /// Bounded steps skipped because an earlier bounded try landed hopelessly off.
  int bounded_tries_skipped = 0;
  double avg_root_force_before = 0.0;     ///< N, the best level's (dense check)
  double avg_root_force_after = 0.0;      ///< N, the polished motion's
  double landing_drift_before_deg = 0.0;  ///< see OptimizationResult::landing_drift_deg
  double landing_drift_after_deg = 0.0;
  /// The largest joint rise of the motion the polish started from against the input's peaks
  /// (evaluation/joint_loads.h); past kJointLoadRiseLimit, when no try is kept, a bounded one
  /// within kPolishMaxRootForceOverPayingJoints may be.
  double joint_rise_before = 1.0;
  /// The kept bounded try was solved once more with the bounds of the joints its dense check
  /// found past them (a load rises between nodes) lowered by that overshoot, and that solve kept.
  bool bounds_tightened = false;
  /// No bounded try held the root force over a motion whose joints paid: the best that solved
  /// and landed was solved again on finer knots (refined where its residual lives), and kept.
  bool knots_refined = false;
  /// When the motion returned is not a bounded try's: the bounded try that solved and whose free
  /// flight landed closest to it. On an athlete the keyframes were not made for, it says what
  /// human joints cost: such a motion holds the root force but flies far from its keyframes.
  struct BoundedAlternative {
    double landing_drift_deg = 0.0;  ///< its free flight against it at landing
    double avg_root_force = 0.0;     ///< N, dense check
    double joint_rise = 1.0;         ///< its largest joint rise over the input's peaks
  };
  std::optional<BoundedAlternative> bounded_alternative;
  int iterations = 0;  ///< over every try
  std::string status;
  bool kept = false;
};

struct OptimizationResult {
  SolveReport solve;
  int variables = 0;
  int constraints = 0;
  /// The refinement K used: the requested one, or more when the interpolation on it could not
  /// meet the keyframes or was near-singular (OptimizeOptions::refine_when_keyframes_missed);
  /// with automatic resolution the largest of `subdivisions`.
  int knots_per_interval = 1;
  /// Knot spans per keyframe interval of the optimised motion (its knots: after.trajectory).
  std::vector<int> subdivisions;
  /// Automatic resolution: each level's spans per interval and true average root force (N).
  struct Level {
    std::vector<int> subdivisions;
    double avg_root_force = 0.0;
    double landing_drift_deg = 0.0;
    int iterations = 0;
    std::string status;
    /// MotionNlpOptions::root_moment_weight of this level's pass: 1, or
    /// kLandingRootMomentWeight in the second pass (when the first landed off).
    double root_moment_weight = 1.0;
  };
  std::vector<Level> levels;
  /// Degrees between the optimised motion's whole-body orientation at landing and that of the
  /// free flight from its own take-off state with its joint movements (simulate_motion's
  /// landing_vs_motion_deg for optimized_motion); measured when the automatic resolution or
  /// least joint effort decided by it.
  std::optional<double> landing_drift_deg;
  /// The input's keyframe intervals too far apart for its twist (evaluation/keyframe_spacing.h),
  /// found once here and written to result.json as they are.
  std::vector<SparseTwistInterval> sparse_twist_intervals;
  /// Those whose start followed the free flight's way round instead of the short way (their
  /// first keyframe, 0-based): every one with the automatic resolution, unless the motion brings
  /// its own spline.
  std::vector<int> twist_guided_intervals;
  /// Least joint effort's last solve, when there was one.
  std::optional<JointLoadPolish> joint_load_polish;
  MotionEvaluation before;  ///< the interpolated motion (the starting point)
  MotionEvaluation after;   ///< the optimised motion, on the same sample grid
  /// J by the optimiser's own quadrature (MotionNlp::force_objective), at the start and at the
  /// end: beside the dense check's (before/after.metrics), they must agree when the quadrature
  /// is fine enough for the knots.
  double optimizer_objective_before = 0.0, optimizer_objective_after = 0.0;
  /// Per keyframe, how far its optimised time could move (s), the rest of the motion following,
  /// before the objective (root force and keyframe prior) rises by what kTimeSpreadForceRise
  /// more average root force costs (MotionNlp::keyframe_time_spreads); 0 for the fixed first
  /// and last. Above kDeterminedTimeSpread the keyframes and their tolerances leave the time
  /// undetermined.
  std::vector<double> keyframe_time_spreads;
  /// The input motion with the optimised keyframe times and the optimised spline stored, so that
  /// loading it reproduces `after` exactly; its take-off state is the optimised motion's own
  /// (fit_flight_state) and its keyframes name the root positions the optimiser met.
  Motion optimized_motion;
};

/// Whether the optimiser's own average root force (its quadrature) and the dense check's agree
/// after optimisation: within 2 % of the check plus 0.02 N.
bool optimizer_agrees_with_check(const OptimizationResult& result);

/// Throws std::invalid_argument for options out of range; solver failures are reported in
/// result.solve (the result is still complete, from the best feasible or the last iterate).
/// Progress comes once per iteration with the stage it belongs to (ProgressInfo::stage). Once
/// `cancel` is set the run stops at the next iteration and reports "cancelled", not solved,
/// whatever the solves before the stop reached: it did not finish the optimiser's policy.
///
/// Cumulative quaternion splines turn by ω_j = log(q_{j−1}⁻¹ q_j) between control points, less
/// than 180°. Where consecutive keyframes are far apart in rotation over uneven intervals (a
/// fast tucked somersault keyframed sparsely, or keyframe times far off) the curve through them
/// would need more, so the interpolation on knots at the keyframes misses them
/// (docs/optimizer.md, "Measurement history") and the optimiser starts outside its constraints,
/// on a landscape where the log's branch cut makes them jump. Then K is raised until the
/// interpolation meets the keyframe tolerances.
OptimizationResult optimize_motion(const Motion& motion, const BodyModel& model,
                                   const OptimizeOptions& options,
                                   const ProgressCallback& progress = {},
                                   const std::atomic<bool>* cancel = nullptr);

}  // namespace saltus
