#pragma once
/// @file
/// Helpers that let the spline and dynamics code run on `double` and on forward-mode automatic
/// differentiation scalars (Eigen::AutoDiffScalar) alike. The optimiser differentiates the same
/// templated code that evaluates it, so the two can never drift apart.

#include <Eigen/Core>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

namespace saltus {

/// Plain value of a scalar (strips derivatives). Used for branching (knot-span search, small-angle
/// switches): branches must depend on values only so that derivatives stay those of one smooth
/// piece.
inline double value_of(double x) {
  return x;
}
template <typename Derivatives>
double value_of(const Eigen::AutoDiffScalar<Derivatives>& x) {
  return x.value();
}

/// Converts a double to Scalar (derivative zero).
template <typename Scalar>
Scalar constant(double x) {
  return Scalar(x);
}

/// atan2 that keeps the scalar type. Eigen 3.4's AutoDiffScalar overload returns dynamic-size
/// derivatives, which heap-allocates inside every fixed-size AD evaluation (and makes GCC 12 -O2
/// emit a false -Wuse-after-free). d atan2(y, x) = (x dy − y dx)/(x² + y²); an empty dynamic
/// derivative vector means zero.
inline double atan2_same_type(double y, double x) {
  return std::atan2(y, x);
}
template <typename Derivatives>
Eigen::AutoDiffScalar<Derivatives> atan2_same_type(const Eigen::AutoDiffScalar<Derivatives>& y,
                                                   const Eigen::AutoDiffScalar<Derivatives>& x) {
  const double yv = y.value();
  const double xv = x.value();
  const double inv_r2 = 1.0 / (xv * xv + yv * yv);
  Eigen::AutoDiffScalar<Derivatives> out;
  out.value() = std::atan2(yv, xv);
  if (y.derivatives().size() == 0) {
    out.derivatives() = x.derivatives() * (-yv * inv_r2);
  } else if (x.derivatives().size() == 0) {
    out.derivatives() = y.derivatives() * (xv * inv_r2);
  } else {
    out.derivatives() = (y.derivatives() * xv - x.derivatives() * yv) * inv_r2;
  }
  return out;
}

}  // namespace saltus
