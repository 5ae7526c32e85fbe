#include "saltus/optim/optimize.h"

#include <stdexcept>

#include "saltus/motion/interpolate.h"

namespace saltus {

OptimizationResult optimize_motion(const Motion& motion, const BodyModel& model,
                                   const OptimizeOptions& options, const ProgressCallback& progress,
                                   const std::atomic<bool>* cancel) {
  EvaluateOptions evaluate;
  evaluate.samples = options.nlp.samples;
  evaluate.interpolation.knots_per_interval = options.nlp.knots_per_interval;

  // Start from the motion's stored spline when it is on the requested knots (re-optimising an
  // optimised motion), otherwise from the keyframe interpolation.
  Motion start = motion;
  const std::size_t knot_count =
      (motion.keyframes.size() - 1) * options.nlp.knots_per_interval + 7;  // clamped cubic
  if (start.spline && start.spline->knots.size() != knot_count) start.spline.reset();

  OptimizationResult result;
  result.before = evaluate_motion(start, model, evaluate);
  MotionNlp nlp(start, model, result.before.trajectory, options.nlp);
  result.variables = nlp.variable_count();
  result.constraints = nlp.constraint_count();
  result.solve = solve_with_ipopt(nlp, options.solver, progress, cancel);

  const double* x = result.solve.x.data();
  Motion optimized = motion;
  const std::vector<double> times = keyframe_times_from(nlp.layout(), nlp.reference(), x);
  for (std::size_t i = 0; i < times.size(); ++i)
    optimized.keyframes[i].time = times[i];
  optimized.spline = to_stored_spline(trajectory_from(nlp.layout(), nlp.reference(), x));
  result.after = evaluate_motion(optimized, model, evaluate);
  result.optimized_motion = std::move(optimized);
  return result;
}

}  // namespace saltus
