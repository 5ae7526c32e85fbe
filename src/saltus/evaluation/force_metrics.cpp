#include "saltus/evaluation/force_metrics.h"

#include <algorithm>
#include <cmath>

#include "saltus/dynamics/inverse_dynamics.h"

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

DenseCheck dense_check(const BodyModel& model, const Trajectory<double>& trajectory,
                       int min_points) {
  DenseCheck check;
  const std::vector<double>& knots = trajectory.knots;
  const double duration = trajectory.duration();
  if (!(duration > 0)) return check;
  DynamicsData<double> data(model);
  BodyState<double> state(model.size());
  check.joint_peaks.assign(model.size(), JointLoadPeak{});
  double sum_force = 0.0, sum_moment = 0.0;
  for (std::size_t s = 3; s + 4 < knots.size(); ++s) {
    const double start = knots[s], end = knots[s + 1];
    if (!(end > start)) continue;
    // An even number of intervals (Simpson), at least kCheckPointsPerSpan, and the span's share
    // of min_points.
    int intervals = std::max({kCheckPointsPerSpan,
                              static_cast<int>(std::ceil(min_points * (end - start) / duration)),
                              static_cast<int>(std::ceil((end - start) / kCheckMaxSpacing))});
    intervals += intervals % 2;
    const double h = (end - start) / intervals;
    double span_force = 0.0, span_moment = 0.0;
    for (int i = 0; i <= intervals; ++i) {
      const double t = i == intervals ? end : start + i * h;
      // Evaluate on this span (its right end as the left limit), whatever rounding says.
      trajectory.sample_on_span(static_cast<int>(s), t, state);
      inverse_dynamics(model, data, state);
      const Vector6d f = root_wrench_force_first(data);
      const double weight = (i == 0 || i == intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      const double force2 = f.head<3>().squaredNorm(), moment2 = f.tail<3>().squaredNorm();
      span_force += weight * force2;
      span_moment += weight * moment2;
      check.metrics.max_force_N = std::max(check.metrics.max_force_N, std::sqrt(force2));
      check.metrics.max_moment_Nm = std::max(check.metrics.max_moment_Nm, std::sqrt(moment2));
      for (int k = 0; k < model.size(); ++k) {
        const Vector6d w = joint_wrench_force_first(data, k);
        JointLoadPeak& peak = check.joint_peaks[k];
        const double force = w.head<3>().norm(), moment = w.tail<3>().norm();
        if (force > peak.force_N) peak.force_N = force, peak.force_time_s = t;
        if (moment > peak.moment_Nm) peak.moment_Nm = moment, peak.moment_time_s = t;
      }
      ++check.points;
    }
    span_force *= h / 3.0;
    span_moment *= h / 3.0;
    sum_force += span_force;
    sum_moment += span_moment;
    check.span_start.push_back(start);
    check.span_end.push_back(end);
    check.span_integral.push_back(span_force + span_moment);
  }
  ForceMetrics& m = check.metrics;
  m.objective = (sum_force + sum_moment) / duration;
  m.avg_root_force = std::sqrt(m.objective / 6.0);
  m.rms_force_N = std::sqrt(sum_force / duration);
  m.rms_moment_Nm = std::sqrt(sum_moment / duration);
  return check;
}

}  // namespace saltus
