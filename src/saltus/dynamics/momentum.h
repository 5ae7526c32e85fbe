#pragma once
/// @file
/// Whole-body momentum and the composite rigid-body inertia seen from the root. Both read the
/// kinematics that inverse_dynamics() left in DynamicsData, so call that first.

#include "saltus/dynamics/inverse_dynamics.h"

namespace saltus {

/// Total spatial momentum of all segments, root frame about the root origin, [angular; linear].
template <typename Scalar>
Vec6<Scalar> spatial_momentum_at_root(const BodyModel& model, const DynamicsData<Scalar>& data) {
  std::vector<Vec6<Scalar>> h(model.size());
  for (int i = 0; i < model.size(); ++i)
    h[i] = data.inertia[i].apply(data.velocity[i]);
  for (int i = model.size() - 1; i > 0; --i)
    h[model.segments[i].parent] += data.placement[i].force_to_parent(h[i]);
  return h[0];
}

template <typename Scalar>
struct WholeBodyMomentum {
  Vec3<Scalar> linear;             ///< P, world, kg·m/s
  Vec3<Scalar> angular_about_com;  ///< L_G, world, kg·m²/s
  Vec3<Scalar> com;                ///< world, m
  Vec3<Scalar> com_velocity;       ///< P / m, world, m/s
};

template <typename Scalar>
WholeBodyMomentum<Scalar> whole_body_momentum(const BodyModel& model,
                                              const DynamicsData<Scalar>& data) {
  const Vec6<Scalar> h = spatial_momentum_at_root(model, data);
  const Mat3<Scalar>& r0 = data.world_rotation[0];
  WholeBodyMomentum<Scalar> out;
  out.linear = r0 * h.template tail<3>();
  out.angular_about_com =
      r0 * h.template head<3>() + (data.world_position[0] - data.com).cross(out.linear);
  out.com = data.com;
  out.com_velocity = out.linear / data.total_mass;
  return out;
}

/// Composite rigid-body inertia of the whole body in the root frame about the root origin
/// (6×6, [angular; linear] ordering): the root's wrench is I_c·a_root + bias.
template <typename Scalar>
Mat6<Scalar> composite_inertia_at_root(const BodyModel& model, const DynamicsData<Scalar>& data) {
  std::vector<Mat6<Scalar>> ic(model.size());
  for (int i = 0; i < model.size(); ++i)
    ic[i] = data.inertia[i].matrix();
  for (int i = model.size() - 1; i > 0; --i) {
    const Mat6<Scalar> x = data.placement[i].motion_matrix_to_child();
    ic[model.segments[i].parent] += x.transpose() * ic[i] * x;
  }
  return ic[0];
}

}  // namespace saltus
