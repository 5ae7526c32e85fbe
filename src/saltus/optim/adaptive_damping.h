#pragma once
/// @file
/// The factor μ of the relaxed model's Levenberg–Marquardt damping μ·J(x)·I, adapted from step
/// to step like a trust region (Nielsen 1999; Fan & Yuan 2005 for the ‖F‖²-scaled form).
///
/// Why it adapts. At the paper's resolution (K = 1) the optimum keeps a root force of a few N
/// to tens of N, where the Gauss–Newton model misses the residual's own curvature Σ F·∇²F and
/// the damping outweighs the curvature it does model: a fixed μ = 1 then acts as a fixed trust
/// radius, and the late steps stay short. Letting μ fall while the model predicts the decrease
/// well lets the steps grow; raising it when it predicts badly or the line search has to cut the
/// step keeps the robustness of μ = 1. Measurements: docs/optimizer.md, "Measurement history"
/// (Damping).

#include <algorithm>

namespace saltus {

struct DampingRule {
  double initial = 1.0;  ///< μ at the first iteration: the steadiest fixed damping
  double minimum = 0.01;
  double maximum = 10.0;
  double shrink = 2.0;       ///< μ /= shrink after a well-predicted step
  double grow = 4.0;         ///< μ *= grow after a poorly predicted or shortened step
  double good_ratio = 0.75;  ///< actual/predicted decrease above which a step is well predicted
  double poor_ratio = 0.25;  ///< ... below which it is poorly predicted
};

class AdaptiveDamping {
 public:
  explicit AdaptiveDamping(const DampingRule& rule = {}) : rule_(rule), factor_(rule.initial) {}

  double factor() const { return factor_; }

  /// Back to the initial factor (a new solver run from another point).
  void reset() { factor_ = rule_.initial; }

  /// Like a trust region: μ grows after a poorly predicted step or one the line search had to
  /// cut back (`shortened`: the model's full step was not acceptable), and shrinks after a
  /// well-predicted one. `ratio` = actual / predicted decrease of the objective along the step
  /// taken, the model being the damped one the step was computed with.
  /// A step stopped short by the fraction-to-the-boundary rule (a slack nearing its bound) is
  /// judged like any other: most late steps stop at an active keyframe bound, and sparing them
  /// from shrinking μ cost iterations (docs/optimizer.md, "Measurement history").
  void update(double ratio, bool shortened) {
    if (shortened || !(ratio >= rule_.poor_ratio))
      factor_ = std::min(rule_.maximum, factor_ * rule_.grow);
    else if (ratio > rule_.good_ratio)
      factor_ = std::max(rule_.minimum, factor_ / rule_.shrink);
  }

 private:
  DampingRule rule_;
  double factor_;
};

}  // namespace saltus
