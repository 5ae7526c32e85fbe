#include "saltus/evaluation/simulate.h"

#include "saltus/base/constants.h"

namespace saltus {

TakeoffMomentum takeoff_angular_momentum(const Motion& motion, const BodyModel& model,
                                         const Trajectory<double>& trajectory) {
  const FlightState own = fit_flight_state(
      evaluate_trajectory(model, trajectory, uniform_times(motion.flight_time(), 201)));
  TakeoffMomentum out;
  out.spread = own.angular_momentum_spread;
  if (motion.takeoff.angular_momentum) {
    out.value = *motion.takeoff.angular_momentum;
    out.from_file = true;
  } else {
    out.value = own.angular_momentum;
  }
  return out;
}

PrescribedJoints trajectory_joints(const Trajectory<double>& trajectory) {
  PrescribedJoints out;
  out.motion = [&trajectory](double t, BodyState<double>& state) {
    for (int k = 1; k < trajectory.segment_count(); ++k) {
      const QuaternionSample<double> s = trajectory.rotations[k].evaluate(t);
      state.joints[k].q = s.q;
      state.joints[k].omega = s.omega;
      state.joints[k].alpha = s.alpha;
    }
  };
  out.breakpoints.assign(trajectory.knots.begin(), trajectory.knots.end());
  out.takeoff_root = trajectory.rotations[0].evaluate(0.0).q;
  out.own_landing_root = trajectory.rotations[0].evaluate(trajectory.duration()).q;
  return out;
}

SimulationResult simulate_joint_motion(const Motion& motion, const BodyModel& model,
                                       const PrescribedJoints& joints,
                                       const Eigen::Vector3d& angular_momentum,
                                       const EvaluateOptions& options) {
  check_evaluate_options(options);
  const std::vector<double> times = uniform_times(motion.flight_time(), options.samples);

  SimulationResult out;
  FreeFlightInitialState initial;
  initial.com_position = motion.takeoff.com_position;
  initial.com_velocity = motion.takeoff.com_velocity;
  initial.root_orientation = joints.takeoff_root;
  out.angular_momentum = angular_momentum;
  initial.angular_momentum = angular_momentum;

  FreeFlightOptions integration;
  integration.breakpoints = joints.breakpoints;
  const std::vector<BodyState<double>> states =
      simulate_free_flight(model, joints.motion, initial, times, integration);
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
  out.landing_vs_motion_deg =
      degrees_from_radians(rotation_angle_between(landing.joints[0].q, joints.own_landing_root));
  return out;
}

SimulationResult simulate_motion(const Motion& motion, const BodyModel& model,
                                 const EvaluateOptions& options) {
  check_evaluate_options(options);
  const Trajectory<double> trajectory = motion_trajectory(motion, model, options.interpolation);
  const TakeoffMomentum takeoff = takeoff_angular_momentum(motion, model, trajectory);
  SimulationResult out =
      simulate_joint_motion(motion, model, trajectory_joints(trajectory), takeoff.value, options);
  out.angular_momentum_from_file = takeoff.from_file;
  out.angular_momentum_spread = takeoff.spread;
  return out;
}

}  // namespace saltus
