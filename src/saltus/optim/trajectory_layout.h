#pragma once
/// @file
/// How the optimiser's variable vector x maps onto a trajectory (docs/method.md).
///
/// Curves: 0 = root translation B(t) (3 coordinates of each control point, m), 1 + k = segment
/// k's quaternion spline (3 local tangent coordinates δ of each control point, q_j = q̄_j·exp(δ_j),
/// around the reference control points q̄ of the interpolation). Interior keyframe times follow
/// (s) when timing is optimised; the first and last times are fixed.
///
/// Ordering is control-major — all curves' control j, then control j+1 — so that the variables
/// a time sample touches (4 consecutive controls) form a contiguous block, and the Gauss-Newton
/// Hessian is a band whose entries can be indexed in O(1).

#include <vector>

#include "saltus/math/bspline_basis.h"
#include "saltus/motion/trajectory.h"

namespace saltus {

struct TrajectoryLayout {
  int segment_count = 0;  ///< joints (quaternion curves)
  int keyframe_count = 0;
  bool optimize_timing = true;
  /// Breakpoint index of each keyframe: 0, K_0, K_0 + K_1, ... where K_i is how many knot spans
  /// keyframe interval i is split into (set_subdivisions).
  std::vector<int> keyframe_breakpoint;

  /// K_i knot spans in keyframe interval i, equal parts (1 = knots at the keyframes only).
  void set_subdivisions(const std::vector<int>& spans_per_interval);
  std::vector<int> subdivisions() const;

  int curve_count() const { return segment_count + 1; }
  /// Spline control points per curve: ΣK_i + 3.
  int control_count() const { return keyframe_breakpoint.back() + 3; }
  int curve_block() const { return 3 * curve_count(); }
  int control_variable_count() const { return control_count() * curve_block(); }
  int time_variable_count() const { return optimize_timing ? keyframe_count - 2 : 0; }
  int size() const { return control_variable_count() + time_variable_count(); }

  /// Index of coordinate `dim` of control `control` of curve `curve`.
  int control_variable(int curve, int control, int dim) const {
    return control * curve_block() + 3 * curve + dim;
  }
  /// Index of interior keyframe i's time (1 <= i <= keyframes − 2), or −1 if it is fixed.
  int time_variable(int keyframe) const {
    if (!optimize_timing || keyframe <= 0 || keyframe >= keyframe_count - 1) return -1;
    return control_variable_count() + keyframe - 1;
  }

  /// Position of knot `knot` (index into the clamped knot vector) as an affine function of the
  /// keyframe times: knot = (1 − weight)·t[left] + weight·t[left + 1].
  struct KnotDependence {
    int left = 0;
    double weight = 0.0;
  };
  KnotDependence knot_dependence(int knot) const;

  /// The span a keyframe's time lies on, structurally: the knot at keyframe i starts span
  /// 3 + its breakpoint (the last keyframe ends the last span).
  int keyframe_span(int keyframe) const {
    return keyframe == keyframe_count - 1 ? control_count() - 1 : 3 + keyframe_breakpoint[keyframe];
  }
  /// Index of keyframe i's knot in the clamped knot vector.
  int keyframe_knot(int keyframe) const { return 3 + keyframe_breakpoint[keyframe]; }
};

/// The fixed data a layout's variables are relative to.
struct TrajectoryReference {
  std::vector<std::vector<Eigen::Quaterniond>> joint_control;  ///< q̄, [segment][control]
  std::vector<double> keyframe_times;                          ///< times when not optimised
};

/// Keyframe times encoded in x (fixed ones from the reference).
std::vector<double> keyframe_times_from(const TrajectoryLayout& layout,
                                        const TrajectoryReference& reference, const double* x);

/// The trajectory that x describes.
Trajectory<double> trajectory_from(const TrajectoryLayout& layout,
                                   const TrajectoryReference& reference, const double* x);

/// Encodes a trajectory (on the layout's knots) as x relative to `reference`
/// (δ_j = log(q̄_j⁻¹ q_j)) and the given keyframe times.
std::vector<double> variables_from(const TrajectoryLayout& layout,
                                   const TrajectoryReference& reference,
                                   const Trajectory<double>& trajectory,
                                   const std::vector<double>& keyframe_times);

}  // namespace saltus
