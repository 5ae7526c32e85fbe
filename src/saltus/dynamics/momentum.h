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
  // Each subtree's inertia as one rigid body (mass, CoM, inertia about the CoM), carried into
  // its parent's frame (x ↦ R·x + t, I ↦ R·I·Rᵀ) and added by the parallel-axis theorem:
  // 3×3 work per segment instead of Xᵀ·I·X with 6×6 matrices, the same spatial inertia.
  std::vector<RigidInertia<Scalar>> ic = data.inertia;
  const auto add = [](const RigidInertia<Scalar>& a, const RigidInertia<Scalar>& b) {
    RigidInertia<Scalar> sum;
    sum.mass = a.mass + b.mass;
    if (!(value_of(sum.mass) > 0)) {
      sum.com = a.com;
      sum.inertia_com = a.inertia_com + b.inertia_com;
      return sum;
    }
    sum.com = (a.mass * a.com + b.mass * b.com) / sum.mass;
    const Vec3<Scalar> da = a.com - sum.com;
    const Vec3<Scalar> db = b.com - sum.com;
    const Mat3<Scalar> eye = Mat3<Scalar>::Identity();
    sum.inertia_com = a.inertia_com + b.inertia_com +
                      a.mass * (da.squaredNorm() * eye - da * da.transpose()) +
                      b.mass * (db.squaredNorm() * eye - db * db.transpose());
    return sum;
  };
  for (int i = model.size() - 1; i > 0; --i) {
    const FramePlacement<Scalar>& p = data.placement[i];
    RigidInertia<Scalar> moved;
    moved.mass = ic[i].mass;
    moved.com = p.rotation * ic[i].com + p.translation;
    moved.inertia_com = p.rotation * ic[i].inertia_com * p.rotation.transpose();
    const int parent = model.segments[i].parent;
    ic[parent] = add(ic[parent], moved);
  }
  return ic[0].matrix();
}

}  // namespace saltus
