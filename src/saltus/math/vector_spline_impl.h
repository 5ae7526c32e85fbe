#pragma once
/// @file
/// Implementation of vector_spline.h (included from there; do not include directly).

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace saltus {

template <typename Scalar>
VectorSample<Scalar> evaluate_vector_span(const Vec3<Scalar>& c0, const Vec3<Scalar>& c1,
                                          const Vec3<Scalar>& c2, const Vec3<Scalar>& c3,
                                          const SpanBasis<Scalar>& basis) {
  // x^(d)(t) = Σ_j B_j^(d)(t) c_j over the four basis functions alive on the span.
  VectorSample<Scalar> out;
  Vec3<Scalar>* rows[3] = {&out.position, &out.velocity, &out.acceleration};
  for (int d = 0; d < 3; ++d) {
    *rows[d] = c0 * basis.value[d][0] + c1 * basis.value[d][1] + c2 * basis.value[d][2] +
               c3 * basis.value[d][3];
  }
  return out;
}

template <typename Scalar>
VectorSpline<Scalar>::VectorSpline(std::vector<Scalar> knots, std::vector<Vec3<Scalar>> control)
    : knots_(std::move(knots)), control_(std::move(control)) {
  if (knots_.size() < 8)
    throw std::invalid_argument("VectorSpline: a cubic knot vector needs at least 8 knots, got " +
                                std::to_string(knots_.size()));
  if (static_cast<int>(control_.size()) != control_count(knots_))
    throw std::invalid_argument("VectorSpline: " + std::to_string(knots_.size()) + " knots need " +
                                std::to_string(control_count(knots_)) + " control points, got " +
                                std::to_string(control_.size()));
}

template <typename Scalar>
VectorSample<Scalar> VectorSpline<Scalar>::evaluate(const Scalar& t) const {
  // t outside the knot range: the nearest end's value and rates (see cubic_basis).
  const SpanBasis<Scalar> basis = cubic_basis(knots_, t);
  const int s = basis.span;
  return evaluate_vector_span(control_[s - 3], control_[s - 2], control_[s - 1], control_[s],
                              basis);
}

template <typename Scalar>
VectorSample<Scalar> VectorSpline<Scalar>::evaluate_on_span(int span, const Scalar& t) const {
  const SpanBasis<Scalar> basis = cubic_basis_on_span(knots_, span, t);
  return evaluate_vector_span(control_[span - 3], control_[span - 2], control_[span - 1],
                              control_[span], basis);
}

}  // namespace saltus
