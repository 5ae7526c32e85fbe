#pragma once
/// @file
/// Analytic first derivatives of the root wrench (F1..F6, root_wrench_force_first) with respect
/// to every joint's state and the root translation's rates, from one double-precision inverse
/// dynamics pass (after Carpentier & Mansard, "Analytical derivatives of rigid body dynamics
/// algorithms", RSS 2018, specialised to ball joints and to the root wrench only).
///
/// Why it is cheap: a joint j's variables move only the segments of subtree(j), and everything
/// outside it (in particular the parent's velocity and acceleration and the force transforms up
/// to the root) stays fixed. Seen from segment j's frame, subtree(j)'s accumulated wrench F_j is
/// a function of its spatial velocity v_j and acceleration a_j alone (the descendants' own joint
/// states being fixed), linear in a_j with the composite inertia Ic_j as coefficient. With
/// D_j = ∂F_j/∂v_j at fixed a_j, one backward sweep of 6×6 matrices gives every joint's
/// derivative, where forward-mode AD through the whole tree would carry 9·n directions through
/// every segment.
///
/// Notation (Featherstone 2008, ch. 2; spatial.h): S = [I₃; 0] is a ball joint's motion subspace,
/// u_j = X_j⁻¹ v_p and b_j = X_j⁻¹ a_p the parent's velocity and acceleration in j's frame, so
/// v_j = u_j + Sω_j and a_j = b_j + Sα_j + v_j ×m Sω_j (inverse_dynamics_impl.h). The root is the
/// same with a "parent" at rest in the world: u_0 = [0; R₀ᵀṗ], b_0 = [0; R₀ᵀ(p̈ − g)].

#include <vector>

#include "saltus/dynamics/inverse_dynamics.h"

namespace saltus {

/// One joint's state tangent: η (q = q₀·exp(η), quaternion.h convention), ω, α.
inline constexpr int kJointStateTangentSize = 9;

/// Result and workspace; sized once per model, reused for every sample (no allocation).
struct RootWrenchStateJacobian {
  explicit RootWrenchStateJacobian(const BodyModel& model);

  /// d(F1..F6)/d(η_i, ω_i, α_i), 6×9 per segment i, rows force first (N, N·m), all in the root
  /// frame about the root origin. η_i is the rotation tangent at the current rotation q_i of
  /// joint i (for the root: its orientation in the world), q_i(η) = q_i·exp(η).
  std::vector<Eigen::Matrix<double, 6, kJointStateTangentSize>> joint;
  /// d(F1..F6)/d(ṗ, p̈): columns root velocity then root acceleration (world frame).
  Eigen::Matrix<double, 6, 6> root_translation;

  /// Workspace, per segment, segment frame, angular part first (spatial.h order).
  std::vector<Mat6<double>> composite_inertia;  ///< Ic_i = ∂F_i/∂a_i, subtree(i) about i
  /// K_i = ∂F_i/∂v_i − Ic_i·crm(Sω_i): F_i's change for a change du_i of the parent's velocity
  /// seen in i's frame, with b_i fixed (v_i and the velocity product in a_i both move).
  std::vector<Mat6<double>> parent_velocity_sensitivity;
  std::vector<Mat6<double>> root_from_segment_force;  ///< X*_{root←i}, force transform
  /// dF_i/d(η_i, ω_i, α_i) in segment i's frame, the turn of X*_i included (i > 0).
  std::vector<Eigen::Matrix<double, 6, kJointStateTangentSize>> segment_columns;
  std::vector<Vec6<double>> parent_velocity, parent_acceleration;  ///< u_i, b_i
};

/// Fills `out` for the state whose inverse dynamics is in `data`.
/// @param data   inverse_dynamics(model, data, state) already run on `state`
/// @param state  the same state (its ω's and the root's ṗ, p̈ are read)
void root_wrench_state_jacobian(const BodyModel& model, const DynamicsData<double>& data,
                                const BodyState<double>& state, RootWrenchStateJacobian& out);

}  // namespace saltus
