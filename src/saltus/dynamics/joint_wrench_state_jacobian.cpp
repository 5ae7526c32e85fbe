#include "saltus/dynamics/joint_wrench_state_jacobian.h"

#include "saltus/dynamics/spatial_cross_matrices.h"

namespace saltus {

namespace {
/// Columns of a change carried down from an ancestor: its 9 state tangents, then (root only)
/// the root translation's ṗ and p̈.
constexpr int kCarriedColumns = kJointStateTangentSize + 6;
using Carried = Eigen::Matrix<double, 6, kCarriedColumns>;
}  // namespace

JointWrenchStateJacobian::JointWrenchStateJacobian(const BodyModel& model)
    : joint(static_cast<std::size_t>(model.size()) * model.size()),
      touches(static_cast<std::size_t>(model.size()) * model.size()),
      root_translation(model.size()),
      size(model.size()),
      velocity_change(model.size()),
      acceleration_change(model.size()) {}

bool joint_wrench_depends_on(const BodyModel& model, int joint, int segment) {
  for (int k = segment; k >= 0; k = model.segments[k].parent)
    if (k == joint) return true;
  for (int a = model.segments[joint].parent; a >= 0; a = model.segments[a].parent)
    if (a == segment) return true;
  return false;
}

void joint_wrench_state_jacobian(const BodyModel& model, const DynamicsData<double>& data,
                                 const BodyState<double>& state,
                                 const RootWrenchStateJacobian& sweep,
                                 JointWrenchStateJacobian& out) {
  const int n = model.size();
  std::fill(out.touches.begin(), out.touches.end(), 0);
  for (auto& m : out.root_translation)
    m.setZero();
  std::vector<char> below(n);

  // A segment's own state and those of its descendants: F_i's columns brought up the chain.
  for (int i = 0; i < n; ++i) {
    Eigen::Matrix<double, 6, kJointStateTangentSize> own = sweep.segment_columns[i];
    // F_i in its own turning frame: without the turn of X*_i that segment_columns includes.
    if (i > 0) own.leftCols<3>() += 2.0 * motion_cross_rotation(data.joint_wrench[i]);
    out.joint[i * n + i] = own;
    out.touches[i * n + i] = 1;
    Mat6<double> to_ancestor = data.placement[i].motion_matrix_to_child().transpose();
    for (int j = model.segments[i].parent; j >= 0; j = model.segments[j].parent) {
      out.joint[j * n + i] = to_ancestor * sweep.segment_columns[i];
      out.touches[j * n + i] = 1;
      if (j > 0) to_ancestor = data.placement[j].motion_matrix_to_child().transpose() * to_ancestor;
    }
  }

  // An ancestor's state: the change of its velocity and acceleration, carried down its subtree.
  const Eigen::Matrix3d root_rotation_t = data.world_rotation[0].transpose();
  for (int a = 0; a < n; ++a) {
    const Mat6<double> rate_a = joint_rate_cross_matrix(state.joints[a].omega);
    Carried dv = Carried::Zero(), da = Carried::Zero();
    // η: u and b turn by u ×m S·2dη, b ×m S·2dη; v_a moves with u, a_a with b and dv ×m Sω.
    dv.leftCols<3>() = 2.0 * motion_cross_rotation(sweep.parent_velocity[a]);
    da.leftCols<3>() = 2.0 * motion_cross_rotation(sweep.parent_acceleration[a]);
    // ω: dv = S dω, da = S dω ×m Sω + v ×m S dω.
    dv.block<3, 3>(0, 3).setIdentity();
    da.middleCols<3>(3) = motion_cross_rotation(data.velocity[a]);
    // α: da = S dα.
    da.block<3, 3>(0, 6).setIdentity();
    if (a == 0) {
      // ṗ and p̈ enter as u_0 = [0; R₀ᵀṗ], b_0 = [0; R₀ᵀp̈].
      dv.block<3, 3>(3, 9) = root_rotation_t;
      da.block<3, 3>(3, 12) = root_rotation_t;
      const Eigen::Matrix<double, 6, 6> root_change =
          sweep.parent_velocity_sensitivity[0] * dv.rightCols<6>() +
          sweep.composite_inertia[0] * da.rightCols<6>();
      out.root_translation[0] = root_change;
    }
    // The velocity product's share: the parts of du ×m Sω not yet counted.
    da.leftCols<3>() -= rate_a * dv.leftCols<3>();
    da.middleCols<3>(3) -= rate_a * dv.middleCols<3>(3);
    da.middleCols<3>(9) -= rate_a * dv.middleCols<3>(9);
    out.velocity_change[a] = dv;
    out.acceleration_change[a] = da;

    std::fill(below.begin(), below.end(), 0);
    below[a] = 1;
    for (int c = a + 1; c < n; ++c) {
      const int p = model.segments[c].parent;
      if (!below[p]) continue;
      below[c] = 1;
      const Mat6<double> to_child = data.placement[c].motion_matrix_to_child();
      const Carried du = to_child * out.velocity_change[p];
      const Carried db = to_child * out.acceleration_change[p];
      const Carried df =
          sweep.parent_velocity_sensitivity[c] * du + sweep.composite_inertia[c] * db;
      out.joint[c * n + a] = df.leftCols<kJointStateTangentSize>();
      out.touches[c * n + a] = 1;
      if (a == 0) out.root_translation[c] = df.rightCols<6>();
      out.velocity_change[c] = du;
      out.acceleration_change[c] = db - joint_rate_cross_matrix(state.joints[c].omega) * du;
    }
  }
}

}  // namespace saltus
