#include "saltus/evaluation/simulate.h"

#include "saltus/base/constants.h"
#include "saltus/dynamics/free_flight.h"

namespace saltus {

SimulationResult simulate_motion(const Motion& motion, const BodyModel& model,
                                 const EvaluateOptions& options) {
  check_evaluate_options(options);
  const Trajectory<double> trajectory = motion_trajectory(motion, model, options.interpolation);
  const std::vector<double> times = uniform_times(motion.flight_time(), options.samples);

  SimulationResult out;
  FreeFlightInitialState initial;
  initial.com_position = motion.takeoff.com_position;
  initial.com_velocity = motion.takeoff.com_velocity;
  initial.root_orientation = trajectory.rotations[0].evaluate(0.0).q;
  const FlightState own = fit_flight_state(
      evaluate_trajectory(model, trajectory, uniform_times(motion.flight_time(), 201)));
  out.angular_momentum_spread = own.angular_momentum_spread;
  if (motion.takeoff.angular_momentum) {
    out.angular_momentum = *motion.takeoff.angular_momentum;
    out.angular_momentum_from_file = true;
  } else {
    out.angular_momentum = own.angular_momentum;
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
  FreeFlightOptions integration;
  integration.breakpoints.assign(trajectory.knots.begin(), trajectory.knots.end());
  const std::vector<BodyState<double>> states =
      simulate_free_flight(model, joints, initial, times, integration);
  out.samples = evaluate_states(model, times, states);
  out.metrics = force_metrics(out.samples);

  const Keyframe& last = motion.keyframes.back();
  const BodyState<double>& landing = states.back();
  for (int seg = 0; seg < model.size(); ++seg) {
    out.landing_joint_error_deg[model.segments[seg].joint] =
        degrees_from_radians(rotation_angle_between(landing.joints[seg].q, last.rotations[seg]));
  }
  out.landing_root_error_deg = out.landing_joint_error_deg.at(model.segments[0].joint);
  out.landing_com_error_m =
      (out.samples.back().com - ballistic_com(motion.takeoff, motion.flight_time())).norm();
  out.landing_vs_motion_deg = degrees_from_radians(rotation_angle_between(
      landing.joints[0].q, trajectory.rotations[0].evaluate(motion.flight_time()).q));
  return out;
}

}  // namespace saltus
