#pragma once
/// @file
/// A continuous motion: root translation B(t) as a cubic B-spline and one quaternion B-spline per
/// segment, all on one shared clamped knot vector (docs/method.md). Templated so that the optimiser
/// can evaluate it with automatic-differentiation scalars.

#include <vector>

#include "saltus/dynamics/body_state.h"
#include "saltus/math/quaternion_spline.h"
#include "saltus/math/vector_spline.h"

namespace saltus {

template <typename Scalar>
struct Trajectory {
  std::vector<Scalar> knots;                        ///< clamped cubic knot vector, [0, T]
  VectorSpline<Scalar> root_translation;            ///< abdomen origin, world, m
  std::vector<QuaternionSpline<Scalar>> rotations;  ///< per segment (0 = root orientation)

  double duration() const { return value_of(knots.back()); }
  int segment_count() const { return static_cast<int>(rotations.size()); }

  /// Fills `out` (sized for the model) with the state at time t: positions, rates, accelerations.
  /// t outside [0, T] takes the nearest end's state.
  void sample(const Scalar& t, BodyState<Scalar>& out) const {
    const VectorSample<Scalar> b = root_translation.evaluate(t);
    out.root_position = b.position;
    out.root_velocity = b.velocity;
    out.root_acceleration = b.acceleration;
    for (std::size_t k = 0; k < rotations.size(); ++k) {
      const QuaternionSample<Scalar> s = rotations[k].evaluate(t);
      out.joints[k].q = s.q;
      out.joints[k].omega = s.omega;
      out.joints[k].alpha = s.alpha;
    }
  }
  /// The same on a given knot span (a knot time as the left limit of the span that ends there).
  void sample_on_span(int span, const Scalar& t, BodyState<Scalar>& out) const {
    const VectorSample<Scalar> b = root_translation.evaluate_on_span(span, t);
    out.root_position = b.position;
    out.root_velocity = b.velocity;
    out.root_acceleration = b.acceleration;
    for (std::size_t k = 0; k < rotations.size(); ++k) {
      const QuaternionSample<Scalar> s = rotations[k].evaluate_on_span(span, t);
      out.joints[k].q = s.q;
      out.joints[k].omega = s.omega;
      out.joints[k].alpha = s.alpha;
    }
  }
};

}  // namespace saltus
