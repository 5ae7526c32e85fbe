#pragma once
/// @file
/// The take-off state a sampled motion itself implies: the centre of mass's ballistic parabola
/// (g fixed) fitted by least squares, and the constant angular momentum nearest to its L(t).
/// In a flight that obeys Newton's laws both fit exactly; their residuals say how far it is off.
/// Written into optimised motion files (so `simulate` starts from the motion's own state) and
/// used by `simulate` when a motion file gives no angular momentum.

#include <Eigen/Core>
#include <vector>

#include "saltus/evaluation/sampling.h"

namespace saltus {

struct FlightState {
  Eigen::Vector3d com_position = Eigen::Vector3d::Zero();  ///< at t = first sample, world, m
  Eigen::Vector3d com_velocity = Eigen::Vector3d::Zero();  ///< there, m/s
  double com_fit_rms_m = 0.0;  ///< RMS distance of the CoM from the fitted parabola, m
  /// L about the CoM, world, kg·m²/s: the time average of L(t) (trapezoidal rule).
  Eigen::Vector3d angular_momentum = Eigen::Vector3d::Zero();
  double angular_momentum_spread = 0.0;  ///< RMS of L(t) about it, kg·m²/s
};

/// Needs at least two samples at distinct times.
FlightState fit_flight_state(const std::vector<SampleRecord>& samples);

}  // namespace saltus
