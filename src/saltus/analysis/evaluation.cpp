#include "saltus/analysis/evaluation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/dynamics/momentum.h"

namespace saltus {

std::vector<double> uniform_times(double duration, int count) {
  if (count < 2) throw std::invalid_argument("need at least 2 samples");
  std::vector<double> out(count);
  for (int k = 0; k < count; ++k)
    out[k] = duration * k / (count - 1);
  out.back() = duration;
  return out;
}

namespace {
SampleRecord record_from(const BodyModel& model, const DynamicsData<double>& data, double t) {
  SampleRecord r;
  r.time = t;
  r.segment_position = data.world_position;
  r.segment_rotation.reserve(model.size());
  for (const auto& m : data.world_rotation)
    r.segment_rotation.emplace_back(m);
  const WholeBodyMomentum<double> momentum = whole_body_momentum(model, data);
  r.com = momentum.com;
  r.com_velocity = momentum.com_velocity;
  r.angular_momentum = momentum.angular_about_com;
  r.root_wrench = root_wrench_force_first(data);
  r.residual = residual_world_about_com(data);
  r.joint_wrench.reserve(model.size());
  for (int i = 0; i < model.size(); ++i)
    r.joint_wrench.push_back(joint_wrench_force_first(data, i));
  return r;
}
}  // namespace

std::vector<SampleRecord> evaluate_states(const BodyModel& model, const std::vector<double>& times,
                                          const std::vector<BodyState<double>>& states) {
  if (times.size() != states.size()) throw std::invalid_argument("times and states differ in size");
  DynamicsData<double> data(model);
  std::vector<SampleRecord> out;
  out.reserve(times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    inverse_dynamics(model, data, states[k]);
    out.push_back(record_from(model, data, times[k]));
  }
  return out;
}

std::vector<SampleRecord> evaluate_trajectory(const BodyModel& model,
                                              const Trajectory<double>& trajectory,
                                              const std::vector<double>& times) {
  DynamicsData<double> data(model);
  BodyState<double> state(model.size());
  std::vector<SampleRecord> out;
  out.reserve(times.size());
  for (double t : times) {
    trajectory.sample(t, state);
    inverse_dynamics(model, data, state);
    out.push_back(record_from(model, data, t));
  }
  return out;
}

ForceMetrics force_metrics(const std::vector<SampleRecord>& samples) {
  ForceMetrics m;
  if (samples.size() < 2) return m;
  const double duration = samples.back().time - samples.front().time;
  double sum_all = 0, sum_force = 0, sum_moment = 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const Vector6d& f = samples[k].root_wrench;
    const double force2 = f.head<3>().squaredNorm();
    const double moment2 = f.tail<3>().squaredNorm();
    m.max_force_N = std::max(m.max_force_N, std::sqrt(force2));
    m.max_moment_Nm = std::max(m.max_moment_Nm, std::sqrt(moment2));
    if (k + 1 < samples.size()) {
      const double dt = samples[k + 1].time - samples[k].time;
      const Vector6d& g = samples[k + 1].root_wrench;
      const double next_force2 = g.head<3>().squaredNorm();
      const double next_moment2 = g.tail<3>().squaredNorm();
      sum_force += 0.5 * dt * (force2 + next_force2);
      sum_moment += 0.5 * dt * (moment2 + next_moment2);
    }
  }
  sum_all = sum_force + sum_moment;
  m.objective = sum_all / duration;
  m.avg_root_force = std::sqrt(m.objective / 6.0);
  m.rms_force_N = std::sqrt(sum_force / duration);
  m.rms_moment_Nm = std::sqrt(sum_moment / duration);
  return m;
}

KeyframeErrors keyframe_errors(const Motion& motion, const Trajectory<double>& trajectory,
                               const std::vector<double>& keyframe_times,
                               const std::vector<Eigen::Vector3d>& root_targets) {
  KeyframeErrors e;
  for (std::size_t i = 0; i < motion.keyframes.size(); ++i) {
    const double t = keyframe_times[i];
    const Eigen::Vector3d b = trajectory.root_translation.evaluate(t).position;
    e.max_translation_error_m =
        std::max(e.max_translation_error_m, (b - root_targets[i]).cwiseAbs().maxCoeff());
    for (int seg = 0; seg < trajectory.segment_count(); ++seg) {
      const Eigen::Quaterniond q = trajectory.rotations[seg].evaluate(t).q;
      const Eigen::Quaterniond& target = motion.keyframes[i].rotations[seg];
      e.max_quaternion_error = std::max(e.max_quaternion_error, quaternion_distance(q, target));
      e.max_rotation_error_deg =
          std::max(e.max_rotation_error_deg, rotation_angle_between(q, target) * 180.0 / M_PI);
    }
  }
  return e;
}

}  // namespace saltus
