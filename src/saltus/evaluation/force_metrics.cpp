#include "saltus/evaluation/force_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

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

namespace {

/// One knot span's integrand, |F_1..3|² and |F_4..6|², at equally spaced points.
struct SpanGrid {
  int span = 0;
  double start = 0.0, end = 0.0;
  std::vector<double> force2, moment2;
};

/// Simpson's rule over equally spaced values (an even number of intervals).
double simpson(const std::vector<double>& values, double h) {
  const std::size_t last = values.size() - 1;
  double sum = values.front() + values.back();
  for (std::size_t i = 1; i < last; ++i)
    sum += values[i] * (i % 2 ? 4.0 : 2.0);
  return sum * h / 3.0;
}

}  // namespace

DenseCheck dense_check(const BodyModel& model, const Trajectory<double>& trajectory,
                       int min_points) {
  DenseCheck check;
  const std::vector<double>& knots = trajectory.knots;
  const double duration = trajectory.duration();
  if (!(duration > 0)) return check;
  DynamicsData<double> data(model);
  BodyState<double> state(model.size());
  check.joint_peaks.assign(model.size(), JointLoadPeak{});
  check.strength_peaks.assign(model.size(), JointStrengthPeak{});
  const AthleteStrength strength = athlete_strength(model);
  // The root wrench's squares at t on span s (its right end as the left limit, whatever rounding
  // says), and every peak over the points seen.
  auto evaluate_at = [&](const SpanGrid& grid, double t, double& force2, double& moment2) {
    trajectory.sample_on_span(grid.span, t, state);
    inverse_dynamics(model, data, state);
    const Vector6d f = root_wrench_force_first(data);
    force2 = f.head<3>().squaredNorm();
    moment2 = f.tail<3>().squaredNorm();
    check.metrics.max_force_N = std::max(check.metrics.max_force_N, std::sqrt(force2));
    check.metrics.max_moment_Nm = std::max(check.metrics.max_moment_Nm, std::sqrt(moment2));
    for (int k = 0; k < model.size(); ++k) {
      const Vector6d w = joint_wrench_force_first(data, k);
      JointLoadPeak& peak = check.joint_peaks[k];
      const double force = w.head<3>().norm(), moment = w.tail<3>().norm();
      if (force > peak.force_N) peak.force_N = force, peak.force_time_s = t;
      if (moment > peak.moment_Nm) peak.moment_Nm = moment, peak.moment_time_s = t;
      if (k == 0) continue;
      const StrengthDemand demand = strength_demand(strength, k, state.joints[k], w.tail<3>());
      JointStrengthPeak& strongest = check.strength_peaks[k];
      if (demand.coordinate >= 0 && (strongest.coordinate < 0 || demand.share > strongest.share))
        static_cast<StrengthDemand&>(strongest) = demand, strongest.time_s = t;
    }
    ++check.points;
  };
  auto point_time = [](const SpanGrid& grid, int i) {
    const int intervals = static_cast<int>(grid.force2.size()) - 1;
    return i == intervals ? grid.end : grid.start + i * (grid.end - grid.start) / intervals;
  };

  // The first grid: an even number of intervals per span (Simpson), at least
  // kCheckPointsPerSpan, the span's share of min_points, and kCheckMaxSpacing apart.
  std::vector<SpanGrid> grids;
  for (std::size_t s = 3; s + 4 < knots.size(); ++s) {
    SpanGrid grid;
    grid.span = static_cast<int>(s);
    grid.start = knots[s];
    grid.end = knots[s + 1];
    if (!(grid.end > grid.start)) continue;
    int intervals =
        std::max({kCheckPointsPerSpan,
                  static_cast<int>(std::ceil(min_points * (grid.end - grid.start) / duration)),
                  static_cast<int>(std::ceil((grid.end - grid.start) / kCheckMaxSpacing))});
    intervals += intervals % 2;
    grid.force2.resize(intervals + 1);
    grid.moment2.resize(intervals + 1);
    for (int i = 0; i <= intervals; ++i)
      evaluate_at(grid, point_time(grid, i), grid.force2[i], grid.moment2[i]);
    grids.push_back(std::move(grid));
  }
  auto total = [&] {
    double sum = 0.0;
    for (const SpanGrid& g : grids) {
      const double h = (g.end - g.start) / (static_cast<double>(g.force2.size()) - 1);
      sum += simpson(g.force2, h) + simpson(g.moment2, h);
    }
    return sum / duration;
  };

  // Halve every spacing until J changes by less than kCheckRelativeChange (or kCheckObjectiveFloor,
  // for motions that are all but exact): a residual left by an optimiser can wiggle between its
  // quadrature nodes faster than the first grid resolves.
  double objective = total();
  for (int halving = 1; halving <= kCheckMaxHalvings; ++halving) {
    for (SpanGrid& g : grids) {
      const std::size_t intervals = g.force2.size() - 1;
      std::vector<double> force2(2 * intervals + 1), moment2(2 * intervals + 1);
      for (std::size_t i = 0; i <= intervals; ++i) {
        force2[2 * i] = g.force2[i];
        moment2[2 * i] = g.moment2[i];
      }
      g.force2.swap(force2);
      g.moment2.swap(moment2);
      for (std::size_t i = 1; i < 2 * intervals; i += 2)
        evaluate_at(g, point_time(g, static_cast<int>(i)), g.force2[i], g.moment2[i]);
    }
    const double finer = total();
    check.halvings = halving;
    check.last_halving_change = std::abs(finer - objective);
    objective = finer;
    if (check.last_halving_change <= kCheckRelativeChange * objective + kCheckObjectiveFloor) {
      check.converged = true;
      break;
    }
  }

  double sum_force = 0.0, sum_moment = 0.0;
  for (const SpanGrid& g : grids) {
    const double h = (g.end - g.start) / (static_cast<double>(g.force2.size()) - 1);
    const double span_force = simpson(g.force2, h), span_moment = simpson(g.moment2, h);
    sum_force += span_force;
    sum_moment += span_moment;
    check.span_start.push_back(g.start);
    check.span_end.push_back(g.end);
    check.span_integral.push_back(span_force + span_moment);
  }
  ForceMetrics& m = check.metrics;
  m.objective = (sum_force + sum_moment) / duration;
  m.avg_root_force = std::sqrt(m.objective / 6.0);
  m.rms_force_N = std::sqrt(sum_force / duration);
  m.rms_moment_Nm = std::sqrt(sum_moment / duration);
  return check;
}

std::vector<double> residual_per_interval(const DenseCheck& check,
                                          const std::vector<double>& keyframe_times) {
  std::vector<double> out(keyframe_times.size() - 1, 0.0);
  for (std::size_t s = 0; s < check.span_integral.size(); ++s) {
    const double middle = 0.5 * (check.span_start[s] + check.span_end[s]);
    const auto it = std::upper_bound(keyframe_times.begin(), keyframe_times.end(), middle);
    const std::size_t interval =
        std::clamp<std::ptrdiff_t>(it - keyframe_times.begin() - 1, 0, out.size() - 1);
    out[interval] += check.span_integral[s];
  }
  return out;
}

std::vector<double> residual_shares(const DenseCheck& check,
                                    const std::vector<double>& keyframe_times) {
  std::vector<double> shares = residual_per_interval(check, keyframe_times);
  double total = 0.0;
  for (const double r : shares)
    total += r;
  for (double& r : shares)
    r = total > 0 ? r / total : 0.0;
  return shares;
}

std::string residual_location_words(const std::vector<double>& shares,
                                    const std::vector<double>& keyframe_times) {
  if (shares.empty() || keyframe_times.size() != shares.size() + 1) return {};
  const std::size_t i =
      static_cast<std::size_t>(std::max_element(shares.begin(), shares.end()) - shares.begin());
  char words[200];
  std::snprintf(
      words, sizeof words,
      "the largest share of the root force left is between keyframes %zu and %zu (%.2f-%.2f s): "
      "%.0f %% of its integral",
      i + 1, i + 2, keyframe_times[i], keyframe_times[i + 1], 100.0 * shares[i]);
  return words;
}

}  // namespace saltus
