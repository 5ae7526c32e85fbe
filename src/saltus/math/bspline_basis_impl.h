#pragma once
/// @file
/// Implementation of bspline_basis.h (included from there; do not include directly).

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "saltus/math/scalar.h"

namespace saltus {

namespace detail {

/// 1 / (knots[i + p] − knots[i]) with the Cox-de Boor convention 0/0 := 0 (de Boor, "A Practical
/// Guide to Splines", ch. IX): a zero-length knot interval (the repeated knots of a clamped end)
/// contributes nothing. Decided on the value so that a derivative with respect to the knots is
/// the one of the smooth piece in use.
template <typename Scalar>
Scalar knot_interval_inverse(const std::vector<Scalar>& knots, int i, int p) {
  const Scalar d = knots[i + p] - knots[i];
  if (value_of(d) == 0.0) return Scalar(0.0);
  return Scalar(1.0) / d;
}

}  // namespace detail

template <typename Scalar>
std::vector<Scalar> refine_breakpoints(const std::vector<Scalar>& keyframe_times,
                                       int knots_per_interval) {
  if (keyframe_times.size() < 2)
    throw std::invalid_argument("refine_breakpoints: need at least two keyframe times");
  if (knots_per_interval < 1)
    throw std::invalid_argument("refine_breakpoints: knots_per_interval must be at least 1, got " +
                                std::to_string(knots_per_interval));
  return refine_breakpoints(keyframe_times,
                            std::vector<int>(keyframe_times.size() - 1, knots_per_interval));
}

template <typename Scalar>
std::vector<Scalar> refine_breakpoints(const std::vector<Scalar>& keyframe_times,
                                       const std::vector<int>& spans_per_interval) {
  if (keyframe_times.size() < 2)
    throw std::invalid_argument("refine_breakpoints: need at least two keyframe times");
  if (spans_per_interval.size() + 1 != keyframe_times.size())
    throw std::invalid_argument("refine_breakpoints: one subdivision per keyframe interval");
  std::vector<Scalar> breakpoints;
  for (std::size_t i = 0; i + 1 < keyframe_times.size(); ++i) {
    const int parts = spans_per_interval[i];
    if (parts < 1)
      throw std::invalid_argument("refine_breakpoints: every interval needs at least one span");
    const Scalar& a = keyframe_times[i];
    const Scalar length = keyframe_times[i + 1] - a;
    breakpoints.push_back(a);
    // a + (k/K)·(b − a): affine in the keyframe times, so the extra knots follow them.
    for (int k = 1; k < parts; ++k)
      breakpoints.push_back(a + length * Scalar(static_cast<double>(k) / parts));
  }
  breakpoints.push_back(keyframe_times.back());
  return breakpoints;
}

template <typename Scalar>
std::vector<Scalar> clamped_cubic_knots(const std::vector<Scalar>& breakpoints) {
  if (breakpoints.size() < 2)
    throw std::invalid_argument("clamped_cubic_knots: need at least two breakpoints");
  std::vector<Scalar> knots;
  knots.reserve(breakpoints.size() + 6);
  // Multiplicity 4 at both ends: the curve interpolates its first and last control points.
  for (int k = 0; k < 3; ++k)
    knots.push_back(breakpoints.front());
  knots.insert(knots.end(), breakpoints.begin(), breakpoints.end());
  for (int k = 0; k < 3; ++k)
    knots.push_back(breakpoints.back());
  return knots;
}

template <typename Scalar>
int find_span(const std::vector<Scalar>& knots, double t) {
  const int n = control_count(knots);
  if (n < 4) throw std::invalid_argument("find_span: a cubic knot vector needs at least 8 knots");
  // Spans 3..n-1 cover [knots[3], knots[n]]; t = T belongs to the last span (left limit).
  if (t >= value_of(knots[n])) return n - 1;
  if (t < value_of(knots[4])) return 3;
  // First knot in knots[5..n] strictly greater than t; the span starts one before it.
  const auto first = knots.begin() + 5;
  const auto last = knots.begin() + n;
  const auto it =
      std::upper_bound(first, last, t, [](double x, const Scalar& k) { return x < value_of(k); });
  return static_cast<int>(it - knots.begin()) - 1;
}

template <typename Scalar>
SpanBasis<Scalar> cubic_basis(const std::vector<Scalar>& knots, const Scalar& t) {
  // Outside [knots[3], knots[n]] evaluate at the nearest end knot itself (not a copy of its
  // value), so derivatives with respect to the knots stay exact there too.
  const int n = control_count(knots);
  const Scalar* clamped = &t;
  if (value_of(t) < value_of(knots[3])) clamped = &knots[3];
  if (value_of(t) > value_of(knots[n])) clamped = &knots[n];
  return cubic_basis_on_span(knots, find_span(knots, value_of(*clamped)), *clamped);
}

template <typename Scalar>
SpanBasis<Scalar> cubic_basis_on_span(const std::vector<Scalar>& knots, int span, const Scalar& t) {
  const int n = control_count(knots);
  if (span < 3 || span > n - 1)
    throw std::out_of_range("cubic_basis_on_span: span " + std::to_string(span) + " outside [3, " +
                            std::to_string(n - 1) + "]");
  const int s = span;
  // Cox-de Boor recursion (de Boor 1972; Piegl & Tiller, The NURBS Book, §2.2-2.3) on the span,
  // written with the inverse knot intervals a(i, p) = 1/(k[i+p] − k[i]) (0/0 := 0):
  //   N_{i,p}  = (t − k_i) a(i,p) N_{i,p−1} + (k_{i+p+1} − t) a(i+1,p) N_{i+1,p−1}
  //   N'_{i,p} = p (a(i,p) N_{i,p−1} − a(i+1,p) N_{i+1,p−1})
  // n_p[j] holds N_{s−p+j,p}, j = 0..p; the others vanish on the span (local support).
  Scalar n1[2], n2[3];
  Scalar d2[3];  // first derivative of the degree-2 functions (feeds the cubic's second)
  {
    const Scalar a = detail::knot_interval_inverse(knots, s, 1);
    n1[0] = (knots[s + 1] - t) * a;
    n1[1] = (t - knots[s]) * a;
  }
  {
    const Scalar a1 = detail::knot_interval_inverse(knots, s - 1, 2);
    const Scalar a2 = detail::knot_interval_inverse(knots, s, 2);
    const Scalar l1 = a1 * n1[0];  // a(s−1,2) N_{s−1,1}
    const Scalar l2 = a2 * n1[1];  // a(s,2) N_{s,1}
    n2[0] = (knots[s + 1] - t) * l1;
    n2[1] = (t - knots[s - 1]) * l1 + (knots[s + 2] - t) * l2;
    n2[2] = (t - knots[s]) * l2;
    d2[0] = Scalar(-2.0) * l1;
    d2[1] = Scalar(2.0) * (l1 - l2);
    d2[2] = Scalar(2.0) * l2;
  }
  SpanBasis<Scalar> b;
  b.span = s;
  {
    const Scalar a1 = detail::knot_interval_inverse(knots, s - 2, 3);
    const Scalar a2 = detail::knot_interval_inverse(knots, s - 1, 3);
    const Scalar a3 = detail::knot_interval_inverse(knots, s, 3);
    const Scalar l1 = a1 * n2[0];  // a(s−2,3) N_{s−2,2}
    const Scalar l2 = a2 * n2[1];
    const Scalar l3 = a3 * n2[2];
    b.value[0][0] = (knots[s + 1] - t) * l1;
    b.value[0][1] = (t - knots[s - 2]) * l1 + (knots[s + 2] - t) * l2;
    b.value[0][2] = (t - knots[s - 1]) * l2 + (knots[s + 3] - t) * l3;
    b.value[0][3] = (t - knots[s]) * l3;
    const Scalar three(3.0);
    b.value[1][0] = -three * l1;
    b.value[1][1] = three * (l1 - l2);
    b.value[1][2] = three * (l2 - l3);
    b.value[1][3] = three * l3;
    const Scalar m1 = a1 * d2[0];
    const Scalar m2 = a2 * d2[1];
    const Scalar m3 = a3 * d2[2];
    b.value[2][0] = -three * m1;
    b.value[2][1] = three * (m1 - m2);
    b.value[2][2] = three * (m2 - m3);
    b.value[2][3] = three * m3;
  }
  // Cumulative basis (Kim, Kim & Shin 1995, eq. 7): B̃_j = Σ_{i>=j} B_i. On the span the sum
  // of all four is the partition of unity, so B̃_{s−3} is exactly 1 with zero derivatives.
  for (int d = 0; d < 3; ++d) {
    b.cumulative[d][3] = b.value[d][3];
    b.cumulative[d][2] = b.value[d][2] + b.cumulative[d][3];
    b.cumulative[d][1] = b.value[d][1] + b.cumulative[d][2];
  }
  b.cumulative[0][0] = Scalar(1.0);
  b.cumulative[1][0] = Scalar(0.0);
  b.cumulative[2][0] = Scalar(0.0);
  return b;
}

}  // namespace saltus
