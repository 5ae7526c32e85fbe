#pragma once
/// @file
/// Unit-quaternion cubic B-spline curves in Kim-Kim-Shin cumulative form, evaluated locally
/// (docs/method.md): on span s only control quaternions q_{s-3}..q_s act,
///   q(t) = q_{s-3} · Π_{j=s-2..s} exp(ω_j B̃_j(t)),   ω_j = log(q_{j-1}⁻¹ q_j).
/// The curve has unit norm by construction and is C² wherever the knots are simple.
/// Angular velocity and acceleration are in the curve's own (child) frame:
///   ω = 2·vec(q* q̇),  α = dω/dt = 2·vec(q* q̈) (the q̇* q̇ term is real).

#include <vector>

#include "saltus/math/bspline_basis.h"
#include "saltus/math/quaternion.h"

namespace saltus {

template <typename Scalar>
struct QuaternionSample {
  Quat<Scalar> q;      ///< orientation (unit)
  Vec3<Scalar> omega;  ///< body-frame angular velocity, rad/s
  Vec3<Scalar> alpha;  ///< body-frame angular acceleration, rad/s²
};

/// Evaluates the curve on one span from its four active control quaternions (in order) and the
/// span basis. Allocation-free; the optimiser calls this directly.
template <typename Scalar>
QuaternionSample<Scalar> evaluate_quaternion_span(const Quat<Scalar>& c0, const Quat<Scalar>& c1,
                                                  const Quat<Scalar>& c2, const Quat<Scalar>& c3,
                                                  const SpanBasis<Scalar>& basis);

template <typename Scalar>
class QuaternionSpline {
 public:
  QuaternionSpline() = default;
  /// @param knots    clamped cubic knot vector (see bspline_basis.h)
  /// @param control  control_count(knots) unit quaternions. Their signs are part of the curve:
  ///                  w_j = log(c_{j-1}⁻¹ c_j) turns the short way (<= 180°) when consecutive
  ///                  controls have a non-negative dot product and the long way otherwise, so
  ///                  never flip a control point of a given curve. Throws std::invalid_argument
  ///                  if the count does not match the knots.
  QuaternionSpline(std::vector<Scalar> knots, std::vector<Quat<Scalar>> control);

  const std::vector<Scalar>& knots() const { return knots_; }
  const std::vector<Quat<Scalar>>& control() const { return control_; }

  /// Orientation and body-frame derivatives at time t. The span is found by binary search;
  /// an interior knot belongs to the span on its right, t = T to the last span (left limit).
  /// t outside the knot range is clamped to the nearest end knot (value, ω and α of that end).
  QuaternionSample<Scalar> evaluate(const Scalar& t) const;
  /// The same on a given knot span (3 <= span <= control count − 1), e.g. at its right end as
  /// the left limit: a knot then belongs to whichever span the caller integrates.
  QuaternionSample<Scalar> evaluate_on_span(int span, const Scalar& t) const;

  /// The largest turn between consecutive control points, 2‖w_j‖ in [0, 2π] (rad). Near 2π the
  /// log map that defines w_j reaches its branch point: its derivative grows like
  /// 1/sin(‖w_j‖), so the curve's sensitivity to its controls is unbounded there.
  Scalar largest_control_turn() const;

 private:
  std::vector<Scalar> knots_;
  std::vector<Quat<Scalar>> control_;
  /// w_j = log(c_{j-1}⁻¹ c_j) for j >= 1 (entry 0 unused), computed once by the constructor:
  /// they do not depend on t, and recomputing them (an atan2 each) would dominate evaluate().
  std::vector<Vec3<Scalar>> relative_log_;
};

struct QuaternionFitOptions {
  /// Weight of the smoothness term Σ‖σ_{j+1} ω_{j+1} − σ_j ω_j‖² that makes the
  /// (underdetermined) fit unique; ω_j = log(q_{j−1}⁻¹ q_j), σ_j = h̄/(τ_j − τ_{j−1}) with τ the
  /// Greville abscissae and h̄ their mean spacing (σ ≡ 1 for uniform spacing). The normalisation
  /// makes a constant-rate rotation cost nothing, so the clamped ends do not spin up. The
  /// penalised optimum misses the keyframes by O(weight), so when the keyframes can be met
  /// exactly the fit finishes with minimum-norm Gauss-Newton projections onto them.
  double smoothness_weight = 1e-6;
  int max_iterations = 100;
  double tolerance = 1e-12;  ///< stop when the step norm falls below this
};

/// The paper's §5.2 fit: control quaternions such that the curve on `knots` passes as near as
/// possible through targets[i] at times[i] (Levenberg-Marquardt in local tangent coordinates,
/// q_j = q̄_j·exp(δ_j), exact Jacobians by forward AD). Targets (any order) are sorted by time and
/// sign-aligned to their predecessors first; the start is the slerp of the targets at each
/// control point's Greville abscissa. When there are no more targets than control points the
/// curve interpolates them to rounding (~1e-15 rad). The result is sign-aligned (consecutive
/// control quaternions have non-negative dot product) except where the keyframes force more than
/// 180° between consecutive controls (fast turns over short knot intervals, e.g. 90° in 0.3 s
/// next to 90° in 0.6 s with knots at the keyframes only): there the negative dot product is what
/// the curve needs, and flipping it would change the curve.
/// Throws std::invalid_argument for size mismatches, fewer than 8 knots, breakpoints that do not
/// increase strictly, or times outside [knots[3], knots[n]].
std::vector<Quat<double>> fit_quaternion_spline(const std::vector<double>& knots,
                                                const std::vector<double>& times,
                                                const std::vector<Quat<double>>& targets,
                                                const QuaternionFitOptions& options = {});

}  // namespace saltus

#include "saltus/math/quaternion_spline_impl.h"
