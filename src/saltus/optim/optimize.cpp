#include "saltus/optim/optimize.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "saltus/evaluation/flight_state.h"
#include "saltus/motion/interpolate.h"

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

OptimizationResult optimize_motion(const Motion& motion, const BodyModel& model,
                                   const OptimizeOptions& options, const ProgressCallback& progress,
                                   const std::atomic<bool>* cancel) {
  if (options.nlp.knots_per_interval < 1)
    throw std::invalid_argument("knots per interval must be at least 1");
  OptimizeOptions chosen = options;
  OptimizationResult result;
  // Start from the motion's stored spline when it is on the requested knots (re-optimising an
  // optimised motion), otherwise from the keyframe interpolation.
  Motion start = motion;
  for (;;) {
    const int k = chosen.nlp.knots_per_interval;
    const std::size_t knot_count = (motion.keyframes.size() - 1) * k + 7;  // clamped cubic
    if (start.spline && start.spline->knots.size() != knot_count) start.spline.reset();
    EvaluateOptions evaluate;
    evaluate.samples = chosen.nlp.samples;
    evaluate.interpolation.knots_per_interval = k;
    result.before = evaluate_motion(start, model, evaluate);
    const KeyframeErrors& missed = result.before.keyframe_errors;
    const bool meets_keyframes = missed.max_quaternion_error <= motion.tolerances.quaternion &&
                                 missed.max_translation_error_m <= motion.tolerances.translation_m;
    const bool well_posed =
        meets_keyframes && largest_control_turn(result.before.trajectory) <= kMaxControlTurn;
    if (well_posed || start.spline || !options.refine_when_keyframes_missed ||
        k >= std::max(options.nlp.knots_per_interval, kMaxAutomaticKnotsPerInterval))
      break;
    chosen.nlp.knots_per_interval = k + 1;
  }
  result.knots_per_interval = chosen.nlp.knots_per_interval;
  MotionNlp nlp(start, model, result.before.trajectory, chosen.nlp);
  result.variables = nlp.variable_count();
  result.constraints = nlp.constraint_count();
  {
    std::vector<double> initial_x(nlp.variable_count());
    nlp.initial_point(initial_x.data());
    result.optimizer_objective_before = nlp.force_objective(initial_x.data());
  }
  result.solve = solve_with_ipopt(nlp, chosen.solver, progress, cancel);

  const double* x = result.solve.x.data();
  result.optimizer_objective_after = nlp.force_objective(x);
  Motion optimized = motion;
  const std::vector<double> times = keyframe_times_from(nlp.layout(), nlp.reference(), x);
  for (std::size_t i = 0; i < times.size(); ++i)
    optimized.keyframes[i].time = times[i];
  optimized.spline = to_stored_spline(trajectory_from(nlp.layout(), nlp.reference(), x));
  EvaluateOptions evaluate;
  evaluate.samples = chosen.nlp.samples;
  evaluate.interpolation.knots_per_interval = result.knots_per_interval;
  result.after = evaluate_motion(optimized, model, evaluate);
  // The file describes the optimised motion: its own take-off state (so `simulate` starts where
  // it starts), and the keyframes' root targets as the optimiser met them (they came from the
  // given take-off's parabola, which the file no longer holds).
  const FlightState own = fit_flight_state(result.after.samples);
  optimized.takeoff.com_position = own.com_position;
  optimized.takeoff.com_velocity = own.com_velocity;
  optimized.takeoff.angular_momentum = own.angular_momentum;
  for (std::size_t i = 0; i < optimized.keyframes.size(); ++i)
    optimized.keyframes[i].root_position = result.after.root_targets[i];
  result.optimized_motion = std::move(optimized);
  return result;
}

}  // namespace saltus
