#pragma once
/// @file
/// The root wrench F1..F6 at a time sample and its exact derivatives with respect to the
/// optimiser's variables, in two stages:
///
///  1. spline stage — each curve's state at t (rotation tangent η, ω, α for a joint; ṗ, p̈ for the
///     root translation) differentiated with respect to the curve's 4 active control points (12
///     directions) and the keyframe times that move the span's knots (<= 8 directions): the
///     span's relative logs and the basis by forward-mode AD, once per span and per sample, the
///     joint's span evaluation from them in closed form (math/quaternion_span_derivatives.h);
///  2. dynamics stage — F differentiated with respect to every joint's state tangent (9 per
///     segment) and the root's ṗ, p̈ in closed form, from one double inverse dynamics pass
///     (dynamics/root_wrench_state_jacobian.h). This replaced AD through the whole inverse
///     dynamics (9 directions per segment through every segment), which took most of the time.
///
/// The chain rule joins them. This keeps the AD pass small (the spline stage never sees the
/// dynamics, the dynamics stage never sees the controls) and the result exactly sparse: a sample
/// touches one contiguous block of control variables (4 controls × all curves) and a few times.

#include <array>
#include <memory>

#include "saltus/body/body_model.h"
#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/optim/trajectory_layout.h"

namespace saltus {

using Vector6d = Eigen::Matrix<double, 6, 1>;

/// Maximum number of keyframe times one span's knots depend on (8 knots, K = 1).
inline constexpr int kMaxLocalTimes = 8;

/// Derivatives of a vector-valued quantity at one time with respect to the local variables.
template <int Rows>
struct LocalJacobian {
  Eigen::Matrix<double, Rows, 1> value;
  int first_control_variable = 0;  ///< x index of the block's first column
  /// Rows × (4·curve_block): columns follow the layout's control-major order.
  Eigen::Matrix<double, Rows, Eigen::Dynamic> control;
  int time_count = 0;
  std::array<int, kMaxLocalTimes> time_variable{};  ///< x indices of the time columns
  Eigen::Matrix<double, Rows, kMaxLocalTimes> time;
};

class RootWrenchDerivatives {
 public:
  RootWrenchDerivatives(const BodyModel& model, const TrajectoryLayout& layout,
                        const TrajectoryReference& reference);
  ~RootWrenchDerivatives();

  /// Loads a new point x (knots and control points); every query below uses it.
  void set_variables(const double* x);

  /// Root wrench at t (force then moment, root frame): value only.
  Vector6d wrench(double t);
  /// Root wrench at t and its derivatives (t fixed while the knots move).
  void wrench_jacobian(double t, LocalJacobian<6>& out);

  /// The same at the point ξ ∈ [0, 1] of knot span `span`, t = k_s + ξ·(k_{s+1} − k_s): a
  /// quadrature node that moves with the knots, so its derivatives with respect to the keyframe
  /// times include the node's own motion. `span_length_rate` receives d(k_{s+1} − k_s)/dτ for
  /// the time slots of `out`.
  Vector6d wrench_on_span(int span, double xi);
  void wrench_jacobian_on_span(int span, double xi, LocalJacobian<6>& out,
                               Eigen::Matrix<double, 1, kMaxLocalTimes>& span_length_rate);

  /// Every non-root joint's moment at the point ξ of knot span `span` (joint_moment_rows rows:
  /// segment 1's n, then segment 2's, ...; the parent's moment on the child's subtree, child
  /// frame, about the joint centre, N·m), values only or with their derivatives (the node moving
  /// with the knots, as wrench_jacobian_on_span).
  Eigen::VectorXd joint_moments_on_span(int span, double xi);
  void joint_moments_jacobian_on_span(int span, double xi, LocalJacobian<Eigen::Dynamic>& out);
  /// The same with each joint's force after its moment: six rows per joint (n_j, then f_j, the
  /// parent's force on the child's subtree, child frame, N).
  Eigen::VectorXd joint_wrenches_on_span(int span, double xi);
  void joint_wrenches_jacobian_on_span(int span, double xi, LocalJacobian<Eigen::Dynamic>& out);
  int joint_moment_rows() const { return 3 * (layout_.segment_count - 1); }

  /// Values only, in plain double (what the constraints need at a line-search trial point):
  /// the root translation and segment `segment`'s rotation (w, x, y, z) at keyframe i's time.
  /// Equal to the `value` members of the derivative versions below.
  Eigen::Vector3d keyframe_translation_value(int keyframe) const;
  Eigen::Vector4d keyframe_rotation_value(int keyframe, int segment) const;

  /// Root translation at keyframe i's (current) time and its derivatives.
  void keyframe_translation(int keyframe, LocalJacobian<3>& out);
  /// Segment `segment`'s rotation at keyframe i's time as 4 coefficients (w, x, y, z) and their
  /// derivatives.
  void keyframe_rotation(int keyframe, int segment, LocalJacobian<4>& out);

  const std::vector<double>& knots() const { return knots_; }

 private:
  struct Workspace;
  /// Every non-root joint's first `rows_per_joint` rows of its wrench (3: the moment, 6: moment
  /// and force), values only or with their derivatives.
  Eigen::VectorXd joint_loads_on_span(int span, double xi, int rows_per_joint);
  template <int RowsPerJoint>
  void joint_loads_jacobian_on_span(int span, double xi, LocalJacobian<Eigen::Dynamic>& out);
  /// Seeds the knots and builds the AD basis at keyframe i's time into the workspace, once per
  /// keyframe and point (every segment's rotation at that keyframe shares it).
  void prepare_keyframe(int keyframe);
  /// Root wrench at t evaluated on `span` (values only).
  Vector6d wrench_at(int span, double t);
  /// Root wrench and derivatives at the AD time t on `span` (knots already seeded for it).
  template <typename Time>
  void wrench_jacobian_seeded(int span, const Time& t, LocalJacobian<6>& out);
  /// Stage 1 (the file comment) at the AD time t on `span`: every curve's state into the
  /// workspace's state, with its derivatives; then inverse dynamics and the root wrench's sweep.
  template <typename Time>
  void seed_state(int span, const Time& t);
  const BodyModel& model_;
  TrajectoryLayout layout_;
  TrajectoryReference reference_;
  std::vector<int> subdivisions_;  ///< knot spans per keyframe interval
  std::vector<double> knots_;
  std::vector<double> keyframe_times_;
  std::vector<Eigen::Vector3d> root_control_;                   ///< [control]
  std::vector<std::vector<Eigen::Quaterniond>> joint_control_;  ///< [segment][control]
  std::vector<std::vector<Eigen::Vector3d>> joint_delta_;       ///< [segment][control]
  std::unique_ptr<Workspace> work_;
};

}  // namespace saltus
