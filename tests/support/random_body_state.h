#pragma once
// A generic body state for derivative tests: tilted joints, brisk rates, the root moving and
// accelerating (the same seed gives the same state).

#include <random>

#include "saltus/dynamics/body_state.h"
#include "saltus/math/quaternion.h"

namespace saltus::test {

inline BodyState<double> random_body_state(int segments, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  auto vec = [&](double scale) {
    return Eigen::Vector3d(scale * normal(rng), scale * normal(rng), scale * normal(rng));
  };
  BodyState<double> state(segments);
  state.root_position = vec(1.0);
  state.root_velocity = vec(3.0);
  state.root_acceleration = vec(10.0);
  for (JointState<double>& joint : state.joints) {
    joint.q = quat_exp(vec(0.6));
    joint.omega = vec(4.0);
    joint.alpha = vec(30.0);
  }
  return state;
}

}  // namespace saltus::test
