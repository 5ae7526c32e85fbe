#pragma once
/// @file
/// Cubic B-spline basis on a clamped, non-uniform knot vector, with the cumulative basis of
/// Kim, Kim & Shin (1995) used by quaternion B-splines. Templated on the scalar so that the
/// derivative with respect to the knots (keyframe-timing optimisation) comes out of automatic
/// differentiation.
///
/// Knot vector layout for breakpoints b_0 < b_1 < ... < b_m (b_0 = 0, b_m = T):
///   [b_0, b_0, b_0, b_0, b_1, ..., b_{m-1}, b_m, b_m, b_m, b_m]   (m + 7 knots)
/// giving n = m + 3 control points c_0..c_{n-1}; the curve starts at c_0 and ends at c_{n-1}.
/// On the span knots[s] <= t < knots[s+1] (3 <= s <= n-1) only B_{s-3}..B_s are non-zero.

#include <vector>

#include "saltus/math/scalar.h"

namespace saltus {

/// The four non-zero basis functions on one span and two time derivatives, plus the cumulative
/// basis B̃_j(t) = Σ_{i >= j} B_i(t) for j = s-3..s (B̃_{s-3} ≡ 1 on the span).
template <typename Scalar>
struct SpanBasis {
  int span = 3;             ///< s; the first active control point is s - 3
  Scalar value[3][4];       ///< value[d][j] = d-th time derivative of B_{s-3+j}(t)
  Scalar cumulative[3][4];  ///< cumulative[d][j] = d-th time derivative of B̃_{s-3+j}(t)
  int first_control() const { return span - 3; }
};

/// Breakpoints from keyframe times: each interval [t_i, t_{i+1}] split into `knots_per_interval`
/// equal parts (1 = knots at the keyframe times only, the paper's resolution). Because the extra
/// knots are affine in the keyframe times they move with them during timing optimisation.
template <typename Scalar>
std::vector<Scalar> refine_breakpoints(const std::vector<Scalar>& keyframe_times,
                                       int knots_per_interval);
/// The same with its own number of equal parts for each interval (spans_per_interval[i] for
/// [t_i, t_{i+1}], each >= 1).
template <typename Scalar>
std::vector<Scalar> refine_breakpoints(const std::vector<Scalar>& keyframe_times,
                                       const std::vector<int>& spans_per_interval);

/// Clamped cubic knot vector for the breakpoints (layout above).
template <typename Scalar>
std::vector<Scalar> clamped_cubic_knots(const std::vector<Scalar>& breakpoints);

/// Number of control points for a knot vector: knots.size() - 4.
template <typename Scalar>
int control_count(const std::vector<Scalar>& knots) {
  return static_cast<int>(knots.size()) - 4;
}

/// The span s with knots[s] <= t < knots[s+1], clamped to [3, n-1] so t = T (and t outside the
/// knot range) uses the last (first) span. Depends on values only.
template <typename Scalar>
int find_span(const std::vector<Scalar>& knots, double t);

/// Basis on the span containing t (Cox-de Boor with derivatives; exact for non-uniform knots).
/// t outside the knot range is evaluated at the nearest end knot (value, rates of that end).
template <typename Scalar>
SpanBasis<Scalar> cubic_basis(const std::vector<Scalar>& knots, const Scalar& t);

/// Basis on a given span (for callers that fix the span, e.g. at a keyframe time, or the left
/// limit at a knot). Zero-length knot intervals (the clamped ends) use 0/0 := 0, decided on
/// values. Throws std::out_of_range for a span outside [3, n-1].
template <typename Scalar>
SpanBasis<Scalar> cubic_basis_on_span(const std::vector<Scalar>& knots, int span, const Scalar& t);

}  // namespace saltus

#include "saltus/math/bspline_basis_impl.h"
