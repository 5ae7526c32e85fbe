#pragma once
/// @file
/// Recursive Newton-Euler inverse dynamics with a free-floating root (paper §4, eqs. 5-7;
/// Featherstone 2008, §5.3). Gravity enters as a fictitious upward acceleration of the base, so
/// the result is the wrench the world would have to apply at the root for the motion to happen.
/// In flight nothing touches the body, so physically that wrench is zero: its size measures how
/// far a motion is from obeying Newton's laws.

#include <vector>

#include "saltus/base/constants.h"
#include "saltus/body/body_model.h"
#include "saltus/dynamics/body_state.h"
#include "saltus/dynamics/spatial.h"

namespace saltus {

/// Workspace for inverse dynamics; sized once per model, reused for every sample (no allocation
/// in the sample loop).
template <typename Scalar>
struct DynamicsData {
  explicit DynamicsData(const BodyModel& model);

  std::vector<RigidInertia<Scalar>> inertia;      ///< per segment, about its origin (constant)
  std::vector<FramePlacement<Scalar>> placement;  ///< parent_from_segment (root: world_from_root)
  std::vector<Mat3<Scalar>> world_rotation;       ///< world_from_segment
  std::vector<Vec3<Scalar>> world_position;       ///< segment origin in world, m
  std::vector<Vec6<Scalar>> velocity;             ///< spatial, segment frame, [ω; v]
  std::vector<Vec6<Scalar>> acceleration;         ///< spatial incl. −g, segment frame
  /// Wrench the parent applies on the segment across its joint, segment frame about the joint
  /// centre, [n; f] (the root's: what the world must apply).
  std::vector<Vec6<Scalar>> joint_wrench;
  Vec3<Scalar> com = Vec3<Scalar>::Zero();  ///< whole-body centre of mass, world, m
  Scalar total_mass = Scalar(0);
};

/// Runs forward kinematics and RNEA. Fills every member of `data`.
/// @param state  root translation (world) and one joint state per segment (see body_state.h)
template <typename Scalar>
void inverse_dynamics(const BodyModel& model, DynamicsData<Scalar>& data,
                      const BodyState<Scalar>& state);

/// The paper's F1..F6: root force (N) then moment (N·m) in the root frame about the root origin.
template <typename Scalar>
Vec6<Scalar> root_wrench_force_first(const DynamicsData<Scalar>& data) {
  Vec6<Scalar> out;
  out.template head<3>() = data.joint_wrench[0].template tail<3>();
  out.template tail<3>() = data.joint_wrench[0].template head<3>();
  return out;
}

/// The same wrench in the world frame about the whole-body CoM, force then moment: equal to
/// dP/dt − m·g and dL_G/dt (docs/formats.md, "res_*").
template <typename Scalar>
Vec6<Scalar> residual_world_about_com(const DynamicsData<Scalar>& data);

/// Joint wrench force first, segment frame about the joint centre (for joint-load analysis).
template <typename Scalar>
Vec6<Scalar> joint_wrench_force_first(const DynamicsData<Scalar>& data, int segment) {
  Vec6<Scalar> out;
  out.template head<3>() = data.joint_wrench[segment].template tail<3>();
  out.template tail<3>() = data.joint_wrench[segment].template head<3>();
  return out;
}

}  // namespace saltus

#include "saltus/dynamics/inverse_dynamics_impl.h"
