#include "saltus/optim/terms/joint_turn_term.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "saltus/math/quaternion.h"

namespace saltus {

namespace {
using TurnAD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 6, 1>>;
}  // namespace

JointTurnTerm::JointTurnTerm(const TrajectoryLayout& layout, const TrajectoryReference& reference,
                             double limit, double weight)
    : layout_(layout), reference_control_(reference.joint_control), weight_(weight) {
  if (!(limit > 0)) throw std::invalid_argument("the joint turn limit must be positive");
  if (!(weight > 0)) throw std::invalid_argument("the joint turn weight must be positive");
  limit_.assign(layout.segment_count, std::vector<double>(layout.control_count(), limit));
  for (int k = 0; k < layout.segment_count; ++k)
    for (int j = 1; j < layout.control_count(); ++j)
      limit_[k][j] =
          std::max(limit, control_turn(reference_control_[k][j - 1], reference_control_[k][j]));
}

double JointTurnTerm::evaluate(const double* x, double* gradient, std::vector<ActivePair>* active,
                               std::vector<double>* excess_of_pair) const {
  if (active) active->clear();
  if (excess_of_pair) excess_of_pair->clear();
  double penalty = 0.0;
  // Segment 0 is the root: the whole body somersaults, so its turns are the skill's own.
  for (int k = 1; k < layout_.segment_count; ++k) {
    const int curve = k + 1;
    auto control = [&](int c) {
      const Eigen::Vector3d delta(x[layout_.control_variable(curve, c, 0)],
                                  x[layout_.control_variable(curve, c, 1)],
                                  x[layout_.control_variable(curve, c, 2)]);
      return Eigen::Quaterniond(reference_control_[k][c] * quat_exp(delta));
    };
    // Each control once: it belongs to the pair before it and the pair after it.
    Eigen::Quaterniond previous = control(0);
    for (int j = 1; j < layout_.control_count(); ++j) {
      const Eigen::Quaterniond current = control(j);
      const double excess = control_turn(previous, current) - limit_[k][j];
      previous = current;
      if (excess_of_pair) excess_of_pair->push_back(std::max(0.0, excess));
      if (excess <= 0) continue;
      penalty += weight_ * excess * excess;
      if (!gradient && !active) continue;
      // The turn's derivative with respect to both controls' tangents (6 directions). Only past
      // the limit (>= π > 0), away from the turn's non-smooth point at 0.
      ActivePair pair;
      Quat<TurnAD> seeded[2];
      for (int side = 0; side < 2; ++side) {
        Vec3<TurnAD> delta;
        for (int d = 0; d < 3; ++d) {
          const int v = layout_.control_variable(curve, j - 1 + side, d);
          pair.variables[3 * side + d] = v;
          delta[d] = TurnAD(x[v], 6, 3 * side + d);
        }
        seeded[side] = reference_control_[k][j - 1 + side].cast<TurnAD>() * quat_exp(delta);
      }
      pair.turn_gradient = control_turn(seeded[0], seeded[1]).derivatives();
      if (gradient)
        for (int i = 0; i < 6; ++i)
          gradient[pair.variables[i]] += 2.0 * weight_ * excess * pair.turn_gradient[i];
      if (active) active->push_back(pair);
    }
  }
  return penalty;
}

void JointTurnTerm::add_curvature(NlpEvaluations& at, double factor, const HessianBand& band,
                                  double* values) {
  std::vector<ActivePair> active;
  evaluate(at.x(), nullptr, &active);
  // Gauss–Newton of ρ·r² with r = θ − L: 2ρ·∇θ∇θᵀ.
  const double scale = 2.0 * factor * weight_;
  for (const ActivePair& pair : active)
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        if (pair.variables[b] <= pair.variables[a])
          values[band.index(pair.variables[a], pair.variables[b])] +=
              scale * pair.turn_gradient[a] * pair.turn_gradient[b];
}

std::vector<double> JointTurnTerm::residuals(NlpEvaluations& at) {
  std::vector<double> excess;
  evaluate(at.x(), nullptr, nullptr, &excess);
  for (double& r : excess)
    r *= std::sqrt(weight_);
  return excess;
}

}  // namespace saltus
