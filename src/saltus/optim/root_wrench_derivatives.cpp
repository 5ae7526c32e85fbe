#include "saltus/optim/root_wrench_derivatives.h"

#include <algorithm>

#include "saltus/dynamics/joint_wrench_state_jacobian.h"
#include "saltus/dynamics/root_wrench_state_jacobian.h"
#include "saltus/math/quaternion_span_derivatives.h"
#include "saltus/math/quaternion_spline.h"
#include "saltus/math/vector_spline.h"

namespace saltus {

namespace {

/// Spline stage: 12 control-tangent directions (control c, coordinate d -> 3c + d) followed by
/// the local keyframe-time slots.
constexpr int kControlDirections = 12;
constexpr int kSplineDirections = kControlDirections + kMaxLocalTimes;
using SplineDerivative = Eigen::Matrix<double, kSplineDirections, 1>;
using SplineAD = Eigen::AutoDiffScalar<SplineDerivative>;

/// Per joint: η (rotation tangent, q = q₀·exp(η)), ω, α. Root translation: ṗ, p̈.
constexpr int kJointStateSize = kJointStateTangentSize;
constexpr int kRootStateSize = 6;

SplineAD spline_variable(double value, int direction) {
  SplineAD a(value);
  a.derivatives()[direction] = 1.0;
  return a;
}

Eigen::Quaterniond quaternion_value(const Quat<SplineAD>& q) {
  return Eigen::Quaterniond(q.w().value(), q.x().value(), q.y().value(), q.z().value());
}

/// A joint curve's span in the form quaternion_span_derivatives consumes: the first control and
/// the relative logs w_j = log(c_{j−1}⁻¹ c_j) with their derivatives along the 4 active control
/// tangents (directions 0..11; the time directions are zero). They do not depend on t, so every
/// sample on the span shares them.
using JointSpanLogs = QuaternionSpanControls<kSplineDirections>;

}  // namespace

struct RootWrenchDerivatives::Workspace {
  explicit Workspace(const BodyModel& model)
      : data(model),
        state(model.size()),
        joint_state_jacobian(model.size()),
        wrench_state(model),
        joint_wrench_state(model),
        span_logs(model.size()) {}

  DynamicsData<double> data;
  BodyState<double> state;
  std::vector<SplineAD> knots_ad;
  int time_count = 0;
  std::array<int, kMaxLocalTimes> time_variable{};
  std::vector<Eigen::Matrix<double, kJointStateSize, kSplineDirections>> joint_state_jacobian;
  Eigen::Matrix<double, kRootStateSize, kSplineDirections> root_state_jacobian;
  RootWrenchStateJacobian wrench_state;
  JointWrenchStateJacobian joint_wrench_state;
  int basis_keyframe = -1;  ///< keyframe whose basis is in keyframe_basis, −1 for none
  /// Span whose joint logs are in span_logs (−1 for none). Samples come in time order, so
  /// caching the last span computes each span's logs once per point.
  int logs_span = -1;
  std::vector<JointSpanLogs> span_logs;  ///< [segment]
  SpanBasis<SplineAD> keyframe_basis;
};

RootWrenchDerivatives::RootWrenchDerivatives(const BodyModel& model, const TrajectoryLayout& layout,
                                             const TrajectoryReference& reference)
    : model_(model),
      layout_(layout),
      reference_(reference),
      subdivisions_(layout.subdivisions()),
      root_control_(layout.control_count()),
      joint_control_(layout.segment_count, std::vector<Eigen::Quaterniond>(layout.control_count())),
      joint_delta_(layout.segment_count, std::vector<Eigen::Vector3d>(layout.control_count())),
      work_(std::make_unique<Workspace>(model)) {}

RootWrenchDerivatives::~RootWrenchDerivatives() = default;

void RootWrenchDerivatives::set_variables(const double* x) {
  work_->basis_keyframe = -1;
  work_->logs_span = -1;
  keyframe_times_ = keyframe_times_from(layout_, reference_, x);
  knots_ = clamped_cubic_knots(refine_breakpoints(keyframe_times_, subdivisions_));
  for (int j = 0; j < layout_.control_count(); ++j) {
    for (int d = 0; d < 3; ++d)
      root_control_[j][d] = x[layout_.control_variable(0, j, d)];
    for (int k = 0; k < layout_.segment_count; ++k) {
      Eigen::Vector3d& delta = joint_delta_[k][j];
      for (int d = 0; d < 3; ++d)
        delta[d] = x[layout_.control_variable(k + 1, j, d)];
      joint_control_[k][j] = reference_.joint_control[k][j] * quat_exp(delta);
    }
  }
}

namespace {

/// Knots as AD scalars whose derivatives are the local time slots, for the knots that shape
/// span `span` (indices span−3 .. span+4). Returns the slots' x indices.
void seed_knots(const TrajectoryLayout& layout, const std::vector<double>& knots, int span,
                std::vector<SplineAD>& knots_ad, int& time_count,
                std::array<int, kMaxLocalTimes>& time_variable) {
  knots_ad.assign(knots.size(), SplineAD(0.0));
  for (std::size_t m = 0; m < knots.size(); ++m)
    knots_ad[m] = SplineAD(knots[m]);
  time_count = 0;
  auto slot_of = [&](int variable) {
    for (int s = 0; s < time_count; ++s)
      if (time_variable[s] == variable) return s;
    time_variable[time_count] = variable;
    return time_count++;
  };
  const int first = std::max(0, span - 3);
  const int last = std::min(static_cast<int>(knots.size()) - 1, span + 4);
  for (int m = first; m <= last; ++m) {
    const TrajectoryLayout::KnotDependence dep = layout.knot_dependence(m);
    const int left = layout.time_variable(dep.left);
    const int right = layout.time_variable(dep.left + 1);
    if (left >= 0 && dep.weight < 1.0)
      knots_ad[m].derivatives()[kControlDirections + slot_of(left)] += 1.0 - dep.weight;
    if (right >= 0 && dep.weight > 0.0)
      knots_ad[m].derivatives()[kControlDirections + slot_of(right)] += dep.weight;
  }
}

/// Curve k's 4 active control points c = c̄·exp(δ) with their tangents δ as AD directions
/// 0..11.
void seeded_joint_controls(const std::vector<Eigen::Vector3d>& delta,
                           const std::vector<Eigen::Quaterniond>& reference, int c0,
                           Quat<SplineAD> (&c)[4]) {
  for (int i = 0; i < 4; ++i) {
    Vec3<SplineAD> d;
    for (int j = 0; j < 3; ++j)
      d[j] = spline_variable(delta[c0 + i][j], 3 * i + j);
    c[i] = reference[c0 + i].cast<SplineAD>() * quat_exp(d);
  }
}

/// Curve k's span evaluated with its 4 active control tangents as AD directions 0..11 (the
/// basis carries the time directions).
QuaternionSample<SplineAD> seeded_joint_span(const std::vector<Eigen::Vector3d>& delta,
                                             const std::vector<Eigen::Quaterniond>& reference,
                                             int c0, const SpanBasis<SplineAD>& basis) {
  Quat<SplineAD> c[4];
  seeded_joint_controls(delta, reference, c0, c);
  return evaluate_quaternion_span(c[0], c[1], c[2], c[3], basis);
}

/// The t-independent part of seeded_joint_span, with the same operations as
/// evaluate_quaternion_span (so the values agree to the last bit); the logs' AD (4 exps, 3 logs
/// per curve) runs once per span, quaternion_span_derivatives does the rest per sample.
void seeded_joint_logs(const std::vector<Eigen::Vector3d>& delta,
                       const std::vector<Eigen::Quaterniond>& reference, int c0,
                       JointSpanLogs& out) {
  Quat<SplineAD> c[4];
  seeded_joint_controls(delta, reference, c0, c);
  out.first = quaternion_value(c[0]);
  for (int dir = 0; dir < kSplineDirections; ++dir) {
    const Eigen::Quaterniond dq(c[0].w().derivatives()[dir], c[0].x().derivatives()[dir],
                                c[0].y().derivatives()[dir], c[0].z().derivatives()[dir]);
    // c₀(ε) = c₀·exp(θ₀) ⇒ dθ₀ = vec(c₀⁻¹ dc₀).
    out.first_tangent.col(dir) = (out.first.conjugate() * dq).vec();
  }
  for (int j = 0; j < 3; ++j) {
    const Vec3<SplineAD> log = quat_log(Quat<SplineAD>(c[j].conjugate() * c[j + 1]));
    for (int i = 0; i < 3; ++i) {
      out.logs[j][i] = log[i].value();
      out.log_derivative[j].row(i) = log[i].derivatives().transpose();
    }
  }
}

/// The cumulative basis values the span evaluation uses and their time derivatives.
CumulativeBasisDerivatives<kSplineDirections> cumulative_basis(const SpanBasis<SplineAD>& basis) {
  CumulativeBasisDerivatives<kSplineDirections> out;
  for (int d = 0; d < 3; ++d)
    for (int j = 0; j < 3; ++j) {
      out.value[d][j] = basis.cumulative[d][j + 1].value();
      out.derivative[d][j] = basis.cumulative[d][j + 1].derivatives().transpose();
    }
  return out;
}

/// The root translation's span with its 4 active control points as AD directions 0..11.
VectorSample<SplineAD> seeded_root_span(const std::vector<Eigen::Vector3d>& control, int c0,
                                        const SpanBasis<SplineAD>& basis) {
  Vec3<SplineAD> p[4];
  for (int i = 0; i < 4; ++i)
    for (int d = 0; d < 3; ++d)
      p[i][d] = spline_variable(control[c0 + i][d], 3 * i + d);
  return evaluate_vector_span(p[0], p[1], p[2], p[3], basis);
}

template <int Rows>
void scatter(const Eigen::Matrix<double, Rows, kSplineDirections>& m, int curve, int curve_block,
             int time_count, LocalJacobian<Rows>& out) {
  for (int c = 0; c < 4; ++c)
    for (int d = 0; d < 3; ++d)
      out.control.col(c * curve_block + 3 * curve + d) += m.col(3 * c + d);
  out.time.leftCols(time_count) += m.middleCols(kControlDirections, time_count);
}

template <int Rows>
void reset(LocalJacobian<Rows>& out, const TrajectoryLayout& layout, int span, int time_count,
           const std::array<int, kMaxLocalTimes>& time_variable) {
  out.first_control_variable = layout.control_variable(0, span - 3, 0);
  out.control.setZero(Rows, 4 * layout.curve_block());
  out.time.setZero();
  out.time_count = time_count;
  out.time_variable = time_variable;
}

}  // namespace

Vector6d RootWrenchDerivatives::wrench(double t) {
  return wrench_at(find_span(knots_, t), t);
}

Vector6d RootWrenchDerivatives::wrench_at(int span, double t) {
  const SpanBasis<double> basis = cubic_basis_on_span(knots_, span, t);
  const int c0 = span - 3;
  const VectorSample<double> b =
      evaluate_vector_span(root_control_[c0], root_control_[c0 + 1], root_control_[c0 + 2],
                           root_control_[c0 + 3], basis);
  BodyState<double>& state = work_->state;
  state.root_position = b.position;
  state.root_velocity = b.velocity;
  state.root_acceleration = b.acceleration;
  for (int k = 0; k < layout_.segment_count; ++k) {
    const auto& c = joint_control_[k];
    const QuaternionSample<double> s =
        evaluate_quaternion_span(c[c0], c[c0 + 1], c[c0 + 2], c[c0 + 3], basis);
    state.joints[k] = {s.q, s.omega, s.alpha};
  }
  inverse_dynamics(model_, work_->data, state);
  return root_wrench_force_first(work_->data);
}

void RootWrenchDerivatives::wrench_jacobian(double t, LocalJacobian<6>& out) {
  Workspace& w = *work_;
  const int span = find_span(knots_, t);
  w.basis_keyframe = -1;  // the time slots below are the sample's, not a keyframe's
  seed_knots(layout_, knots_, span, w.knots_ad, w.time_count, w.time_variable);
  wrench_jacobian_seeded(span, t, out);
}

Vector6d RootWrenchDerivatives::wrench_on_span(int span, double xi) {
  return wrench_at(span, knots_[span] + xi * (knots_[span + 1] - knots_[span]));
}

void RootWrenchDerivatives::wrench_jacobian_on_span(
    int span, double xi, LocalJacobian<6>& out,
    Eigen::Matrix<double, 1, kMaxLocalTimes>& span_length_rate) {
  Workspace& w = *work_;
  w.basis_keyframe = -1;
  seed_knots(layout_, knots_, span, w.knots_ad, w.time_count, w.time_variable);
  const SplineAD length = w.knots_ad[span + 1] - w.knots_ad[span];
  const SplineAD t = w.knots_ad[span] + xi * length;
  span_length_rate = length.derivatives().tail<kMaxLocalTimes>().transpose();
  wrench_jacobian_seeded(span, t, out);
}

template <typename Time>
void RootWrenchDerivatives::seed_state(int span, const Time& t) {
  Workspace& w = *work_;
  const int n = layout_.segment_count;
  const int c0 = span - 3;
  const SpanBasis<SplineAD> basis = cubic_basis_on_span(w.knots_ad, span, SplineAD(t));

  // Stage 1: each curve's state and its derivatives with respect to controls and times.
  if (w.logs_span != span) {
    for (int k = 0; k < n; ++k)
      seeded_joint_logs(joint_delta_[k], reference_.joint_control[k], c0, w.span_logs[k]);
    w.logs_span = span;
  }
  BodyState<double>& state = w.state;
  const CumulativeBasisDerivatives<kSplineDirections> cumulative = cumulative_basis(basis);
  for (int k = 0; k < n; ++k) {
    const QuaternionSpanDerivatives<kSplineDirections> s =
        quaternion_span_derivatives(w.span_logs[k], cumulative);
    w.joint_state_jacobian[k] = s.jacobian;
    state.joints[k] = {s.sample.q, s.sample.omega, s.sample.alpha};
  }
  const VectorSample<SplineAD> b = seeded_root_span(root_control_, c0, basis);
  for (int i = 0; i < 3; ++i) {
    state.root_position[i] = b.position[i].value();
    state.root_velocity[i] = b.velocity[i].value();
    state.root_acceleration[i] = b.acceleration[i].value();
    w.root_state_jacobian.row(i) = b.velocity[i].derivatives().transpose();
    w.root_state_jacobian.row(3 + i) = b.acceleration[i].derivatives().transpose();
  }

  // Stage 2's common part: one double inverse dynamics pass and the root wrench's derivatives
  // with respect to every curve's state, in closed form.
  inverse_dynamics(model_, w.data, state);
  root_wrench_state_jacobian(model_, w.data, state, w.wrench_state);
}

template <typename Time>
void RootWrenchDerivatives::wrench_jacobian_seeded(int span, const Time& t, LocalJacobian<6>& out) {
  Workspace& w = *work_;
  const int n = layout_.segment_count;
  seed_state(span, t);
  out.value = root_wrench_force_first(w.data);

  // Chain rule. lazyProduct: these fixed-size products are past Eigen's small-product threshold
  // and would otherwise go through the blocked GEMM kernel, whose packing costs more than the
  // arithmetic here.
  reset(out, layout_, span, w.time_count, w.time_variable);
  const int block = layout_.curve_block();
  const Eigen::Matrix<double, 6, kSplineDirections> root_part =
      w.wrench_state.root_translation.lazyProduct(w.root_state_jacobian);
  scatter<6>(root_part, 0, block, w.time_count, out);
  for (int k = 0; k < n; ++k) {
    const Eigen::Matrix<double, 6, kSplineDirections> joint_part =
        w.wrench_state.joint[k].lazyProduct(w.joint_state_jacobian[k]);
    scatter<6>(joint_part, k + 1, block, w.time_count, out);
  }
}

Eigen::VectorXd RootWrenchDerivatives::joint_loads_on_span(int span, double xi,
                                                           int rows_per_joint) {
  wrench_on_span(span, xi);
  const DynamicsData<double>& data = work_->data;
  Eigen::VectorXd out(rows_per_joint * (layout_.segment_count - 1));
  for (int j = 1; j < layout_.segment_count; ++j)
    out.segment(rows_per_joint * (j - 1), rows_per_joint) =
        data.joint_wrench[j].head(rows_per_joint);
  return out;
}

Eigen::VectorXd RootWrenchDerivatives::joint_moments_on_span(int span, double xi) {
  return joint_loads_on_span(span, xi, 3);
}

Eigen::VectorXd RootWrenchDerivatives::joint_wrenches_on_span(int span, double xi) {
  return joint_loads_on_span(span, xi, 6);
}

void RootWrenchDerivatives::joint_moments_jacobian_on_span(int span, double xi,
                                                           LocalJacobian<Eigen::Dynamic>& out) {
  joint_loads_jacobian_on_span<3>(span, xi, out);
}

void RootWrenchDerivatives::joint_wrenches_jacobian_on_span(int span, double xi,
                                                            LocalJacobian<Eigen::Dynamic>& out) {
  joint_loads_jacobian_on_span<6>(span, xi, out);
}

template <int RowsPerJoint>
void RootWrenchDerivatives::joint_loads_jacobian_on_span(int span, double xi,
                                                         LocalJacobian<Eigen::Dynamic>& out) {
  Workspace& w = *work_;
  const int n = layout_.segment_count;
  w.basis_keyframe = -1;
  seed_knots(layout_, knots_, span, w.knots_ad, w.time_count, w.time_variable);
  const SplineAD t = w.knots_ad[span] + xi * (w.knots_ad[span + 1] - w.knots_ad[span]);
  seed_state(span, t);
  joint_wrench_state_jacobian(model_, w.data, w.state, w.wrench_state, w.joint_wrench_state);

  const int rows = RowsPerJoint * (n - 1);
  const int block = layout_.curve_block();
  out.first_control_variable = layout_.control_variable(0, span - 3, 0);
  out.value.resize(rows);
  out.control.setZero(rows, 4 * block);
  out.time.setZero(rows, kMaxLocalTimes);
  out.time_count = w.time_count;
  out.time_variable = w.time_variable;
  // Chain rule, joint by joint: only the curves whose state moves that joint's load.
  Eigen::Matrix<double, RowsPerJoint, kSplineDirections> part;
  auto add = [&](int row, int curve) {
    for (int c = 0; c < 4; ++c)
      out.control.template block<RowsPerJoint, 3>(row, c * block + 3 * curve) +=
          part.template middleCols<3>(3 * c);
    out.time.block(row, 0, RowsPerJoint, w.time_count) +=
        part.middleCols(kControlDirections, w.time_count);
  };
  const JointWrenchStateJacobian& jac = w.joint_wrench_state;
  for (int j = 1; j < n; ++j) {
    const int row = RowsPerJoint * (j - 1);
    out.value.segment(row, RowsPerJoint) = w.data.joint_wrench[j].head<RowsPerJoint>();
    part.noalias() =
        jac.root_translation[j].topRows<RowsPerJoint>().lazyProduct(w.root_state_jacobian);
    add(row, 0);
    for (int k = 0; k < n; ++k) {
      if (!jac.touches[j * n + k]) continue;
      part.noalias() =
          jac.joint[j * n + k].topRows<RowsPerJoint>().lazyProduct(w.joint_state_jacobian[k]);
      add(row, k + 1);
    }
  }
}

namespace {
/// The evaluation time of keyframe i as an AD scalar: it is the knot itself, so it carries that
/// knot's time derivative.
SplineAD keyframe_time(const std::vector<SplineAD>& knots_ad, const TrajectoryLayout& layout,
                       int keyframe) {
  return knots_ad[layout.keyframe_knot(keyframe)];
}
}  // namespace

void RootWrenchDerivatives::prepare_keyframe(int keyframe) {
  Workspace& w = *work_;
  if (w.basis_keyframe == keyframe) return;
  const int span = layout_.keyframe_span(keyframe);
  seed_knots(layout_, knots_, span, w.knots_ad, w.time_count, w.time_variable);
  w.keyframe_basis =
      cubic_basis_on_span(w.knots_ad, span, keyframe_time(w.knots_ad, layout_, keyframe));
  w.basis_keyframe = keyframe;
}

Eigen::Vector3d RootWrenchDerivatives::keyframe_translation_value(int keyframe) const {
  const int span = layout_.keyframe_span(keyframe);
  const int c0 = span - 3;
  const SpanBasis<double> basis =
      cubic_basis_on_span(knots_, span, knots_[layout_.keyframe_knot(keyframe)]);
  return evaluate_vector_span(root_control_[c0], root_control_[c0 + 1], root_control_[c0 + 2],
                              root_control_[c0 + 3], basis)
      .position;
}

Eigen::Vector4d RootWrenchDerivatives::keyframe_rotation_value(int keyframe, int segment) const {
  const int span = layout_.keyframe_span(keyframe);
  const int c0 = span - 3;
  const SpanBasis<double> basis =
      cubic_basis_on_span(knots_, span, knots_[layout_.keyframe_knot(keyframe)]);
  const auto& c = joint_control_[segment];
  const Eigen::Quaterniond q =
      evaluate_quaternion_span(c[c0], c[c0 + 1], c[c0 + 2], c[c0 + 3], basis).q;
  return {q.w(), q.x(), q.y(), q.z()};
}

void RootWrenchDerivatives::keyframe_translation(int keyframe, LocalJacobian<3>& out) {
  Workspace& w = *work_;
  prepare_keyframe(keyframe);
  const int span = layout_.keyframe_span(keyframe);
  const VectorSample<SplineAD> b = seeded_root_span(root_control_, span - 3, w.keyframe_basis);
  Eigen::Matrix<double, 3, kSplineDirections> jac;
  for (int i = 0; i < 3; ++i) {
    out.value[i] = b.position[i].value();
    jac.row(i) = b.position[i].derivatives().transpose();
  }
  reset(out, layout_, span, w.time_count, w.time_variable);
  scatter<3>(jac, 0, layout_.curve_block(), w.time_count, out);
}

void RootWrenchDerivatives::keyframe_rotation(int keyframe, int segment, LocalJacobian<4>& out) {
  Workspace& w = *work_;
  prepare_keyframe(keyframe);
  const int span = layout_.keyframe_span(keyframe);
  const QuaternionSample<SplineAD> s = seeded_joint_span(
      joint_delta_[segment], reference_.joint_control[segment], span - 3, w.keyframe_basis);
  Eigen::Matrix<double, 4, kSplineDirections> jac;
  const SplineAD* coefficient[4] = {&s.q.w(), &s.q.x(), &s.q.y(), &s.q.z()};
  for (int i = 0; i < 4; ++i) {
    out.value[i] = coefficient[i]->value();
    jac.row(i) = coefficient[i]->derivatives().transpose();
  }
  reset(out, layout_, span, w.time_count, w.time_variable);
  scatter<4>(jac, segment + 1, layout_.curve_block(), w.time_count, out);
}

}  // namespace saltus
