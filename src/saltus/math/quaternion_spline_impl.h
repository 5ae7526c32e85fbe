#pragma once
/// @file
/// Implementation of quaternion_spline.h (included from there; do not include directly).

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace saltus {

namespace detail {

/// The span evaluation once the relative rotations w_j = log(c_{j−1}⁻¹ c_j) are known.
/// Kim, Kim & Shin (1995) eq. (11) in local form: q = c0 · Π_{j=1..3} exp(w_j B̃_j(t)). The
/// product is built left to right; for P = A·B with B = exp(w b(t)) (w constant, so B and Ḃ
/// commute with w):
///   P*Ṗ = B*(A*Ȧ)B + B*Ḃ  ⇒  ω_P = R(B)ᵀ ω_A + 2 w ḃ,
///   α_P = R(B)ᵀ α_A − (2 w ḃ) × (R(B)ᵀ ω_A) + 2 w b̈   (using d/dt R(B)ᵀ = −[ω_B]× R(B)ᵀ).
/// The constant c0 starts with ω = α = 0. Unit norm holds by construction: a product of exps.
template <typename Scalar>
QuaternionSample<Scalar> evaluate_span_from_logs(const Quat<Scalar>& c0, const Vec3<Scalar> (&w)[3],
                                                 const SpanBasis<Scalar>& basis) {
  // The three factors are independent of each other: computing them first lets their square
  // roots and sin/cos overlap instead of forming one long dependency chain.
  Quat<Scalar> step[3];
  for (int j = 0; j < 3; ++j)
    step[j] = quat_exp(Vec3<Scalar>(w[j] * basis.cumulative[0][j + 1]));
  const Scalar two(2.0);
  QuaternionSample<Scalar> out;
  out.omega = w[0] * (two * basis.cumulative[1][1]);
  out.alpha = w[0] * (two * basis.cumulative[2][1]);
  for (int j = 1; j < 3; ++j) {
    const Vec3<Scalar> omega_step = w[j] * (two * basis.cumulative[1][j + 1]);
    const Vec3<Scalar> alpha_step = w[j] * (two * basis.cumulative[2][j + 1]);
    const Mat3<Scalar> rt = step[j].toRotationMatrix().transpose();
    const Vec3<Scalar> omega_rotated = rt * out.omega;
    out.alpha = rt * out.alpha - omega_step.cross(omega_rotated) + alpha_step;
    out.omega = omega_rotated + omega_step;
  }
  out.q = c0 * step[0] * step[1] * step[2];
  return out;
}

}  // namespace detail

template <typename Scalar>
QuaternionSample<Scalar> evaluate_quaternion_span(const Quat<Scalar>& c0, const Quat<Scalar>& c1,
                                                  const Quat<Scalar>& c2, const Quat<Scalar>& c3,
                                                  const SpanBasis<Scalar>& basis) {
  const Vec3<Scalar> w[3] = {quat_log(Quat<Scalar>(c0.conjugate() * c1)),
                             quat_log(Quat<Scalar>(c1.conjugate() * c2)),
                             quat_log(Quat<Scalar>(c2.conjugate() * c3))};
  return detail::evaluate_span_from_logs(c0, w, basis);
}

template <typename Scalar>
QuaternionSpline<Scalar>::QuaternionSpline(std::vector<Scalar> knots,
                                           std::vector<Quat<Scalar>> control)
    : knots_(std::move(knots)), control_(std::move(control)) {
  if (knots_.size() < 8)
    throw std::invalid_argument(
        "QuaternionSpline: a cubic knot vector needs at least 8 knots, got " +
        std::to_string(knots_.size()));
  if (static_cast<int>(control_.size()) != control_count(knots_))
    throw std::invalid_argument("QuaternionSpline: " + std::to_string(knots_.size()) +
                                " knots need " + std::to_string(control_count(knots_)) +
                                " control quaternions, got " + std::to_string(control_.size()));
  relative_log_.resize(control_.size(), Vec3<Scalar>::Zero());
  for (std::size_t j = 1; j < control_.size(); ++j)
    relative_log_[j] = quat_log(Quat<Scalar>(control_[j - 1].conjugate() * control_[j]));
}

template <typename Scalar>
Scalar QuaternionSpline<Scalar>::largest_control_turn() const {
  // From the controls, not from relative_log_: at exactly 2π (c_j = −c_{j−1}) the log is 0/0.
  Scalar largest(0);
  for (std::size_t j = 1; j < control_.size(); ++j) {
    const Scalar turn = control_turn(control_[j - 1], control_[j]);
    if (value_of(turn) > value_of(largest)) largest = turn;
  }
  return largest;
}

template <typename Scalar>
QuaternionSample<Scalar> QuaternionSpline<Scalar>::evaluate(const Scalar& t) const {
  // t outside the knot range: the nearest end's value, ω and α (see cubic_basis).
  const SpanBasis<Scalar> basis = cubic_basis(knots_, t);
  const int s = basis.span;
  // Same as evaluate_quaternion_span(control_[s−3..s], basis), with the logs precomputed.
  const Vec3<Scalar> w[3] = {relative_log_[s - 2], relative_log_[s - 1], relative_log_[s]};
  return detail::evaluate_span_from_logs(control_[s - 3], w, basis);
}

template <typename Scalar>
QuaternionSample<Scalar> QuaternionSpline<Scalar>::evaluate_on_span(int span,
                                                                    const Scalar& t) const {
  const SpanBasis<Scalar> basis = cubic_basis_on_span(knots_, span, t);
  const Vec3<Scalar> w[3] = {relative_log_[span - 2], relative_log_[span - 1], relative_log_[span]};
  return detail::evaluate_span_from_logs(control_[span - 3], w, basis);
}

}  // namespace saltus
