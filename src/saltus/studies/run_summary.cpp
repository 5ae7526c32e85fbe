#include "saltus/studies/run_summary.h"

namespace saltus {

RunSummary summarize_run(const Motion& motion, const OptimizationResult& result) {
  RunSummary s;
  s.motion_name = motion.name;
  s.keyframes = static_cast<int>(motion.keyframes.size());
  s.status = result.solve.status;
  s.solved = result.solve.solved;
  s.iterations = result.solve.iterations;
  s.seconds = result.solve.seconds;
  s.variables = result.variables;
  s.constraints = result.constraints;
  s.knots_per_interval = result.knots_per_interval;
  s.restarts = result.solve.restarts;
  s.objective_before = result.before.metrics.objective;
  s.objective_after = result.after.metrics.objective;
  s.avg_force_before = result.before.metrics.avg_root_force;
  s.avg_force_after = result.after.metrics.avg_root_force;
  s.max_force_after = result.after.metrics.max_force_N;
  s.max_quaternion_error = result.after.keyframe_errors.max_quaternion_error;
  s.keyframe_times_before = result.before.keyframe_times;
  s.keyframe_times_after = result.after.keyframe_times;
  return s;
}

}  // namespace saltus
