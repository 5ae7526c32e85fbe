#pragma once
/// @file
/// Physical and angular constants shared by every layer (docs/method.md, "Conventions": SI
/// units, y up).

#include <Eigen/Core>

namespace saltus {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegreesPerRadian = 180.0 / kPi;
/// Standard gravity, m/s².
inline constexpr double kStandardGravity = 9.81;

/// Gravity in the world frame: (0, −9.81, 0) m/s², y up.
inline Eigen::Vector3d gravity() {
  return Eigen::Vector3d(0.0, -kStandardGravity, 0.0);
}

/// Angle in degrees from radians (x · 180 / π, the form every report has used).
inline double degrees_from_radians(double radians) {
  return radians * 180.0 / kPi;
}

}  // namespace saltus
