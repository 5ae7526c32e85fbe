#pragma once
/// @file
/// Analytic first derivatives of every joint's wrench (the moment and force the parent applies
/// on the child's subtree across a ball joint, child frame, moment about the joint centre:
/// DynamicsData::joint_wrench, moment rows first) with respect to every joint's state and the
/// root translation's rates. What the optimiser's joint-load term and joint bounds need
/// (optim/terms/joint_load_term.h, joint_bound_block.h).
///
/// Built on root_wrench_state_jacobian's sweep (Ic_i and K_i for every segment): joint j's
/// subtree wrench F_j depends on
///  - a descendant i's state (i in subtree(j)) through F_i, as the root wrench does, brought to
///    j's frame by the fixed transforms between them; j's own η without the turn of X*_j, since
///    F_j is wanted in j's own (turning) frame;
///  - an ancestor a's state through j's parent's velocity and acceleration only:
///    dF_j = K_j·du_j + Ic_j·db_j, with (du, db) carried down the chain from a to j
///    (dv_c = X_c⁻¹·dv_p, da_c = X_c⁻¹·da_p − crm(Sω_c)·dv_c).
/// Notation as root_wrench_state_jacobian.h.

#include <vector>

#include "saltus/dynamics/root_wrench_state_jacobian.h"

namespace saltus {

using JointWrenchColumns = Eigen::Matrix<double, 6, kJointStateTangentSize>;

/// Result and workspace; sized once per model, reused for every sample.
struct JointWrenchStateJacobian {
  explicit JointWrenchStateJacobian(const BodyModel& model);

  /// d(n_j, f_j)/d(η_i, ω_i, α_i) at [j * size + i]; zero when i is neither in subtree(j) nor
  /// an ancestor of j (then `touches` is false). Row j = 0 (the root wrench) is filled too, in
  /// the root frame about the root origin.
  std::vector<JointWrenchColumns> joint;
  std::vector<char> touches;
  /// d(n_j, f_j)/d(ṗ, p̈) (world frame), per j.
  std::vector<Eigen::Matrix<double, 6, 6>> root_translation;
  int size = 0;

  /// Workspace: the velocity and acceleration changes carried down from one ancestor (its 9
  /// state columns, then the root translation's 6).
  std::vector<Eigen::Matrix<double, 6, 15>> velocity_change, acceleration_change;
};

/// Whether segment k's state can move joint j's wrench: k is j, below j (in its subtree) or above
/// it (an ancestor, the root among them). `touches` is set nowhere else; the joint bounds declare
/// only these columns (optim/terms/joint_bound_block.h).
bool joint_wrench_depends_on(const BodyModel& model, int joint, int segment);

/// Fills `out` for the state whose inverse dynamics is in `data` and whose root-wrench sweep is
/// in `sweep` (root_wrench_state_jacobian on the same state).
void joint_wrench_state_jacobian(const BodyModel& model, const DynamicsData<double>& data,
                                 const BodyState<double>& state,
                                 const RootWrenchStateJacobian& sweep,
                                 JointWrenchStateJacobian& out);

}  // namespace saltus
