#include "saltus/evaluation/sampling.h"

#include <stdexcept>

#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/dynamics/momentum.h"
#include "saltus/evaluation/strength_demand.h"

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
SampleRecord record_from(const BodyModel& model, const AthleteStrength& strength,
                         const DynamicsData<double>& data, const BodyState<double>& state,
                         double t) {
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
  r.strength_share.assign(model.size(), 0.0);
  for (int i = 1; i < model.size(); ++i)
    r.strength_share[i] =
        strength_demand(strength, i, state.joints[i], r.joint_wrench[i].tail<3>()).share;
  return r;
}
}  // namespace

std::vector<SampleRecord> evaluate_states(const BodyModel& model, const std::vector<double>& times,
                                          const std::vector<BodyState<double>>& states) {
  if (times.size() != states.size()) throw std::invalid_argument("times and states differ in size");
  DynamicsData<double> data(model);
  const AthleteStrength strength = athlete_strength(model);
  std::vector<SampleRecord> out;
  out.reserve(times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    inverse_dynamics(model, data, states[k]);
    out.push_back(record_from(model, strength, data, states[k], times[k]));
  }
  return out;
}

std::vector<SampleRecord> evaluate_trajectory(const BodyModel& model,
                                              const Trajectory<double>& trajectory,
                                              const std::vector<double>& times) {
  DynamicsData<double> data(model);
  const AthleteStrength strength = athlete_strength(model);
  BodyState<double> state(model.size());
  std::vector<SampleRecord> out;
  out.reserve(times.size());
  for (double t : times) {
    trajectory.sample(t, state);
    inverse_dynamics(model, data, state);
    out.push_back(record_from(model, strength, data, state, t));
  }
  return out;
}

}  // namespace saltus
