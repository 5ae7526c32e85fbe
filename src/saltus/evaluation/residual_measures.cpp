#include "saltus/evaluation/residual_measures.h"

#include "saltus/base/constants.h"

namespace saltus {

double force_magnitude(const Vector6d& wrench) {
  return wrench.head<3>().norm();
}

double moment_magnitude(const Vector6d& wrench) {
  return wrench.tail<3>().norm();
}

std::vector<double> root_force_magnitudes(const std::vector<SampleRecord>& samples) {
  std::vector<double> out;
  out.reserve(samples.size());
  for (const SampleRecord& s : samples)
    out.push_back(force_magnitude(s.root_wrench));
  return out;
}

std::vector<double> root_moment_magnitudes(const std::vector<SampleRecord>& samples) {
  std::vector<double> out;
  out.reserve(samples.size());
  for (const SampleRecord& s : samples)
    out.push_back(moment_magnitude(s.root_wrench));
  return out;
}

double body_weight(const BodyModel& model) {
  return model.total_mass() * gravity().norm();
}

double percent_of_body_weight(double force_N, const BodyModel& model) {
  const double weight = body_weight(model);
  return weight > 0.0 ? 100.0 * force_N / weight : 0.0;
}

}  // namespace saltus
