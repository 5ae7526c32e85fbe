#pragma once
/// @file
/// The optimisation models of docs/method.md over a keyframed motion.
///
/// Relaxed (the paper's eqs. 1-4): minimise J = (1/T) ∫ Σ F_i² dt (Gauss–Lobatto nodes on every
/// knot span, moving with the knots: RootWrenchTerm, see `quadrature_nodes`), plus a small
/// proximity term (see `regularization`), the keyframe prior (see `keyframe_weight`) and a soft
/// limit on how far joints turn between control points (see `joint_turn_limit`), subject to
///   |B_d(t_i) − B̄_d(t_i)| <= ε1   per keyframe i and coordinate d              (eq. 2)
///   ‖Q_k(t_i) − Q̄_k‖² <= ε2²       per keyframe and joint, sign-aligned         (eq. 3)
/// (both divided by their tolerance, see kKeyframeBoundMargin)
///   t_{i+1} − t_i >= gap           per pair of consecutive keyframes            (eq. 4)
/// with B̄(t) = s(t) − s'_i (the CoM parabola at the keyframe's current time minus the keyframe
/// pose's CoM offset) unless the keyframe gives root_position.
/// The Hessian is Gauss-Newton, (2/T) Σ w_s J_sᵀ J_s: J is a sum of squares whose residuals vanish
/// at the physical optimum, where Gauss-Newton is exact. Where they do not (the paper's coarse
/// knots), it is damped by μ·J·I with μ adapted step by step (MotionNlpOptions::damping): each
/// Hessian evaluation first judges the step that led to it, so hessian_values is not a pure
/// function of x (step_taken tells the NLP how the solver got there).
///
/// Strict (classic spacetime constraints): the same variables and keyframe constraints plus
/// |F_i(t_s)| <= ε at every one of the `samples` grid times; objective the keyframe distance
/// Σ‖B(t_i) − B̄_i‖² + Σ‖Q_k(t_i) − Q̄_k‖², plus the same proximity term and joint-turn limit
/// (with the same weights, so here they weigh more against the objective). Its Hessian is the
/// Gauss-Newton one of that objective; the force constraints' curvature is not available and
/// left out.

#include <memory>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/motion/motion.h"
#include "saltus/optim/adaptive_damping.h"
#include "saltus/optim/hessian_band.h"
#include "saltus/optim/keyframe_targets.h"
#include "saltus/optim/nlp.h"
#include "saltus/optim/nlp_evaluations.h"
#include "saltus/optim/terms/constraint_block.h"
#include "saltus/optim/terms/objective_term.h"
#include "saltus/optim/trajectory_layout.h"

namespace saltus {

enum class Formulation { kRelaxed, kStrict };

/// The keyframe constraints are stated in units of their tolerance: translation rows are
/// (B_d − B̄_d)/ε1 in [−b, b], rotation rows ‖Q − Q̄‖²/ε2² <= b, with b = 1 − kKeyframeBoundMargin.
/// Dimensionless rows matter to Ipopt: it pushes every initial slack max(1, |bound|)·1e-2
/// inside its bound, and for an unscaled ‖Q − Q̄‖² <= 0.0025 that put the slack at −0.0075, a
/// value no squared distance can reach: the first Newton step then flew off to wherever the
/// linearisation pointed (docs/optimizer.md, "Measurement history").
/// The margin is 2× SolverOptions::acceptable_constraint_violation, so a point the solver
/// accepts still meets the user's tolerances: for ε2 = 0.05 the optimiser works to
/// ‖Q − Q̄‖ <= 0.0495, for ε1 = 0.25 m to 0.245 m.
inline constexpr double kKeyframeBoundMargin = 0.02;

struct MotionNlpOptions {
  Formulation formulation = Formulation::kRelaxed;
  double epsilon = 100.0;       ///< strict: bound on each |F_i(t_s)|, N or N·m
  bool optimize_timing = true;  ///< interior keyframe times are variables
  int knots_per_interval = 1;   ///< spline refinement K (1 = the paper's resolution)
  /// Knot spans per keyframe interval, one entry per interval; when given it replaces the
  /// uniform knots_per_interval (automatic resolution refines where the residual lives).
  std::vector<int> subdivisions;
  /// The spans per interval these options ask for (subdivisions, or K everywhere).
  std::vector<int> spans_per_interval(int keyframe_count) const {
    return subdivisions.empty() ? std::vector<int>(keyframe_count - 1, knots_per_interval)
                                : subdivisions;
  }
  int samples = kDefaultSamples;  ///< strict model: the times of its force bounds on [0, T]
  /// The relaxed objective's integral (RootWrenchTerm): Gauss–Lobatto nodes on every knot
  /// span (its ends included), at least quadrature_nodes and at most quadrature_spacing apart.
  int quadrature_nodes = 8;
  double quadrature_spacing = 0.02;
  double min_time_gap = 0.05;    ///< s, eq. (4)'s gap (capped at half the shortest interval)
  double max_time_shift = 0.25;  ///< s, how far a keyframe time may move from the given one
  /// The given keyframe times, when the motion passed to the NLP holds others (a finer
  /// resolution started from a coarser optimum): bounds and gaps stay relative to these.
  std::vector<double> given_keyframe_times;
  /// Levenberg-Marquardt damping of the Gauss-Newton Hessian: μ·J(x)·I is added (Yamashita &
  /// Fukushima 2001: damping ∝ ‖F‖² keeps fast local convergence at a zero residual).
  /// Light segments (feet, forearms) barely change the root force, so undamped Gauss-Newton
  /// steps would swing them by radians on a linear model that no longer holds. μ starts at
  /// damping.initial and, with adapt_damping, follows how well the damped model predicted each
  /// step (AdaptiveDamping; measurements in docs/optimizer.md, "Measurement history").
  DampingRule damping;
  bool adapt_damping = true;
  /// Weight w (N²/rad²) of the proximity term w·Σ‖δ‖² added to the relaxed objective (δ: the
  /// joints' control-point tangents relative to the interpolation, rad): turning a joint control
  /// by 1 rad costs as much as 1 N² of mean squared root wrench. The root force hardly depends
  /// on light segments, so without it the optimum swings feet and forearms through large angles
  /// between keyframes for tiny gains. A fixed physical weight, not one relative to the
  /// starting J, so that a bad start (wrong timing) is not held near its own interpolation.
  /// Reported objectives are J alone. 0 disables it.
  double regularization = 1.0;
  /// Weight w of the joint-acceleration term (JointAccelerationTerm, relaxed model): the joints'
  /// angular accelerations stay near the starting motion's, in units of the joint moments they
  /// ask for; w = 1 weighs a joint moment change like a root moment. 0 = none.
  double joint_effort = 0.0;
  /// Weight w (N² per (N·m)²) of least joint effort, w·(1/T)∫ Σ_j |n_j|² dt over the non-root
  /// joints (terms/joint_load_term.h); 0 = none.
  double joint_load_weight = 0.001;
  /// Weight of the root moment against the root force in the minimised objective (1: the
  /// paper's J). Least joint effort's polish raises it, so that it trades root force, which
  /// only shifts the CoM, and not root moment, which a twisting body turns into degrees at
  /// landing. force_objective() stays the paper's J.
  double root_moment_weight = 1.0;
  /// Least joint effort's weight on each non-root joint's moment, in model order (empty: 1 for
  /// every joint). optimize_motion sets them from the input's peaks, so that the term counts
  /// each joint's load against what the input needed and not in absolute N·m.
  std::vector<double> joint_load_scales;
  /// Upper bounds on each non-root joint's moment (N·m) and force (N) magnitudes, in model
  /// order, as constraints at nodes on every span (terms/joint_bound_block.h); empty: none
  /// (forces: only with moments). optimize_motion's polish sets them from the input's peaks.
  std::vector<double> joint_moment_bounds;
  std::vector<double> joint_force_bounds;
  /// Weight w (N²) of the keyframe prior added to the relaxed objective:
  /// w·Σ_i (‖B(t_i) − B̄_i‖²/ε1² + Σ_k ‖Q_k(t_i) − Q̄_k‖²/ε2²), the strict model's keyframe
  /// distance in units of the tolerances. The tolerances let a motion meet its keyframes at
  /// many sets of times with nearly the same root force; of those, the prior prefers the one
  /// that passes closest to the keyframes, which for a physically exact flight is the one at
  /// its true times (measurements in docs/optimizer.md). optimize_motion uses it with
  /// automatic resolution only. 0 = none.
  double keyframe_weight = 10.0;
  /// Soft limit (rad) on the turn of each non-root joint between two consecutive control points
  /// (JointTurnTerm: the floor of L; the interpolation's own larger turns stay allowed), with
  /// weight joint_turn_weight (N²/rad², in J's units: 0.1 rad past the limit costs 10 N²). Half a
  /// revolution: no joint turns further relative to its parent between two controls, and every
  /// run stays well off the spline's branch point at 2π (docs/optimizer.md, "Measurement
  /// history"). 0 = none.
  double joint_turn_limit = 3.14159265358979323846;
  double joint_turn_weight = 1000.0;
  bool limits_joint_turns() const { return joint_turn_limit > 0 && joint_turn_weight > 0; }
  /// Threads that evaluate the root wrench and its derivatives (each takes a contiguous run of
  /// samples, keyframes or knot spans); 0 = one per hardware thread, at most 4. A fixed
  /// default, not the machine's core count, so that the same input gives the same output
  /// everywhere: the values do not depend on it, but the Hessian's blocked products round
  /// differently with where each thread's memory lies, and the iterations follow the rounding
  /// (docs/optimizer.md, "Measurement history").
  int threads = 2;
};

class RootWrenchTerm;

/// One formulation assembled from objective terms and constraint blocks (optim/terms/): the
/// relaxed model sums the root wrench, the keyframe prior, the proximity term and the joint-turn
/// penalty, subject to the keyframe translation, keyframe rotation and time-order blocks; the
/// strict model sums the keyframe distance, proximity and penalty, subject to the same blocks and
/// the force bounds.
/// This class only stacks them for the solver, caches the gradient per point and adapts the
/// damping of the relaxed model's Hessian.
class MotionNlp : public Nlp {
 public:
  /// @param initial  the starting trajectory (the §5 interpolation) on the knots of the motion's
  ///                 keyframe times refined by options.knots_per_interval; its joint control
  ///                 points become the reference q̄ of the tangent coordinates.
  MotionNlp(const Motion& motion, const BodyModel& model, const Trajectory<double>& initial,
            const MotionNlpOptions& options);
  ~MotionNlp() override;

  const TrajectoryLayout& layout() const { return layout_; }
  const TrajectoryReference& reference() const { return reference_; }
  const std::vector<double>& sample_times() const { return sample_times_; }
  const MotionNlpOptions& options() const { return options_; }
  /// The objective's terms, in the order they are summed.
  const std::vector<ObjectiveTerm*>& objective_terms() const { return objective_; }
  /// The constraint blocks, in row order.
  const std::vector<ConstraintBlock*>& constraint_blocks() const { return constraint_; }
  /// The shared evaluations at the current point (for the terms' tests).
  NlpEvaluations& evaluations() { return *at_; }

  int variable_count() const override { return layout_.size(); }
  int constraint_count() const override { return rows_; }
  void bounds(double* x_lower, double* x_upper, double* g_lower, double* g_upper) const override;
  void initial_point(double* x) const override;

  double objective(const double* x) override;
  void gradient(const double* x, double* gradient) override;
  void constraints(const double* x, double* g) override;

  int jacobian_nonzeros() const override { return static_cast<int>(jacobian_columns_.size()); }
  void jacobian_structure(int* rows, int* columns) const override;
  void jacobian_values(const double* x, double* values) override;

  bool has_hessian() const override { return true; }
  int hessian_nonzeros() const override { return band_.nonzeros(); }
  void hessian_structure(int* rows, int* columns) const override;
  void hessian_values(const double* x, double objective_factor, const double* multipliers,
                      double* values) override;
  void step_taken(const StepTaken& step) override;

  /// The damping factor μ the next Hessian will use.
  double damping_factor() const { return damping_.factor(); }

  /// Relaxed objective J at x by the span quadrature (also defined for the strict model).
  double force_objective(const double* x);

  /// How closely the keyframes pin each time at x (s, one per keyframe; 0 for fixed times): the
  /// move of that time which, with every other variable following at best, costs `rise` (N²) of
  /// objective, each constraint counted as a quadratic wall that costs `rise` where it uses up
  /// the slack it has at x: sqrt(2·rise·(H⁻¹)_tt), H the undamped Gauss-Newton Hessian plus the
  /// walls'. Capped at max_time_shift.
  std::vector<double> keyframe_time_spreads(const double* x, double rise);

 private:
  /// Bounds of the variables: joint tangents within ±1.5 rad, keyframe times within
  /// max_time_shift of the given ones and the gap of their neighbours.
  void variable_bounds(double* x_lower, double* x_upper) const;
  /// Judges the step from the last Hessian's point to x by the damped model of the objective
  /// kept at that point, and updates μ.
  void judge_last_step(const double* x);

  MotionNlpOptions options_;
  TrajectoryLayout layout_;
  TrajectoryReference reference_;
  std::vector<double> initial_x_;
  std::vector<double> given_times_;  ///< the centres of the time bounds
  double duration_ = 0.0;
  double time_gap_ = 0.0;
  std::vector<double> sample_times_;
  std::unique_ptr<KeyframeTargets> targets_;
  std::unique_ptr<NlpEvaluations> at_;
  HessianBand band_;
  AdaptiveDamping damping_;

  std::vector<std::unique_ptr<ObjectiveTerm>> owned_terms_;
  std::vector<std::unique_ptr<ConstraintBlock>> owned_blocks_;
  std::vector<ObjectiveTerm*> objective_;
  std::vector<ConstraintBlock*> constraint_;
  RootWrenchTerm* root_wrench_ = nullptr;  ///< in objective_ for the relaxed model

  int rows_ = 0;
  std::vector<int> block_row_, block_entry_;  ///< first row and Jacobian entry of each block
  std::vector<int> jacobian_rows_, jacobian_columns_;

  std::vector<double> gradient_;  ///< at the current point, when gradient_generation_ is its
  long gradient_generation_ = -1;

  /// The relaxed objective's damped quadratic model at the last Hessian's point (objective
  /// part only: the keyframe constraints are Ipopt's business), to judge the step taken from it.
  struct ObjectiveModel {
    bool valid = false;
    std::vector<double> x, gradient, hessian;  ///< hessian: the band, per unit objective factor
    double objective = 0.0;
  };
  ObjectiveModel last_model_;
  StepTaken last_step_;
};

}  // namespace saltus
