#include "saltus/analysis/motion_analysis.h"

#include <cmath>
#include <stdexcept>

#include "saltus/dynamics/free_flight.h"

namespace saltus {

namespace {
void check_options(const EvaluateOptions& options) {
  if (options.samples < 2) throw std::invalid_argument("samples must be at least 2");
  if (options.interpolation.knots_per_interval < 1)
    throw std::invalid_argument("knots per interval must be at least 1");
}
}  // namespace

MotionEvaluation evaluate_motion(const Motion& motion, const BodyModel& model,
                                 const EvaluateOptions& options) {
  check_options(options);
  MotionEvaluation e;
  e.trajectory = motion_trajectory(motion, model, options.interpolation);
  for (const Keyframe& k : motion.keyframes)
    e.keyframe_times.push_back(k.time);
  e.root_targets = keyframe_root_targets(motion, model);
  e.samples = evaluate_trajectory(model, e.trajectory,
                                  uniform_times(motion.flight_time(), options.samples));
  e.metrics = force_metrics(e.samples);
  e.keyframe_errors = keyframe_errors(motion, e.trajectory, e.keyframe_times, e.root_targets);
  return e;
}

SimulationResult simulate_motion(const Motion& motion, const BodyModel& model,
                                 const EvaluateOptions& options) {
  check_options(options);
  const Trajectory<double> trajectory = motion_trajectory(motion, model, options.interpolation);
  const std::vector<double> times = uniform_times(motion.flight_time(), options.samples);

  SimulationResult out;
  FreeFlightInitialState initial;
  initial.com_position = motion.takeoff.com_position;
  initial.com_velocity = motion.takeoff.com_velocity;
  initial.root_orientation = trajectory.rotations[0].evaluate(0.0).q;
  if (motion.takeoff.angular_momentum) {
    out.angular_momentum = *motion.takeoff.angular_momentum;
    out.angular_momentum_from_file = true;
  } else {
    out.angular_momentum = evaluate_trajectory(model, trajectory, {0.0}).front().angular_momentum;
  }
  initial.angular_momentum = out.angular_momentum;

  const JointMotion joints = [&trajectory](double t, BodyState<double>& state) {
    for (int k = 1; k < trajectory.segment_count(); ++k) {
      const QuaternionSample<double> s = trajectory.rotations[k].evaluate(t);
      state.joints[k].q = s.q;
      state.joints[k].omega = s.omega;
      state.joints[k].alpha = s.alpha;
    }
  };
  const std::vector<BodyState<double>> states = simulate_free_flight(model, joints, initial, times);
  out.samples = evaluate_states(model, times, states);
  out.metrics = force_metrics(out.samples);

  const Keyframe& last = motion.keyframes.back();
  const BodyState<double>& landing = states.back();
  for (int seg = 0; seg < model.size(); ++seg) {
    out.landing_joint_error_deg[model.segments[seg].joint] =
        rotation_angle_between(landing.joints[seg].q, last.rotations[seg]) * 180.0 / M_PI;
  }
  out.landing_root_error_deg = out.landing_joint_error_deg.at(model.segments[0].joint);
  out.landing_com_error_m =
      (out.samples.back().com - ballistic_com(motion.takeoff, motion.flight_time())).norm();
  return out;
}

}  // namespace saltus
