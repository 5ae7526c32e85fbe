#pragma once
/// @file
/// Whole-body rotation quantities for teaching why a tucked body spins faster: the angular
/// momentum about the centre of mass (constant in a valid flight), the whole-body moment of
/// inertia about the CoM, the whole-body angular velocity ω = I⁻¹·L, and Yeadon's somersault,
/// tilt and twist angles with the turns counted by them. Everything is derived from SampleRecords
/// (segment poses and the angular momentum that inverse dynamics computed through
/// dynamics/momentum.h), so front ends show these numbers without re-implementing any physics.

#include <Eigen/Core>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/sampling.h"

namespace saltus {

struct RotationSample {
  double time = 0.0;  ///< s
  /// L about the whole-body CoM, world frame, kg·m²/s (SampleRecord::angular_momentum).
  Eigen::Vector3d angular_momentum = Eigen::Vector3d::Zero();
  /// Whole-body inertia tensor about the CoM, world axes, kg·m².
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  /// I_xx: moment of inertia about the somersault axis (world x through the CoM), kg·m².
  double somersault_inertia = 0.0;
  /// ω = I⁻¹·L, world frame, rad/s: the angular velocity of the rigid body that would have the
  /// same inertia and angular momentum (the whole body's "average" angular velocity; equal to
  /// the body's angular velocity when it does not change shape).
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  /// ω_x, rad/s: somersault rate about the world x axis (negative = backward,
  /// docs/method.md, "Conventions").
  double somersault_rate = 0.0;
  /// ω projected on the root segment's long axis (its y axis in the world), rad/s: the spin
  /// about the body's long axis (not Yeadon's twist rate, which is relative to the somersault).
  double twist_rate = 0.0;
  /// Yeadon's somersault φ, tilt θ and twist ψ of the root, degrees (yeadon_angles.h), φ and ψ
  /// continuous over the samples.
  double somersault_deg = 0.0, tilt_deg = 0.0, twist_deg = 0.0;
  /// Somersaults and twists since the first sample, revolutions: (φ − φ₀)/360° and
  /// (ψ − ψ₀)/360° (signed: < 0 backward; > 0 to the left).
  double somersaults = 0.0;
  double twists = 0.0;
};

/// Whole-body inertia tensor about the CoM in world axes from the segment poses of one sample:
/// Σ R_i·I_i·R_iᵀ + m_i·(|r_i|²·1 − r_i·r_iᵀ), r_i = segment CoM − whole-body CoM (parallel axes).
/// @param sample  must hold one pose per model segment (as evaluate_trajectory fills it)
Eigen::Matrix3d whole_body_inertia_about_com(const BodyModel& model, const SampleRecord& sample);

/// Rotation quantities at every sample (consecutive samples less than half a turn apart). Throws
/// std::invalid_argument if a sample does not hold one pose per segment.
std::vector<RotationSample> rotation_metrics(const BodyModel& model,
                                             const std::vector<SampleRecord>& samples);

}  // namespace saltus
