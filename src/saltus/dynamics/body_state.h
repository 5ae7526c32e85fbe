#pragma once
/// @file
/// The kinematic state of the whole body at one instant: what inverse dynamics consumes and what
/// trajectories and the free-flight simulator produce.

#include <vector>

#include "saltus/math/quaternion.h"

namespace saltus {

/// One joint's rotation and its rates, all in the CHILD segment's frame.
template <typename Scalar>
struct JointState {
  Quat<Scalar> q = Quat<Scalar>::Identity();  ///< parent_from_child (root: world_from_abdomen)
  Vec3<Scalar> omega = Vec3<Scalar>::Zero();  ///< relative angular velocity, child frame, rad/s
  Vec3<Scalar> alpha = Vec3<Scalar>::Zero();  ///< d(omega)/dt in the child frame, rad/s²
};

/// Root translation plus one JointState per segment (index = segment index; joints[0] is the
/// root's orientation relative to the world).
template <typename Scalar>
struct BodyState {
  Vec3<Scalar> root_position = Vec3<Scalar>::Zero();      ///< abdomen origin, world, m
  Vec3<Scalar> root_velocity = Vec3<Scalar>::Zero();      ///< m/s, world
  Vec3<Scalar> root_acceleration = Vec3<Scalar>::Zero();  ///< m/s², world
  std::vector<JointState<Scalar>> joints;

  explicit BodyState(int segment_count = 0) : joints(segment_count) {}
};

}  // namespace saltus
