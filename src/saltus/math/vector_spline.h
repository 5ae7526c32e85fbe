#pragma once
/// @file
/// Cubic B-spline curves in R³ (the root translation B(t)), on the same clamped knot vectors as
/// the quaternion splines.

#include <Eigen/Core>
#include <vector>

#include "saltus/math/bspline_basis.h"
#include "saltus/math/quaternion.h"

namespace saltus {

template <typename Scalar>
struct VectorSample {
  Vec3<Scalar> position;
  Vec3<Scalar> velocity;
  Vec3<Scalar> acceleration;
};

/// Evaluates on one span from the four active control points and the span basis.
template <typename Scalar>
VectorSample<Scalar> evaluate_vector_span(const Vec3<Scalar>& c0, const Vec3<Scalar>& c1,
                                          const Vec3<Scalar>& c2, const Vec3<Scalar>& c3,
                                          const SpanBasis<Scalar>& basis);

template <typename Scalar>
class VectorSpline {
 public:
  VectorSpline() = default;
  VectorSpline(std::vector<Scalar> knots, std::vector<Vec3<Scalar>> control);
  const std::vector<Scalar>& knots() const { return knots_; }
  const std::vector<Vec3<Scalar>>& control() const { return control_; }
  VectorSample<Scalar> evaluate(const Scalar& t) const;
  /// The same on a given knot span (see QuaternionSpline::evaluate_on_span).
  VectorSample<Scalar> evaluate_on_span(int span, const Scalar& t) const;

 private:
  std::vector<Scalar> knots_;
  std::vector<Vec3<Scalar>> control_;
};

/// Linear least-squares control points so the curve follows points[i] at times[i], plus
/// `smoothness_weight` × Σ‖second difference of control points‖² so it is well posed when the
/// samples are sparse. Dense sampling (e.g. 20 per span) gives a faithful fit.
std::vector<Eigen::Vector3d> fit_vector_spline(const std::vector<double>& knots,
                                               const std::vector<double>& times,
                                               const std::vector<Eigen::Vector3d>& points,
                                               double smoothness_weight = 1e-9);

}  // namespace saltus

#include "saltus/math/vector_spline_impl.h"
