#pragma once
/// @file
/// Unit-quaternion cubic B-spline curves in Kim-Kim-Shin cumulative form, evaluated locally
/// (DESIGN §5): on span s only control quaternions q_{s-3}..q_s act,
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
  /// @param control  control_count(knots) unit quaternions, consecutive ones sign-aligned
  QuaternionSpline(std::vector<Scalar> knots, std::vector<Quat<Scalar>> control);

  const std::vector<Scalar>& knots() const { return knots_; }
  const std::vector<Quat<Scalar>>& control() const { return control_; }

  /// Orientation and body-frame derivatives at time t (t outside the knot range is clamped).
  QuaternionSample<Scalar> evaluate(const Scalar& t) const;

 private:
  std::vector<Scalar> knots_;
  std::vector<Quat<Scalar>> control_;
};

struct QuaternionFitOptions {
  /// Weight of the smoothness term Σ‖ω_{j+1} − ω_j‖² that makes the (underdetermined) fit
  /// unique; small so the curve still passes through the keyframes.
  double smoothness_weight = 1e-6;
  int max_iterations = 100;
  double tolerance = 1e-12;  ///< stop when the step norm falls below this
};

/// The paper's §5.2 fit: control quaternions such that the curve on `knots` passes as near as
/// possible through targets[i] at times[i] (Gauss-Newton in local tangent coordinates,
/// q_j = q̄_j·exp(δ_j)). Targets are sign-aligned to their predecessors first. The result is
/// sign-aligned (consecutive control quaternions have non-negative dot product).
std::vector<Quat<double>> fit_quaternion_spline(const std::vector<double>& knots,
                                                const std::vector<double>& times,
                                                const std::vector<Quat<double>>& targets,
                                                const QuaternionFitOptions& options = {});

}  // namespace saltus

#include "saltus/math/quaternion_spline_impl.h"
