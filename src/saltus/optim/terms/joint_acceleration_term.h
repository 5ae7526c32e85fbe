#pragma once
/// @file
/// Keeps the joints' angular accelerations near the motion the optimiser started from, in units
/// of the joint moments they ask of the athlete: w·(1/T)∫ Σ_k I_k²·|δ̈_k(t)|² dt over every
/// non-root joint k, where δ_k(t) = Σ_c δ_{k,c}·B_c(t) is the joint's deviation curve built from
/// its control-point tangents δ (rad) and I_k the largest principal moment of inertia of the
/// segments the joint moves, about the joint, standing (kg·m²), at least kMinJointInertia:
/// I_k·δ̈_k is the change in the joint moment a rigid subtree would need (N·m), and w = 1 weighs
/// it like a root moment. The floor keeps light limbs from becoming the cheap way to buy root
/// force (their joints' own loads rise instead: measured in docs/optimizer.md, "Joint loads").
///
/// Why. The root force hardly depends on a light limb's path, so the relaxed optimum used to buy
/// the last newtons at the ends of the flight with kicks: a knee flexing 20° and back in the
/// first 0.02 s, 371 N·m where the input needed 27 N·m (docs/optimizer.md, "Joint loads"). The
/// proximity term (ProximityTerm) cannot see that: it weighs a control's tangent alike on a span
/// of 0.02 s and of 0.3 s, while the acceleration grows like 1/span². This term weighs what a
/// joint pays.
///
/// The deviation curve is the linearisation of the quaternion spline in its tangent coordinates
/// and the spans are the starting knots', so the term is a fixed convex quadratic in δ: its
/// residuals are exact on each span by 2-point Gauss rule (δ̈ is linear on a span), its
/// Gauss–Newton curvature is its Hessian, and every residual touches 4 consecutive controls of
/// one joint coordinate, inside the Hessian's band.

#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/optim/terms/objective_term.h"

namespace saltus {

/// kg·m²: the least inertia a joint's acceleration is weighed with (a forearm's is ~0.05).
inline constexpr double kMinJointInertia = 0.5;

/// The largest principal moment of inertia (kg·m²) of the segments that segment `segment`'s
/// joint moves (it and everything below it), about the joint centre, with every joint at
/// identity (standing).
double joint_subtree_inertia(const BodyModel& model, int segment);

class JointAccelerationTerm : public ObjectiveTerm {
 public:
  /// @param knots   the clamped knot vector the trajectory starts on (its spans weigh δ̈)
  /// @param weight  w, dimensionless (the objective's N² per (N·m)² of joint moment)
  JointAccelerationTerm(const TrajectoryLayout& layout, const BodyModel& model,
                        const std::vector<double>& knots, double weight);

  std::string name() const override { return "joint acceleration"; }
  double value(NlpEvaluations& at) override;
  void add_gradient(NlpEvaluations& at, double* gradient) override;
  void add_curvature(NlpEvaluations& at, double factor, const HessianBand& band,
                     double* values) override;
  std::vector<double> residuals(NlpEvaluations& at) override;

 private:
  /// One Gauss point of one span: the weighted B'' of its 4 active controls.
  struct Point {
    int first_control = 0;
    double coefficient[4] = {0, 0, 0, 0};  ///< √(ω·h/T)·B''_{c+j}(t)
  };
  /// r for every point, joint and coordinate, in that order; `gradient` += 2·r·∂r/∂x if given.
  std::vector<double> evaluate(const double* x, double* gradient) const;

  TrajectoryLayout layout_;
  std::vector<Point> points_;
  std::vector<double> joint_scale_;  ///< per segment: √w·I_k (0 for the root)
};

}  // namespace saltus
