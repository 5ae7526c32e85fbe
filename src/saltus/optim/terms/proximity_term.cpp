#include "saltus/optim/terms/proximity_term.h"

#include <cmath>

namespace saltus {

ProximityTerm::ProximityTerm(const TrajectoryLayout& layout, double weight)
    : layout_(layout), weight_(weight) {}

double ProximityTerm::value(NlpEvaluations& at) {
  const double* x = at.x();
  double penalty = 0.0;
  for (int v = 0; v < layout_.control_variable_count(); ++v)
    if (is_joint(v)) penalty += weight_ * x[v] * x[v];
  return penalty;
}

void ProximityTerm::add_gradient(NlpEvaluations& at, double* gradient) {
  const double* x = at.x();
  for (int v = 0; v < layout_.control_variable_count(); ++v)
    if (is_joint(v)) gradient[v] += 2.0 * weight_ * x[v];
}

void ProximityTerm::add_curvature(NlpEvaluations&, double factor, const HessianBand& band,
                                  double* values) {
  for (int v = 0; v < layout_.control_variable_count(); ++v)
    if (is_joint(v)) values[band.index(v, v)] += factor * (2.0 * weight_);
}

std::vector<double> ProximityTerm::residuals(NlpEvaluations& at) {
  std::vector<double> r;
  for (int v = 0; v < layout_.control_variable_count(); ++v)
    if (is_joint(v)) r.push_back(std::sqrt(weight_) * at.x()[v]);
  return r;
}

}  // namespace saltus
