#include "saltus/optim/trajectory_layout.h"

#include <algorithm>
#include <stdexcept>

namespace saltus {

void TrajectoryLayout::set_subdivisions(const std::vector<int>& spans_per_interval) {
  if (static_cast<int>(spans_per_interval.size()) != keyframe_count - 1)
    throw std::invalid_argument("one subdivision per keyframe interval is needed");
  keyframe_breakpoint.assign(1, 0);
  for (int k : spans_per_interval) {
    if (k < 1) throw std::invalid_argument("every keyframe interval needs at least one span");
    keyframe_breakpoint.push_back(keyframe_breakpoint.back() + k);
  }
}

std::vector<int> TrajectoryLayout::subdivisions() const {
  std::vector<int> out;
  for (std::size_t i = 0; i + 1 < keyframe_breakpoint.size(); ++i)
    out.push_back(keyframe_breakpoint[i + 1] - keyframe_breakpoint[i]);
  return out;
}

TrajectoryLayout::KnotDependence TrajectoryLayout::knot_dependence(int knot) const {
  // Breakpoint m = knot − 3, clamped to [0, M] for the repeated end knots.
  const int m = std::clamp(knot - 3, 0, keyframe_breakpoint.back());
  KnotDependence d;
  d.left =
      static_cast<int>(std::upper_bound(keyframe_breakpoint.begin(), keyframe_breakpoint.end(), m) -
                       keyframe_breakpoint.begin()) -
      1;
  d.left = std::min(d.left, keyframe_count - 2);
  const int first = keyframe_breakpoint[d.left];
  d.weight = static_cast<double>(m - first) / (keyframe_breakpoint[d.left + 1] - first);
  return d;
}

std::vector<double> keyframe_times_from(const TrajectoryLayout& layout,
                                        const TrajectoryReference& reference, const double* x) {
  std::vector<double> times = reference.keyframe_times;
  for (int i = 0; i < layout.keyframe_count; ++i) {
    const int v = layout.time_variable(i);
    if (v >= 0) times[i] = x[v];
  }
  return times;
}

Trajectory<double> trajectory_from(const TrajectoryLayout& layout,
                                   const TrajectoryReference& reference, const double* x) {
  const std::vector<double> times = keyframe_times_from(layout, reference, x);
  Trajectory<double> t;
  t.knots = clamped_cubic_knots(refine_breakpoints(times, layout.subdivisions()));
  const int n = layout.control_count();
  std::vector<Eigen::Vector3d> root(n);
  for (int j = 0; j < n; ++j)
    for (int d = 0; d < 3; ++d)
      root[j][d] = x[layout.control_variable(0, j, d)];
  t.root_translation = VectorSpline<double>(t.knots, root);
  for (int k = 0; k < layout.segment_count; ++k) {
    std::vector<Eigen::Quaterniond> control(n);
    for (int j = 0; j < n; ++j) {
      Eigen::Vector3d delta;
      for (int d = 0; d < 3; ++d)
        delta[d] = x[layout.control_variable(k + 1, j, d)];
      control[j] = reference.joint_control[k][j] * quat_exp(delta);
    }
    t.rotations.emplace_back(t.knots, control);
  }
  return t;
}

std::vector<double> variables_from(const TrajectoryLayout& layout,
                                   const TrajectoryReference& reference,
                                   const Trajectory<double>& trajectory,
                                   const std::vector<double>& keyframe_times) {
  std::vector<double> x(layout.size(), 0.0);
  const int n = layout.control_count();
  for (int j = 0; j < n; ++j) {
    for (int d = 0; d < 3; ++d)
      x[layout.control_variable(0, j, d)] = trajectory.root_translation.control()[j][d];
    for (int k = 0; k < layout.segment_count; ++k) {
      const Eigen::Quaterniond relative =
          reference.joint_control[k][j].conjugate() * trajectory.rotations[k].control()[j];
      // q = q̄·exp(δ) ⇔ δ = log(q̄⁻¹q). log does not fold the sign, so exp(δ) reproduces q
      // exactly, sign included (the sign of a control decides which way its span turns).
      const Eigen::Vector3d delta = quat_log(relative);
      for (int d = 0; d < 3; ++d)
        x[layout.control_variable(k + 1, j, d)] = delta[d];
    }
  }
  for (int i = 0; i < layout.keyframe_count; ++i) {
    const int v = layout.time_variable(i);
    if (v >= 0) x[v] = keyframe_times[i];
  }
  return x;
}

}  // namespace saltus
