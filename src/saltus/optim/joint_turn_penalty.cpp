#include "saltus/optim/joint_turn_penalty.h"

#include <algorithm>
#include <stdexcept>

#include "saltus/math/quaternion.h"

namespace saltus {

namespace {
using TurnAD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 6, 1>>;
}  // namespace

JointTurnPenalty::JointTurnPenalty(const TrajectoryLayout& layout,
                                   const TrajectoryReference& reference, double limit,
                                   double weight)
    : layout_(layout), reference_control_(reference.joint_control), weight_(weight) {
  if (!(limit > 0)) throw std::invalid_argument("the joint turn limit must be positive");
  if (!(weight > 0)) throw std::invalid_argument("the joint turn weight must be positive");
  limit_.assign(layout.segment_count, std::vector<double>(layout.control_count(), limit));
  for (int k = 0; k < layout.segment_count; ++k)
    for (int j = 1; j < layout.control_count(); ++j)
      limit_[k][j] =
          std::max(limit, control_turn(reference_control_[k][j - 1], reference_control_[k][j]));
}

double JointTurnPenalty::evaluate(const double* x, double* gradient,
                                  std::vector<ActivePair>* active) const {
  if (active) active->clear();
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

}  // namespace saltus
