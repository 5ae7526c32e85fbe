#include "saltus/dynamics/root_wrench_state_jacobian.h"

#include "saltus/dynamics/spatial_cross_matrices.h"

namespace saltus {

namespace {

using Mat6d = Mat6<double>;
using Vec6d = Vec6<double>;

}  // namespace

RootWrenchStateJacobian::RootWrenchStateJacobian(const BodyModel& model)
    : joint(model.size()),
      composite_inertia(model.size()),
      parent_velocity_sensitivity(model.size()),
      root_from_segment_force(model.size()),
      segment_columns(model.size()),
      parent_velocity(model.size()),
      parent_acceleration(model.size()) {}

void root_wrench_state_jacobian(const BodyModel& model, const DynamicsData<double>& data,
                                const BodyState<double>& state, RootWrenchStateJacobian& out) {
  const int n = model.size();
  std::vector<Mat6d>& composite = out.composite_inertia;
  std::vector<Mat6d>& sensitivity = out.parent_velocity_sensitivity;

  // Each segment's own terms: f_i = I a_i + v_i ×* I v_i, so ∂f_i/∂a_i = I and
  // ∂f_i/∂v_i = crf(v_i)·I + (δv ↦ δv ×* I v_i).
  for (int i = 0; i < n; ++i) {
    const RigidInertia<double>& inertia = data.inertia[i];
    composite[i] = inertia.matrix();
    sensitivity[i] = force_cross_matrix(data.velocity[i]) * composite[i] +
                     cross_force_by_velocity(inertia.apply(data.velocity[i]));
  }

  // Backward sweep, leaves to root. When segment i is reached every child has already added
  // itself, so sensitivity[i] holds D_i = ∂F_i/∂v_i (a_i fixed) and is turned into K_i: a change
  // du_i moves v_i by du_i and a_i by du_i ×m Sω_i = −crm(Sω_i)·du_i. A child c then adds
  // X*_c·K_c·X_c⁻¹ to its parent's D_p and X*_c·Ic_c·X_c⁻¹ to Ic_p (the composite-rigid-body
  // recursion, Featherstone 2008 §6.2).
  for (int i = n - 1; i >= 0; --i) {
    sensitivity[i] -= composite[i] * joint_rate_cross_matrix(state.joints[i].omega);
    if (i == 0) break;
    const int p = model.segments[i].parent;
    const Mat6d to_child = data.placement[i].motion_matrix_to_child();
    const Mat6d to_parent = to_child.transpose();  // force transform X*_i = (X_i⁻¹)ᵀ
    composite[p] += to_parent * composite[i] * to_child;
    sensitivity[p] += to_parent * sensitivity[i] * to_child;
  }

  // Forward sweep: force transforms to the root, then each joint's 9 columns.
  const Eigen::Matrix3d root_rotation_t = data.world_rotation[0].transpose();
  for (int i = 0; i < n; ++i) {
    Vec6d& parent_velocity = out.parent_velocity[i];  // u_i, b_i: the parent's, in i's frame
    Vec6d& parent_acceleration = out.parent_acceleration[i];
    Mat6d& to_root = out.root_from_segment_force[i];
    if (i == 0) {
      to_root.setIdentity();
      parent_velocity << Eigen::Vector3d::Zero(), root_rotation_t * state.root_velocity;
      parent_acceleration << Eigen::Vector3d::Zero(),
          root_rotation_t * (state.root_acceleration - gravity());
    } else {
      const int p = model.segments[i].parent;
      const FramePlacement<double>& x = data.placement[i];
      to_root = out.root_from_segment_force[p] * x.motion_matrix_to_child().transpose();
      parent_velocity = x.motion_to_child(data.velocity[p]);
      parent_acceleration = x.motion_to_child(data.acceleration[p]);
    }
    const Mat6d& ic = composite[i];
    const Mat6d& k = sensitivity[i];
    const Mat63d u_cross = motion_cross_rotation(parent_velocity);

    // Columns in segment i's frame, angular rows first.
    Eigen::Matrix<double, 6, kJointStateTangentSize>& local = out.segment_columns[i];
    // η: q·exp(η) rotates i's frame by 2η (quaternion exp, rotation angle 2|η|), so u and b,
    // fixed in the parent, turn by du = u ×m S·2dη, db = b ×m S·2dη. For a non-root joint the
    // transform to the parent turns too: X*(η)·F_i changes by X*_i·(S·2dη ×* F_i), and
    // S·δ ×* [n; f] = [δ × n; δ × f] = −[[n]×; [f]×]·δ. The root's F_0 is wanted in its own
    // (turning) frame, so it has no such term.
    Mat63d eta = k * u_cross + ic * motion_cross_rotation(parent_acceleration);
    if (i > 0) eta -= motion_cross_rotation(data.joint_wrench[i]);
    local.leftCols<3>() = 2.0 * eta;
    // ω: dv_i = S dω and da_i = S dω ×m Sω + v_i ×m S dω; K_i holds the first of these.
    local.middleCols<3>(3) = k.leftCols<3>() + ic * motion_cross_rotation(data.velocity[i]);
    // α: da_i = S dα.
    local.rightCols<3>() = ic.leftCols<3>();

    // lazyProduct keeps this small fixed-size product out of Eigen's blocked GEMM kernel.
    const Eigen::Matrix<double, 6, kJointStateTangentSize> in_root = to_root.lazyProduct(local);
    out.joint[i].topRows<3>() = in_root.bottomRows<3>();  // force first
    out.joint[i].bottomRows<3>() = in_root.topRows<3>();
  }

  // Root translation: ṗ enters as u_0 = [0; R₀ᵀṗ], p̈ as b_0 = [0; R₀ᵀp̈].
  Eigen::Matrix<double, 6, 6> translation;
  translation.leftCols<3>() = sensitivity[0].rightCols<3>() * root_rotation_t;
  translation.rightCols<3>() = composite[0].rightCols<3>() * root_rotation_t;
  out.root_translation.topRows<3>() = translation.bottomRows<3>();
  out.root_translation.bottomRows<3>() = translation.topRows<3>();
}

}  // namespace saltus
