#pragma once
// Template definitions for inverse_dynamics.h; include that header instead.

namespace saltus {

template <typename Scalar>
DynamicsData<Scalar>::DynamicsData(const BodyModel& model)
    : placement(model.size()),
      world_rotation(model.size()),
      world_position(model.size()),
      velocity(model.size()),
      acceleration(model.size()),
      joint_wrench(model.size()) {
  inertia.reserve(model.size());
  total_mass = Scalar(model.total_mass());
  for (const Segment& s : model.segments) {
    inertia.push_back(RigidInertia<Scalar>{Scalar(s.mass), s.com.template cast<Scalar>(),
                                           s.inertia.template cast<Scalar>()});
  }
}

template <typename Scalar>
void inverse_dynamics(const BodyModel& model, DynamicsData<Scalar>& data,
                      const BodyState<Scalar>& state) {
  const int n = model.size();
  const Vec3<Scalar> g = gravity().template cast<Scalar>();

  // Forward pass (eqs. 5-6): velocities and accelerations, root first.
  {
    const JointState<Scalar>& root = state.joints[0];
    const Mat3<Scalar> r0 = root.q.toRotationMatrix();
    data.placement[0] = FramePlacement<Scalar>{r0, state.root_position};
    data.world_rotation[0] = r0;
    data.world_position[0] = state.root_position;
    const Vec3<Scalar> v_body = r0.transpose() * state.root_velocity;
    data.velocity[0] << root.omega, v_body;
    // Spatial acceleration of a free body in its own coordinates: [α; Rᵀ(p̈ − g) − ω × Rᵀṗ].
    // The −g is the fictitious base acceleration that brings gravity in (Featherstone §5.3).
    data.acceleration[0] << root.alpha,
        r0.transpose() * (state.root_acceleration - g) - root.omega.cross(v_body);
  }
  for (int i = 1; i < n; ++i) {
    const Segment& seg = model.segments[i];
    const int p = seg.parent;
    const JointState<Scalar>& joint = state.joints[i];
    FramePlacement<Scalar>& x = data.placement[i];
    x.rotation = joint.q.toRotationMatrix();
    x.translation = seg.joint_position.template cast<Scalar>();
    data.world_rotation[i] = data.world_rotation[p] * x.rotation;
    data.world_position[i] = data.world_position[p] + data.world_rotation[p] * x.translation;

    Vec6<Scalar> joint_velocity;
    joint_velocity << joint.omega, Vec3<Scalar>::Zero();
    data.velocity[i] = x.motion_to_child(data.velocity[p]) + joint_velocity;
    Vec6<Scalar> joint_acceleration;
    joint_acceleration << joint.alpha, Vec3<Scalar>::Zero();
    // A ball joint's motion subspace is constant in child coordinates, so the only velocity
    // product term is v_i ×m (S q̇).
    data.acceleration[i] = x.motion_to_child(data.acceleration[p]) + joint_acceleration +
                           cross_motion(data.velocity[i], joint_velocity);
  }

  // Backward pass (eq. 7): each segment's own wrench, then accumulate leaves to root.
  for (int i = 0; i < n; ++i) {
    const Vec6<Scalar> momentum = data.inertia[i].apply(data.velocity[i]);
    data.joint_wrench[i] =
        data.inertia[i].apply(data.acceleration[i]) + cross_force(data.velocity[i], momentum);
  }
  for (int i = n - 1; i > 0; --i) {
    const int p = model.segments[i].parent;
    data.joint_wrench[p] += data.placement[i].force_to_parent(data.joint_wrench[i]);
  }

  // Whole-body centre of mass.
  Vec3<Scalar> weighted = Vec3<Scalar>::Zero();
  for (int i = 0; i < n; ++i) {
    weighted += data.inertia[i].mass *
                (data.world_position[i] + data.world_rotation[i] * data.inertia[i].com);
  }
  data.com = weighted / data.total_mass;
}

template <typename Scalar>
Vec6<Scalar> residual_world_about_com(const DynamicsData<Scalar>& data) {
  const Mat3<Scalar>& r0 = data.world_rotation[0];
  const Vec3<Scalar> force = r0 * data.joint_wrench[0].template tail<3>();
  const Vec3<Scalar> moment_at_root = r0 * data.joint_wrench[0].template head<3>();
  Vec6<Scalar> out;
  out.template head<3>() = force;
  // Moment transfer from the root origin to the CoM: n_G = n_O + (O − G) × f.
  out.template tail<3>() = moment_at_root + (data.world_position[0] - data.com).cross(force);
  return out;
}

}  // namespace saltus
