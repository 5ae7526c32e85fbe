#include "saltus/evaluation/force_metrics.h"

#include <algorithm>
#include <cmath>

namespace saltus {

ForceMetrics force_metrics(const std::vector<SampleRecord>& samples) {
  ForceMetrics m;
  if (samples.size() < 2) return m;
  const double duration = samples.back().time - samples.front().time;
  double sum_all = 0, sum_force = 0, sum_moment = 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const Vector6d& f = samples[k].root_wrench;
    const double force2 = f.head<3>().squaredNorm();
    const double moment2 = f.tail<3>().squaredNorm();
    m.max_force_N = std::max(m.max_force_N, std::sqrt(force2));
    m.max_moment_Nm = std::max(m.max_moment_Nm, std::sqrt(moment2));
    if (k + 1 < samples.size()) {
      const double dt = samples[k + 1].time - samples[k].time;
      const Vector6d& g = samples[k + 1].root_wrench;
      const double next_force2 = g.head<3>().squaredNorm();
      const double next_moment2 = g.tail<3>().squaredNorm();
      sum_force += 0.5 * dt * (force2 + next_force2);
      sum_moment += 0.5 * dt * (moment2 + next_moment2);
    }
  }
  sum_all = sum_force + sum_moment;
  m.objective = sum_all / duration;
  m.avg_root_force = std::sqrt(m.objective / 6.0);
  m.rms_force_N = std::sqrt(sum_force / duration);
  m.rms_moment_Nm = std::sqrt(sum_moment / duration);
  return m;
}

}  // namespace saltus
