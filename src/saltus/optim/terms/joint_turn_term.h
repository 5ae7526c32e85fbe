#pragma once
/// @file
/// A soft limit on how far a joint may turn between two consecutive control points of its
/// quaternion spline: ρ·Σ (θ − L)₊² over every non-root joint and pair of controls, where θ is
/// the turn from control j−1 to control j (control_turn) and L = max(limit, the interpolation's
/// own turn there), so the starting point is never penalised.
///
/// Why. A joint rotation is the child segment relative to its parent, and no human joint turns
/// through half a revolution between two control points. But the root force hardly depends on
/// light segments, and at the paper's resolution (K = 1, controls 0.15-0.3 s apart) the relaxed
/// optimum without this limit spun forearms, feet and shanks by nearly a full turn between two
/// controls. At 2π the spline's relative log has its branch point: the gradient blows up there,
/// and runs that reached it failed.
///
/// A penalty, not constraint rows: the residual √ρ·(θ − L)₊ joins the objective's sum of squares
/// with a Gauss–Newton Hessian 2ρ·∇θ∇θᵀ on the two controls' 6 tangent coordinates, which lie
/// inside the Hessian's band (hard rows ⟨c_{j−1}, c_j⟩ >= cos(L/2) cost more iterations).
/// Measurements: docs/optimizer.md, "Measurement history" (Joint-turn limit).

#include <array>
#include <vector>

#include <Eigen/Geometry>

#include "saltus/optim/terms/objective_term.h"

namespace saltus {

class JointTurnTerm : public ObjectiveTerm {
 public:
  /// A pair of controls past its limit: the 6 tangent coordinates (control j−1's, then j's)
  /// and the gradient of the turn with respect to them.
  struct ActivePair {
    std::array<int, 6> variables{};
    Eigen::Matrix<double, 6, 1> turn_gradient;
  };

  /// @param limit   L's floor, rad (> 0)
  /// @param weight  ρ, in the objective's units per rad² (N²/rad² for the relaxed model)
  JointTurnTerm(const TrajectoryLayout& layout, const TrajectoryReference& reference, double limit,
                double weight);

  std::string name() const override { return "joint turn"; }
  double value(NlpEvaluations& at) override { return evaluate(at.x(), nullptr, nullptr); }
  void add_gradient(NlpEvaluations& at, double* gradient) override {
    evaluate(at.x(), gradient, nullptr);
  }
  /// 2ρ·∇θ∇θᵀ per active pair: both controls are neighbours on one curve, inside the band.
  void add_curvature(NlpEvaluations& at, double factor, const HessianBand& band,
                     double* values) override;
  /// √ρ·(θ − L)₊ for every non-root joint and pair of consecutive controls.
  std::vector<double> residuals(NlpEvaluations& at) override;

  /// The penalty at x. Adds its gradient to `gradient` and lists the active pairs (for the
  /// Hessian) when given; `excess` receives (θ − L)₊ of every pair when given.
  double evaluate(const double* x, double* gradient, std::vector<ActivePair>* active,
                  std::vector<double>* excess = nullptr) const;

  double weight() const { return weight_; }

 private:
  TrajectoryLayout layout_;
  std::vector<std::vector<Eigen::Quaterniond>> reference_control_;  ///< q̄, [segment][control]
  double weight_;
  std::vector<std::vector<double>> limit_;  ///< [segment][control j], for the pair (j−1, j)
};

}  // namespace saltus
