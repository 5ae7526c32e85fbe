#pragma once
/// @file
/// Helpers that let the spline and dynamics code run on `double` and on forward-mode automatic
/// differentiation scalars (Eigen::AutoDiffScalar) alike. The optimiser differentiates the same
/// templated code that evaluates it, so the two can never drift apart.

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>
#include <cmath>

namespace saltus {

/// Plain value of a scalar (strips derivatives). Used for branching (knot-span search, small-angle
/// switches): branches must depend on values only so that derivatives stay those of one smooth
/// piece.
inline double value_of(double x) { return x; }
template <typename Derivatives>
double value_of(const Eigen::AutoDiffScalar<Derivatives>& x) {
  return x.value();
}

/// Converts a double to Scalar (derivative zero).
template <typename Scalar>
Scalar constant(double x) {
  return Scalar(x);
}

}  // namespace saltus
