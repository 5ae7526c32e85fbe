#pragma once
// Knot vectors and AD scalars shared by the spline tests (unit/math/*_spline_test.cpp,
// bspline_basis_test.cpp).

#include <unsupported/Eigen/AutoDiff>
#include <vector>

#include "saltus/math/bspline_basis.h"

namespace saltus::test {

/// Fixed-size AD with three directions (a control point's coordinates).
using AdFixed = Eigen::AutoDiffScalar<Eigen::Matrix<double, 3, 1>>;
/// Dynamic-size AD (keyframe times, sample times).
using AdDynamic = Eigen::AutoDiffScalar<Eigen::VectorXd>;

/// Keyframe times with uneven gaps (0.31, 0.59, 0.3, 0.84 s) over the paper's 2.04 s flight.
inline const std::vector<double> kNonUniformTimes = {0.0, 0.31, 0.9, 1.2, 2.04};

/// The clamped cubic knot vector on `times`, each interval cut into `knots_per_interval`.
inline std::vector<double> knots_for(const std::vector<double>& times, int knots_per_interval) {
  return clamped_cubic_knots(refine_breakpoints(times, knots_per_interval));
}

}  // namespace saltus::test
