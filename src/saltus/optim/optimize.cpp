#include "saltus/optim/optimize.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <stdexcept>

#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/evaluation/flight_state.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/evaluation/keyframe_spacing.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/motion/interpolate.h"
#include "saltus/optim/automatic_resolution.h"
#include "saltus/optim/option_table.h"
#include "saltus/optim/polish_rules.h"

namespace saltus {

double largest_control_turn(const Trajectory<double>& trajectory, int first_segment) {
  double largest = 0.0;
  for (std::size_t k = std::max(0, first_segment); k < trajectory.rotations.size(); ++k)
    largest = std::max(largest, trajectory.rotations[k].largest_control_turn());
  return largest;
}

bool optimizer_agrees_with_check(const OptimizationResult& result) {
  const double optimizer = std::sqrt(result.optimizer_objective_after / 6.0);
  const double check = result.after.metrics.avg_root_force;
  return std::abs(optimizer - check) <= 0.02 * check + 0.02;
}

namespace {

EvaluateOptions evaluate_options(int samples, const std::vector<int>& subdivisions) {
  EvaluateOptions evaluate;
  evaluate.samples = samples;
  evaluate.interpolation.subdivisions = subdivisions;
  return evaluate;
}

/// Whether an interpolation can be optimised from: it meets the keyframes and turns no segment
/// near a full turn between two control points (kMaxControlTurn).
bool well_posed(const MotionEvaluation& start, const Motion& motion) {
  const KeyframeErrors& missed = start.keyframe_errors;
  return missed.max_quaternion_error <= motion.tolerances.quaternion &&
         missed.max_translation_error_m <= motion.tolerances.translation_m &&
         largest_control_turn(start.trajectory) <= kMaxControlTurn;
}

/// One solve: the NLP over `start` (on the knots of `subdivisions` at the keyframe times of
/// `motion_at_start`), its result as a motion with the optimised times and spline.
struct Solved {
  SolveReport solve;
  int variables = 0, constraints = 0;
  double objective_before = 0.0, objective_after = 0.0;
  Motion optimized;
  Trajectory<double> trajectory;
  /// Kept for keyframe_time_spreads, which only the level that is returned needs (a sparse
  /// factorization of the Hessian: 3 % of M7's run per level).
  std::unique_ptr<MotionNlp> nlp;
};

/// The motion as optimized.motion.json holds it: its own take-off state, fitted to its evaluation
/// (so `simulate` starts where it starts), and the keyframes' root targets as the optimiser met
/// them (they came from the given take-off's parabola, which the file no longer holds).
Motion with_own_flight_state(Motion optimized, const MotionEvaluation& evaluation) {
  const FlightState own = fit_flight_state(evaluation.samples);
  optimized.takeoff.com_position = own.com_position;
  optimized.takeoff.com_velocity = own.com_velocity;
  optimized.takeoff.angular_momentum = own.angular_momentum;
  for (std::size_t i = 0; i < optimized.keyframes.size(); ++i)
    optimized.keyframes[i].root_position = evaluation.root_targets[i];
  return optimized;
}

/// A solved motion (its stored spline) evaluated on `samples` times, which is result.after when
/// it is the one returned, and its OptimizationResult::landing_drift_deg from a free flight.
struct Flown {
  MotionEvaluation evaluation;
  double drift_deg = 0.0;
};
Flown fly(const Motion& optimized, const BodyModel& model, int samples) {
  const EvaluateOptions grid = evaluate_options(samples, {});
  Flown flown;
  flown.evaluation = evaluate_motion(optimized, model, grid);
  flown.drift_deg = simulate_motion(with_own_flight_state(optimized, flown.evaluation), model, grid)
                        .landing_vs_motion_deg;
  return flown;
}

/// How far each keyframe time of `solved` may move before the average root force rises by
/// kTimeSpreadForceRise (OptimizationResult::keyframe_time_spreads).
std::vector<double> keyframe_time_spreads(Solved& solved) {
  const double force = std::sqrt(solved.objective_after / 6.0);
  return solved.nlp->keyframe_time_spreads(
      solved.solve.x.data(), 6.0 * (std::pow(force + kTimeSpreadForceRise, 2) - force * force));
}

Solved solve_level(const Motion& motion, const Motion& motion_at_start, const BodyModel& model,
                   const Trajectory<double>& start, const MotionNlpOptions& nlp_options,
                   const SolverOptions& solver, const ProgressCallback& progress,
                   const std::atomic<bool>* cancel) {
  Solved out;
  out.nlp = std::make_unique<MotionNlp>(motion_at_start, model, start, nlp_options);
  MotionNlp& nlp = *out.nlp;
  out.variables = nlp.variable_count();
  out.constraints = nlp.constraint_count();
  std::vector<double> initial_x(nlp.variable_count());
  nlp.initial_point(initial_x.data());
  out.objective_before = nlp.force_objective(initial_x.data());
  out.solve = solve_nlp(nlp, solver, progress, cancel);
  const double* x = out.solve.x.data();
  out.objective_after = nlp.force_objective(x);
  out.optimized = motion;
  const std::vector<double> times = keyframe_times_from(nlp.layout(), nlp.reference(), x);
  for (std::size_t i = 0; i < times.size(); ++i)
    out.optimized.keyframes[i].time = times[i];
  out.trajectory = trajectory_from(nlp.layout(), nlp.reference(), x);
  out.optimized.spline = to_stored_spline(out.trajectory);
  return out;
}

std::vector<double> keyframe_times_of(const Motion& motion) {
  std::vector<double> times;
  for (const Keyframe& k : motion.keyframes)
    times.push_back(k.time);
  return times;
}

/// Least joint effort's per-joint scales: s_j = P / max(P_j, floor), P_j the input's peak
/// moment at joint j and P their root mean square, so that a joint counts by its load against
/// the input's (the rise joint_loads.h reports) while the term keeps the size it has unscaled.
std::vector<double> joint_load_scales(const DenseCheck& input) {
  std::vector<double> peaks;
  for (std::size_t j = 1; j < input.joint_peaks.size(); ++j)
    peaks.push_back(std::max(input.joint_peaks[j].moment_Nm, kJointMomentFloorNm));
  if (peaks.empty()) return {};
  double mean_square = 0.0;
  for (const double p : peaks)
    mean_square += p * p;
  const double reference = std::sqrt(mean_square / static_cast<double>(peaks.size()));
  for (double& p : peaks)
    p = reference / p;
  return peaks;
}

/// The polish's bounds on each joint's moment and force: kPolishJointBound times the smaller of
/// two interpolations' peaks there, the paper's (`input`, knots at the keyframes) and the
/// optimiser's starting point (`start`, its finer knots, which often needs less: M2's right hip
/// 13.4 against 18.2 N·m), at least kJointMomentFloorNm and kJointForceFloorN.
void set_joint_bounds(const DenseCheck& input, const DenseCheck& start, MotionNlpOptions& options) {
  const std::size_t n = std::min(input.joint_peaks.size(), start.joint_peaks.size());
  for (std::size_t j = 1; j < n; ++j) {
    const JointLoadPeak& a = input.joint_peaks[j];
    const JointLoadPeak& b = start.joint_peaks[j];
    options.joint_moment_bounds.push_back(
        kPolishJointBound * std::max(std::min(a.moment_Nm, b.moment_Nm), kJointMomentFloorNm));
    options.joint_force_bounds.push_back(
        kPolishJointBound * std::max(std::min(a.force_N, b.force_N), kJointForceFloorN));
  }
}

/// A bounded try's bounds lowered where its dense check found a joint's load past them (a load
/// rises between the nodes that bound it): each such bound divided by that overshoot, so that the
/// dense peak of a solve again sits near the bound rather than the nodes' peak.
void tighten_joint_bounds(const DenseCheck& solved, MotionNlpOptions& options) {
  for (std::size_t j = 1; j < solved.joint_peaks.size() && j <= options.joint_moment_bounds.size();
       ++j) {
    double& moment = options.joint_moment_bounds[j - 1];
    moment *= std::min(1.0, moment / std::max(solved.joint_peaks[j].moment_Nm, 1e-12));
    if (j > options.joint_force_bounds.size()) continue;
    double& force = options.joint_force_bounds[j - 1];
    force *= std::min(1.0, force / std::max(solved.joint_peaks[j].force_N, 1e-12));
  }
}

/// The best of one pass of levels (MotionOptimizer::run_levels), then what the polish made of it.
struct Levels {
  Solved best;
  std::vector<int> subdivisions;
  double force = 0.0;
  std::optional<Flown> flown;  // when the drift was measured
  /// Of the best level, which has the time variables (the polish has none).
  std::vector<double> time_spreads;
  int variables = 0, constraints = 0;
  std::optional<JointLoadPolish> polish;  // least joint effort's, when it ran
};

/// optimize_motion's state over its solves: the start, the options every solve shares, and one
/// iteration count and clock over all of them (an app's counter never goes backwards).
class MotionOptimizer {
 public:
  MotionOptimizer(const Motion& motion, const BodyModel& model, const OptimizeOptions& options,
                  const ProgressCallback& progress, const std::atomic<bool>* cancel)
      : motion_(motion),
        model_(model),
        options_(options),
        progress_(progress),
        cancel_(cancel),
        automatic_(options.resolution_is_automatic()),
        refine_unconverged_(options.solver.max_iterations >= SolverOptions{}.max_iterations) {
    if (progress_)
      counted_ = [this](const ProgressInfo& info) {
        ProgressInfo over_levels = info;
        over_levels.iteration += iterations_;
        over_levels.elapsed_seconds += seconds_;
        over_levels.stage = stage_;
        progress_(over_levels);
      };
  }

  bool automatic() const { return automatic_; }
  bool cancelled() const { return cancel_ && cancel_->load(); }
  /// The options of the levels: the keyframe prior as the option table says for this case,
  /// without least joint effort (the polish's), the given keyframe times.
  const MotionNlpOptions& level_options() const { return nlp_options_; }

  void choose_start(OptimizationResult& result);
  Levels run_levels(double root_moment_weight, OptimizationResult& result);
  void polish(Levels& pass, const OptimizationResult& result);
  void set_landing_pass() { landing_pass_ = true; }
  void finish(Levels levels, OptimizationResult& result) const;

 private:
  class PolishLadder;

  Solved solve(const Motion& at_start, const Trajectory<double>& start, const MotionNlpOptions& nlp,
               const SolverOptions& solver, SolveStage stage) {
    stage_ = stage;
    Solved solved = solve_level(motion_, at_start, model_, start, nlp, solver, counted_, cancel_);
    iterations_ += solved.solve.iterations;
    restarts_ += solved.solve.restarts;
    seconds_ += solved.solve.seconds;
    return solved;
  }
  Flown fly(const Motion& optimized) const {
    return saltus::fly(optimized, model_, options_.nlp.samples);
  }

  const Motion& motion_;
  const BodyModel& model_;
  const OptimizeOptions& options_;
  const ProgressCallback& progress_;
  const std::atomic<bool>* cancel_;
  const AutomaticResolution rules_;
  const bool automatic_;
  /// An unconverged level is refined only under the default iteration limit or a larger one: a
  /// smaller --max-iter (0: the input evaluated as it is) asks for that many iterations.
  const bool refine_unconverged_;
  ProgressCallback counted_;
  int iterations_ = 0, restarts_ = 0;
  double seconds_ = 0.0;
  SolveStage stage_;  // the solve under way, for the caller's progress
  bool landing_pass_ = false;

  std::vector<int> first_level_;
  Motion start_;
  MotionEvaluation start_evaluation_;
  MotionNlpOptions nlp_options_;
  double joint_load_weight_ = 0.0;
};

/// The first level's knots and the motion the solves start from; result.before.
void MotionOptimizer::choose_start(OptimizationResult& result) {
  const int n_key = static_cast<int>(motion_.keyframes.size());
  std::vector<int> subdivisions = automatic_ ? first_subdivisions(motion_, model_, rules_)
                                             : options_.nlp.spans_per_interval(n_key);
  // Where the keyframes are too far apart for the twist (evaluation/keyframe_spacing.h), the
  // root's curve also passes through the free flight's turn inside the interval, on a span per
  // guide at least: the short way would start the solve on a motion that twists the other way.
  std::vector<std::pair<double, Eigen::Quaterniond>> root_guides;
  result.sparse_twist_intervals = sparse_twist_intervals(motion_, model_);
  if (automatic_ && !motion_.spline)
    for (const SparseTwistInterval& interval : result.sparse_twist_intervals) {
      root_guides.insert(root_guides.end(), interval.flight_roots.begin(),
                         interval.flight_roots.end());
      result.twist_guided_intervals.push_back(interval.first_keyframe);
      int& spans = subdivisions[interval.first_keyframe];
      spans = std::max(spans, static_cast<int>(interval.flight_roots.size()) + 1);
    }
  // Start from the motion's stored spline when it is on these knots (re-optimising an optimised
  // motion), otherwise from the keyframe interpolation; refine the knots uniformly while the
  // interpolation cannot meet the keyframes or turns a segment nearly a full turn (see
  // kMaxControlTurn).
  start_ = motion_;
  for (;;) {
    const std::size_t knot_count =
        std::accumulate(subdivisions.begin(), subdivisions.end(), 0) + 7;  // clamped cubic
    if (start_.spline && start_.spline->knots.size() != knot_count) start_.spline.reset();
    EvaluateOptions start_options = evaluate_options(options_.nlp.samples, subdivisions);
    start_options.interpolation.root_guides = root_guides;
    start_evaluation_ = evaluate_motion(start_, model_, start_options);
    const int finest = *std::max_element(subdivisions.begin(), subdivisions.end());
    if (well_posed(start_evaluation_, motion_) || start_.spline ||
        !options_.refine_when_keyframes_missed ||
        finest >= std::max(options_.nlp.knots_per_interval, kMaxAutomaticKnotsPerInterval))
      break;
    for (int& k : subdivisions)
      k = std::max(k, finest + 1);
  }
  first_level_ = subdivisions;
  // "Before" is the paper's interpolation, knots at the keyframes, whatever the optimiser
  // then works on (Table 1 compares it), unless the motion brings its own spline.
  result.before =
      automatic_ && !start_.spline
          ? evaluate_motion(motion_, model_,
                            evaluate_options(options_.nlp.samples, std::vector<int>(n_key - 1, 1)))
          : start_evaluation_;

  // Options that do not apply (the keyframe prior on a fixed resolution) take the value the
  // option table declares for that case.
  nlp_options_ = effective_options(options_).nlp;
  // Least joint effort waits for the polish: with it in the levels, the times moved to where
  // the joints work least, not back to where the flight puts them.
  joint_load_weight_ = nlp_options_.joint_load_weight;
  nlp_options_.joint_load_weight = 0.0;
  for (const Keyframe& k : motion_.keyframes)
    nlp_options_.given_keyframe_times.push_back(k.time);
}

/// One pass of levels from the starting point, the root moment weighed `root_moment_weight`
/// times; each level is recorded in result.levels.
Levels MotionOptimizer::run_levels(double root_moment_weight, OptimizationResult& result) {
  MotionNlpOptions level_options = nlp_options_;
  level_options.root_moment_weight = root_moment_weight;
  std::vector<int> spans = first_level_;
  SolverOptions solver = options_.solver;
  Motion at_start = start_;
  Trajectory<double> start_trajectory = start_evaluation_.trajectory;
  Levels out;
  bool have_best = false;
  for (int level = 0;; ++level) {
    level_options.subdivisions = spans;
    // A level that may still be refined only has to show where its residual lives, so it
    // stops at the coarse objective change; one that then turns out to be the last (near the
    // target) is finished below. The first level stops so only when it starts far above the
    // target.
    SolverOptions level_solver = solver;
    const bool coarse =
        automatic_ && level < rules_.max_refinements &&
        (level > 0 || start_evaluation_.metrics.avg_root_force > 10.0 * rules_.target_force);
    if (coarse)
      level_solver.objective_change_tolerance =
          std::max(solver.objective_change_tolerance, rules_.coarse_objective_change);
    const SolveStage stage = {SolveStage::Kind::kLevel, level + 1,
                              automatic_ ? rules_.max_refinements + 1 : 1, landing_pass_};
    Solved solved = solve(at_start, start_trajectory, level_options, level_solver, stage);
    // Only the automatic resolution decides by the drift in its levels (a free flight:
    // ~50 ms); the free flight's evaluation holds the level's dense check, so it is not run
    // twice.
    std::optional<Flown> flown;
    DenseCheck check;
    if (automatic_ && !coarse) {
      flown = fly(solved.optimized);
      check = flown->evaluation.check;
    } else {
      check = dense_check(model_, solved.trajectory, options_.nlp.samples);
    }
    double force = check.metrics.avg_root_force;
    if (coarse && solved.solve.solved && force <= rules_.target_force && !cancelled()) {
      // Near the target already: this level is the last, so finish it at the full tolerance,
      // warm-started from where the coarse stop left it.
      SolverOptions finish = solver;
      finish.warm_start = true;
      Solved finished = solve(solved.optimized, solved.trajectory, level_options, finish, stage);
      Flown finished_flown = fly(finished.optimized);
      if (finished.solve.solved &&
          finished_flown.evaluation.check.metrics.avg_root_force <= force) {
        finished.solve.iterations += solved.solve.iterations;
        solved = std::move(finished);
        check = finished_flown.evaluation.check;
        force = check.metrics.avg_root_force;
        flown = std::move(finished_flown);
      }
    }
    if (automatic_ && !flown) flown = fly(solved.optimized);
    const double drift = flown ? flown->drift_deg : 0.0;
    result.levels.push_back(
        {spans, force, drift, solved.solve.iterations, solved.solve.status, root_moment_weight});
    if (result.levels.size() == 1) result.optimizer_objective_before = solved.objective_before;
    const bool better = !have_best || (solved.solve.solved && !out.best.solve.solved) ||
                        (solved.solve.solved == out.best.solve.solved && force < out.force);
    const double previous_force = out.force;
    if (better) {
      out.best = std::move(solved);
      out.subdivisions = spans;
      out.force = force;
      out.flown = std::move(flown);
      have_best = true;
    }
    const bool force_met = force <= rules_.target_force;
    if (!automatic_ || (!out.best.solve.solved && !refine_unconverged_) ||
        (force_met && drift <= rules_.max_landing_drift_deg) || level >= rules_.max_refinements ||
        cancelled())
      break;
    if (level > 0 && !(force < (1.0 - rules_.min_gain) * previous_force)) break;  // stopped paying
    if (!better) break;
    const std::vector<double> times = keyframe_times_of(out.best.optimized);
    // Below the force target but drifting: aim at half the force the level reached.
    AutomaticResolution aim = rules_;
    if (force_met) aim.target_force = 0.5 * force;
    if (!refine(spans, residual_per_interval(check, times), times, aim)) break;
    if (out.best.solve.solved) {
      // The finer level starts from this optimum, refitted onto the finer knots at its times.
      at_start = out.best.optimized;
      at_start.spline.reset();
      start_trajectory = refit_trajectory(out.best.trajectory,
                                          clamped_cubic_knots(refine_breakpoints(times, spans)));
      solver.warm_start = true;
    } else {
      // No level has converged yet (dense keyframes on one span each can leave Ipopt
      // alternating between two points until its iteration limit): the finer knots start
      // again from the input, the unconverged level having only said where the residual lives.
      const std::vector<double> given = keyframe_times_of(start_);
      start_trajectory = refit_trajectory(start_evaluation_.trajectory,
                                          clamped_cubic_knots(refine_breakpoints(given, spans)));
    }
  }
  if (have_best) {
    out.time_spreads = keyframe_time_spreads(out.best);
    out.variables = out.best.variables;
    out.constraints = out.best.constraints;
  }
  return out;
}

/// The polish's tries (kPolishTries) over one pass of levels, and what it keeps of them: the
/// first try that holds, else a bounded one over a motion whose joints pay (Fallback). Its
/// record is `p`, which the caller's pass holds.
class MotionOptimizer::PolishLadder {
 public:
  PolishLadder(MotionOptimizer& run, Levels& pass, const OptimizationResult& result)
      : run_(run), pass_(pass), result_(result), p_(pass.polish.emplace()) {
    options_ = run.nlp_options_;
    options_.joint_load_scales = joint_load_scales(result.before.check);
    options_.optimize_timing = false;
    solver_ = run.options_.solver;
    solver_.warm_start = false;  // no time variables: another layout
    solver_.max_iterations = std::min(solver_.max_iterations, kPolishMaxIterations);
    if (!pass.flown) pass.flown = run.fly(pass.best.optimized);
    p_.avg_root_force_before = pass.force;
    p_.landing_drift_before_deg = pass.flown->drift_deg;
    p_.joint_rise_before = joint_rise(*pass.flown);
    baseline_ = {pass.force, pass.flown->drift_deg, p_.joint_rise_before > kJointLoadRiseLimit,
                 run.rules_.max_landing_drift_deg};
  }

  /// The tries in order until one is kept, then the fallback when none is.
  void climb() {
    for (int step = 0; step < kPolishAttempts; ++step) {
      const PolishTry& attempt = kPolishTries[step];
      if (p_.kept || run_.cancelled()) break;
      // Before the joints go unbounded over a motion that made them pay: the closest bounded
      // try again on finer knots. Only where the resolution is the optimiser's to choose.
      if (polish_refines_before_unbounded(attempt, run_.automatic_, baseline_,
                                          over_limit_.has_value()) &&
          kept_on_finer_knots())
        break;
      if (attempt.joints_bounded && bounded_tries_hopeless_) {
        ++p_.bounded_tries_skipped;
        continue;
      }
      take(step);
    }
    if (!p_.kept && fallback_) {
      record(fallback_->step, fallback_->solved, fallback_->flown);
      p_.kept = true;
      pass_.best = std::move(fallback_->solved);
      pass_.flown = std::move(fallback_->flown);
    }
    if (!(p_.kept && p_.joint_bound > 0)) p_.bounded_alternative = closest_bounded_;
  }

 private:
  /// A try's motion, where another solve may start.
  struct TryMotion {
    Motion optimized;
    Trajectory<double> trajectory;
  };
  /// The bounded try kept when no try meets the limits and the motion before makes a joint pay
  /// (kPolishMaxRootForceOverPayingJoints): the one with the least root force.
  struct Fallback {
    int step = 0;
    Solved solved;
    Flown flown;
  };
  /// The bounded try that solved and landed with the least root force past the limit: its
  /// knots may be too coarse for a motion whose joints keep to the input's loads.
  struct OverLimit {
    int step = 0;
    TryMotion motion;
    DenseCheck check;
  };

  /// A motion's largest joint rise over the input's peaks.
  double joint_rise(const Flown& flown) const {
    return largest_joint_load_rise(run_.model_, result_.before.check, flown.evaluation.check)
        .ratio();
  }
  static PolishTryFigures figures(const Solved& solved, const Flown& flown) {
    return {solved.solve.solved, flown.evaluation.metrics.avg_root_force, flown.drift_deg};
  }
  /// Whether a try may be kept (polish_try_holds).
  bool holds(const Solved& solved, const Flown& flown) const {
    return polish_try_holds(figures(solved, flown), baseline_);
  }
  /// What a try reports in `p`: its step, settings, root force, landing and status.
  void record(int step, const Solved& solved, const Flown& flown) {
    const PolishTry& attempt = kPolishTries[step];
    p_.weight = attempt.weight_factor * run_.joint_load_weight_;
    p_.root_moment_weight = attempt.root_moment_weight;
    p_.joint_bound = attempt.joints_bounded ? kPolishJointBound : 0.0;
    p_.attempts = step + 1;
    p_.avg_root_force_after = flown.evaluation.metrics.avg_root_force;
    p_.landing_drift_after_deg = flown.drift_deg;
    p_.status = solved.solve.status;
  }
  /// The polish's options for a try of the ladder on `spans`.
  MotionNlpOptions try_options(const PolishTry& attempt, const std::vector<int>& spans) const {
    MotionNlpOptions out = options_;
    out.subdivisions = spans;
    out.joint_load_weight = attempt.weight_factor * run_.joint_load_weight_;
    out.root_moment_weight = attempt.root_moment_weight;
    out.joint_moment_bounds.clear();
    out.joint_force_bounds.clear();
    if (attempt.joints_bounded)
      set_joint_bounds(result_.before.check, run_.start_evaluation_.check, out);
    return out;
  }
  SolveStage stage(int step) const {
    return {SolveStage::Kind::kJoints, step + 1, kPolishAttempts, run_.landing_pass_};
  }
  /// A polish solve and its free flight, its iterations counted in `p`.
  std::pair<Solved, Flown> solve(const Motion& at_start, const Trajectory<double>& start,
                                 const MotionNlpOptions& nlp, int step) {
    Solved solved = run_.solve(at_start, start, nlp, solver_, stage(step));
    p_.iterations += solved.solve.iterations;
    Flown flown = run_.fly(solved.optimized);
    return {std::move(solved), std::move(flown)};
  }

  /// The try over the limit solved again on knots refined where its residual lives, as a level
  /// is; true when that is kept (JointLoadPolish::knots_refined).
  bool kept_on_finer_knots() {
    const std::vector<double> times = keyframe_times_of(over_limit_->motion.optimized);
    std::vector<int> spans = pass_.subdivisions;
    run_.stage_ = stage(over_limit_->step);
    if (!refine(spans, residual_per_interval(over_limit_->check, times), times, run_.rules_))
      return false;
    Motion at_start = over_limit_->motion.optimized;
    at_start.spline.reset();
    auto [refined, refined_flown] =
        solve(at_start,
              refit_trajectory(over_limit_->motion.trajectory,
                               clamped_cubic_knots(refine_breakpoints(times, spans))),
              try_options(kPolishTries[over_limit_->step], spans), over_limit_->step);
    record(over_limit_->step, refined, refined_flown);
    p_.kept = holds(refined, refined_flown);
    if (!p_.kept) return false;
    p_.knots_refined = true;
    pass_.subdivisions = spans;
    pass_.best = std::move(refined);
    pass_.flown = std::move(refined_flown);
    return true;
  }

  /// A kept try whose joint rose past the bar between the nodes that bound it, solved once more
  /// from it with those bounds lowered; that kept if it holds as this did with a smaller rise.
  void tighten(int step, const MotionNlpOptions& step_options, double rise, Solved& polished,
               Flown& polished_flown) {
    MotionNlpOptions tightened = step_options;
    tighten_joint_bounds(polished_flown.evaluation.check, tightened);
    auto [again, again_flown] = solve(polished.optimized, polished.trajectory, tightened, step);
    if (holds(again, again_flown) && joint_rise(again_flown) < rise) {
      record(step, again, again_flown);
      p_.bounds_tightened = true;
      polished = std::move(again);
      polished_flown = std::move(again_flown);
    }
  }

  /// One try of the ladder, and what it leaves for the tries after it.
  void take(int step) {
    const PolishTry& attempt = kPolishTries[step];
    const MotionNlpOptions step_options = try_options(attempt, pass_.subdivisions);
    const bool from_bounded = !attempt.from_levels && bounded_start_;
    auto [polished, polished_flown] = solve(
        from_bounded ? bounded_start_->optimized : pass_.best.optimized,
        from_bounded ? bounded_start_->trajectory : pass_.best.trajectory, step_options, step);
    record(step, polished, polished_flown);
    const PolishTryFigures tried = figures(polished, polished_flown);
    const bool bounded_solved = attempt.joints_bounded && polished.solve.solved;
    const double rise = bounded_solved ? joint_rise(polished_flown) : 0.0;
    if (bounded_solved) bounded_start_ = TryMotion{polished.optimized, polished.trajectory};
    if (bounded_solved &&
        (!closest_bounded_ || polished_flown.drift_deg < closest_bounded_->landing_drift_deg))
      closest_bounded_ = JointLoadPolish::BoundedAlternative{polished_flown.drift_deg,
                                                             p_.avg_root_force_after, rise};
    p_.kept = polish_try_holds(tried, baseline_);
    if (polish_bounded_tries_hopeless(attempt, p_.kept, tried, baseline_))
      bounded_tries_hopeless_ = true;
    if (polish_tightens(p_.kept, rise) && !run_.cancelled())
      tighten(step, step_options, rise, polished, polished_flown);
    if (polish_over_limit_candidate(
            attempt, p_.kept, tried, baseline_,
            over_limit_ ? std::optional(over_limit_->check.metrics.avg_root_force) : std::nullopt))
      over_limit_ = OverLimit{step, TryMotion{polished.optimized, polished.trajectory},
                              polished_flown.evaluation.check};
    if (p_.kept) {
      pass_.best = std::move(polished);
      pass_.flown = std::move(polished_flown);
    } else if (polish_fallback_candidate(
                   attempt, p_.kept, tried, baseline_,
                   fallback_ ? std::optional(fallback_->flown.evaluation.metrics.avg_root_force)
                             : std::nullopt)) {
      fallback_ = Fallback{step, std::move(polished), std::move(polished_flown)};
    }
  }

  MotionOptimizer& run_;
  Levels& pass_;
  const OptimizationResult& result_;
  JointLoadPolish& p_;
  MotionNlpOptions options_;
  SolverOptions solver_;
  PolishBaseline baseline_;
  std::optional<Fallback> fallback_;
  std::optional<OverLimit> over_limit_;
  /// JointLoadPolish::bounded_alternative, among the bounded tries that solved.
  std::optional<JointLoadPolish::BoundedAlternative> closest_bounded_;
  bool bounded_tries_hopeless_ = false;
  /// The last bounded try that solved, where a step not PolishTry::from_levels starts.
  std::optional<TryMotion> bounded_start_;
};

/// The polish: least joint effort at the keyframe times found, from the best level's optimum
/// on its knots (or a bounded try before it, PolishTry::from_levels). Kept when it solves and its
/// root force stays within the target a motion is held to (kPolishMaxRootForce) or below the
/// levels' (it trades a little root force for joints that do not kick; result.joint_load_polish
/// records both figures). `pass` then holds the polished motion and the polish's record.
void MotionOptimizer::polish(Levels& pass, const OptimizationResult& result) {
  if (!(joint_load_weight_ > 0 && nlp_options_.formulation == Formulation::kRelaxed &&
        pass.best.solve.solved && !cancelled()))
    return;
  PolishLadder(*this, pass, result).climb();
}

/// The result of the kept pass: its motion, evaluation, solve report and records.
void MotionOptimizer::finish(Levels levels, OptimizationResult& result) const {
  result.joint_load_polish = std::move(levels.polish);
  result.keyframe_time_spreads = std::move(levels.time_spreads);
  result.variables = levels.variables;  // the problem's size with its times, polish or not
  result.constraints = levels.constraints;
  Solved best = std::move(levels.best);
  result.solve = best.solve;
  result.solve.iterations = iterations_;
  result.solve.restarts = restarts_;
  result.solve.seconds = seconds_;
  result.optimizer_objective_after = best.objective_after;
  result.subdivisions = levels.subdivisions;
  result.knots_per_interval =
      *std::max_element(levels.subdivisions.begin(), levels.subdivisions.end());
  // The returned motion's evaluation, unless no free flight evaluated it already.
  if (levels.flown) {
    result.after = std::move(levels.flown->evaluation);
    result.landing_drift_deg = levels.flown->drift_deg;
  } else {
    result.after =
        evaluate_motion(best.optimized, model_, evaluate_options(options_.nlp.samples, {}));
  }
  result.optimized_motion = with_own_flight_state(best.optimized, result.after);
  // A run stopped by its cancel flag did not finish the optimiser's policy (the finer levels,
  // the joints' tries): whatever a solve before the stop reached, it is called cancelled.
  if (cancelled()) {
    result.solve.status = "cancelled";
    result.solve.solved = false;
  }
}

}  // namespace

OptimizationResult optimize_motion(const Motion& motion, const BodyModel& model,
                                   const OptimizeOptions& options, const ProgressCallback& progress,
                                   const std::atomic<bool>* cancel) {
  if (options.nlp.knots_per_interval < 1)
    throw std::invalid_argument("knots per interval must be at least 1");
  const int n_key = static_cast<int>(motion.keyframes.size());
  if (n_key < 2) throw std::invalid_argument("a motion needs at least two keyframes");
  if (n_key > kMaxOptimizedKeyframes)
    throw std::invalid_argument(
        "the motion has " + std::to_string(n_key) + " keyframes; optimize takes at most " +
        std::to_string(kMaxOptimizedKeyframes) +
        " (its cost grows faster than their count: 100 took 3.6 min and 1 GB): pick fewer, "
        "e.g. with import --keyframes N");
  OptimizationResult result;
  MotionOptimizer run(motion, model, options, progress, cancel);
  run.choose_start(result);
  Levels levels = run.run_levels(run.level_options().root_moment_weight, result);
  run.polish(levels, result);
  // A motion that still flies off (a light athlete's twist turns 0.1-0.2 N·m of root moment into
  // tens of degrees) is made again: the levels from the start with the root moment weighed as
  // the polish weighs it, then the polish. The motion that lands closer is kept, if its root
  // force stays within the polish's limit or below the first's.
  if (run.automatic() && levels.best.solve.solved && levels.flown &&
      levels.flown->drift_deg > AutomaticResolution{}.max_landing_drift_deg &&
      run.level_options().root_moment_weight < kLandingRootMomentWeight && !run.cancelled()) {
    run.set_landing_pass();
    Levels weighed = run.run_levels(kLandingRootMomentWeight, result);
    run.polish(weighed, result);
    if (weighed.best.solve.solved && weighed.flown &&
        weighed.flown->drift_deg < levels.flown->drift_deg &&
        root_force_within_limit(weighed.flown->evaluation.metrics.avg_root_force,
                                levels.flown->evaluation.metrics.avg_root_force))
      levels = std::move(weighed);
  }
  run.finish(std::move(levels), result);
  return result;
}

}  // namespace saltus
