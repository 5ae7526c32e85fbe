#include "saltus/evaluation/evaluate.h"

#include <stdexcept>

namespace saltus {

void check_evaluate_options(const EvaluateOptions& options) {
  if (options.samples < 2) throw std::invalid_argument("samples must be at least 2");
  if (options.interpolation.knots_per_interval < 1)
    throw std::invalid_argument("knots per interval must be at least 1");
}

MotionEvaluation evaluate_motion(const Motion& motion, const BodyModel& model,
                                 const EvaluateOptions& options) {
  check_evaluate_options(options);
  MotionEvaluation e;
  e.trajectory = motion_trajectory(motion, model, options.interpolation);
  for (const Keyframe& k : motion.keyframes)
    e.keyframe_times.push_back(k.time);
  e.root_targets = keyframe_root_targets(motion, model);
  e.samples = evaluate_trajectory(model, e.trajectory,
                                  uniform_times(motion.flight_time(), options.samples));
  e.check = dense_check(model, e.trajectory, options.samples);
  e.metrics = e.check.metrics;
  e.keyframe_errors = keyframe_errors(motion, e.trajectory, e.keyframe_times, e.root_targets);
  return e;
}

}  // namespace saltus
