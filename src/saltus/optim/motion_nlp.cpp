#include "saltus/optim/motion_nlp.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <thread>

#include "saltus/evaluation/sampling.h"
#include "saltus/motion/interpolate.h"

namespace saltus {

namespace {

/// The entry of a local Jacobian (weighted over its rows) for variable `column`, 0 if the
/// quantity does not depend on it at this x.
template <int Rows>
double local_derivative(const LocalJacobian<Rows>& jac,
                        const Eigen::Matrix<double, 1, Rows>& weights, int column) {
  const int local = column - jac.first_control_variable;
  if (local >= 0 && local < jac.control.cols()) return weights * jac.control.col(local);
  for (int s = 0; s < jac.time_count; ++s)
    if (jac.time_variable[s] == column) return weights * jac.time.col(s);
  return 0.0;
}

Eigen::Quaterniond aligned(const Eigen::Quaterniond& target, const Eigen::Vector4d& q) {
  // Sign-align the target to the curve (paper eq. 3 compares rotations, not signs).
  const Eigen::Vector4d t(target.w(), target.x(), target.y(), target.z());
  return t.dot(q) < 0 ? Eigen::Quaterniond(-target.w(), -target.x(), -target.y(), -target.z())
                      : target;
}

Eigen::Vector4d wxyz(const Eigen::Quaterniond& q) {
  return {q.w(), q.x(), q.y(), q.z()};
}

}  // namespace

MotionNlp::MotionNlp(const Motion& motion, const BodyModel& model,
                     const Trajectory<double>& initial, const MotionNlpOptions& options)
    : options_(options),
      takeoff_(motion.takeoff),
      tolerances_(motion.tolerances),
      damping_(options.damping) {
  const int n_key = static_cast<int>(motion.keyframes.size());
  if (n_key < 2) throw std::invalid_argument("a motion needs at least two keyframes");
  if (options.samples < 2) throw std::invalid_argument("samples must be at least 2");
  if (options.knots_per_interval < 1)
    throw std::invalid_argument("knots per interval must be at least 1");
  if (options.formulation == Formulation::kStrict && !(options.epsilon > 0))
    throw std::invalid_argument("epsilon must be positive");

  if (!(motion.tolerances.translation_m > 0) || !(motion.tolerances.quaternion > 0))
    throw std::invalid_argument("keyframe tolerances must be positive");
  translation_scale_ = 1.0 / motion.tolerances.translation_m;
  rotation_scale_ = 1.0 / (motion.tolerances.quaternion * motion.tolerances.quaternion);
  layout_.segment_count = model.size();
  layout_.keyframe_count = n_key;
  layout_.knots_per_interval = options.knots_per_interval;
  layout_.optimize_timing = options.optimize_timing && n_key >= 3;
  if (static_cast<int>(initial.knots.size()) != layout_.control_count() + 4)
    throw std::invalid_argument("initial trajectory is not on the layout's knots");

  for (const Keyframe& k : motion.keyframes)
    reference_.keyframe_times.push_back(k.time);
  for (const auto& r : initial.rotations)
    reference_.joint_control.push_back(r.control());
  initial_x_ = variables_from(layout_, reference_, initial, reference_.keyframe_times);
  if (options.limits_joint_turns())
    turn_penalty_ = std::make_unique<JointTurnPenalty>(
        layout_, reference_, options.joint_turn_limit, options.joint_turn_weight);
  duration_ = motion.flight_time();
  double shortest = duration_;
  for (int i = 0; i + 1 < n_key; ++i)
    shortest = std::min(shortest, reference_.keyframe_times[i + 1] - reference_.keyframe_times[i]);
  time_gap_ = std::min(options.min_time_gap, 0.5 * shortest);

  for (const Keyframe& k : motion.keyframes) {
    keyframe_com_offset_.push_back(com_with_root_at_origin(model, k.rotations));
    fixed_root_.push_back(k.root_position);
    keyframe_rotation_.push_back(k.rotations);
  }

  sample_times_ = uniform_times(duration_, options.samples);
  sample_weights_.assign(options.samples, 0.0);
  for (int s = 0; s + 1 < options.samples; ++s) {
    const double half = 0.5 * (sample_times_[s + 1] - sample_times_[s]) / duration_;
    sample_weights_[s] += half;
    sample_weights_[s + 1] += half;
  }

  int threads = options.threads > 0
                    ? options.threads
                    : std::min(4, static_cast<int>(std::thread::hardware_concurrency()));
  // A thread below ~20 samples costs more to start than it saves.
  threads = std::max(1, std::min(threads, options.samples / 20));
  for (int t = 0; t < threads; ++t)
    derivatives_.push_back(std::make_unique<RootWrenchDerivatives>(model, layout_, reference_));
  pool_ = std::make_unique<WorkerPool>(threads);
  stacked_rows_.resize(threads);

  // Jacobian structure, row by row.
  std::vector<int> time_variables;
  for (int i = 0; i < n_key; ++i)
    if (layout_.time_variable(i) >= 0) time_variables.push_back(layout_.time_variable(i));
  int row = 0;
  auto add_row = [&](const std::vector<int>& columns) {
    row_begin_.push_back(static_cast<int>(jacobian_columns_.size()));
    for (int c : columns) {
      jacobian_rows_.push_back(row);
      jacobian_columns_.push_back(c);
    }
    ++row;
  };
  for (int i = 0; i < n_key; ++i) {
    const int c0 = layout_.keyframe_span(i) - 3;
    for (int d = 0; d < 3; ++d) {
      std::vector<int> columns;
      for (int c = c0; c < c0 + 4; ++c)
        columns.push_back(layout_.control_variable(0, c, d));
      columns.insert(columns.end(), time_variables.begin(), time_variables.end());
      add_row(columns);
      ++translation_rows_;
    }
  }
  for (int i = 0; i < n_key; ++i) {
    const int c0 = layout_.keyframe_span(i) - 3;
    for (int k = 0; k < model.size(); ++k) {
      std::vector<int> columns;
      for (int c = c0; c < c0 + 4; ++c)
        for (int d = 0; d < 3; ++d)
          columns.push_back(layout_.control_variable(k + 1, c, d));
      columns.insert(columns.end(), time_variables.begin(), time_variables.end());
      add_row(columns);
      ++rotation_rows_;
    }
  }
  if (layout_.optimize_timing) {
    for (int i = 0; i + 1 < n_key; ++i) {
      std::vector<int> columns;
      if (layout_.time_variable(i) >= 0) columns.push_back(layout_.time_variable(i));
      if (layout_.time_variable(i + 1) >= 0) columns.push_back(layout_.time_variable(i + 1));
      order_pairs_.push_back(i);
      add_row(columns);
      ++order_rows_;
    }
  }
  if (options.formulation == Formulation::kStrict) {
    // A sample's span can change when the times move: its row covers every span it can reach
    // within the time bounds (exactly one span when timing is fixed).
    std::vector<double> x_lower(layout_.size()), x_upper(layout_.size());
    std::vector<double> g_lower(constraint_count() + 6 * options.samples), g_upper(g_lower.size());
    bounds(x_lower.data(), x_upper.data(), g_lower.data(), g_upper.data());
    const auto knots_at = [&](const std::vector<double>& x) {
      return clamped_cubic_knots(refine_breakpoints(
          keyframe_times_from(layout_, reference_, x.data()), layout_.knots_per_interval));
    };
    const std::vector<double> earliest = knots_at(x_lower), latest = knots_at(x_upper);
    for (double t : sample_times_) {
      const int first_span = find_span(latest, t), last_span = find_span(earliest, t);
      std::vector<int> columns;
      for (int v = layout_.control_variable(0, first_span - 3, 0);
           v < layout_.control_variable(0, last_span + 1, 0); ++v)
        columns.push_back(v);
      columns.insert(columns.end(), time_variables.begin(), time_variables.end());
      for (int component = 0; component < 6; ++component) {
        add_row(columns);
        ++strict_rows_;
      }
    }
  }
  row_begin_.push_back(static_cast<int>(jacobian_columns_.size()));

  // Hessian band (lower triangle): a control variable couples with controls at most 3 indices
  // below its own (they share a span) and with every time; a time couples with everything.
  const int n = layout_.size();
  hessian_first_column_.resize(n);
  hessian_row_start_.resize(n + 1);
  long total = 0;
  for (int r = 0; r < n; ++r) {
    if (r < layout_.control_variable_count()) {
      const int control = r / layout_.curve_block();
      hessian_first_column_[r] = std::max(0, control - 3) * layout_.curve_block();
    } else {
      hessian_first_column_[r] = 0;
    }
    hessian_row_start_[r] = total;
    total += r - hessian_first_column_[r] + 1;
  }
  hessian_row_start_[n] = total;
  hessian_nonzeros_ = static_cast<int>(total);

  wrench_.resize(options.samples);
  wrench_jacobian_.resize(options.samples);
  translation_jacobian_.resize(n_key);
  rotation_jacobian_.resize(n_key * model.size());
}

MotionNlp::~MotionNlp() = default;

double MotionNlp::proximity_term(const double* x, double* gradient,
                                 double* hessian_diagonal) const {
  // w Σ ‖δ‖² over the joints' tangent coordinates: smooth and convex, it makes the directions
  // the root force hardly sees (light limbs) well posed without bounds.
  const double w = options_.regularization;
  if (w <= 0) return 0.0;
  double penalty = 0.0;
  for (int v = 0; v < layout_.control_variable_count(); ++v) {
    if (v % layout_.curve_block() < 3) continue;  // root translation
    penalty += w * x[v] * x[v];
    if (gradient) gradient[v] += 2.0 * w * x[v];
    if (hessian_diagonal) hessian_diagonal[v] += 2.0 * w;
  }
  return penalty;
}

int MotionNlp::constraint_count() const {
  return translation_rows_ + rotation_rows_ + order_rows_ + strict_rows_;
}

void MotionNlp::bounds(double* x_lower, double* x_upper, double* g_lower, double* g_upper) const {
  for (int v = 0; v < layout_.control_variable_count(); ++v) {
    const bool joint = v % layout_.curve_block() >= 3;
    // Tangent coordinates stay well inside |δ| < π/2 where exp is a one-to-one chart. Nothing
    // tighter: hundreds of bounded variables would add barrier terms that swamp a small J.
    x_lower[v] = joint ? -1.5 : -kUnbounded;
    x_upper[v] = joint ? 1.5 : kUnbounded;
  }
  for (int i = 0; i < layout_.keyframe_count; ++i) {
    const int v = layout_.time_variable(i);
    if (v < 0) continue;
    const double t0 = reference_.keyframe_times[i];
    x_lower[v] = std::max(t0 - options_.max_time_shift, time_gap_ * i);
    x_upper[v] = std::min(t0 + options_.max_time_shift,
                          duration_ - time_gap_ * (layout_.keyframe_count - 1 - i));
  }
  // Keyframe rows are in units of their tolerance, with bounds kKeyframeBoundMargin inside it:
  // the solver may stop at a point that violates its bounds by half that (SolverOptions::
  // acceptable_constraint_violation), and the written motion must still meet ε1 and ε2.
  const double bound = 1.0 - kKeyframeBoundMargin;
  int row = 0;
  for (int r = 0; r < translation_rows_; ++r, ++row) {
    g_lower[row] = -bound;
    g_upper[row] = bound;
  }
  for (int r = 0; r < rotation_rows_; ++r, ++row) {
    g_lower[row] = -kUnbounded;
    g_upper[row] = bound;
  }
  for (int r = 0; r < order_rows_; ++r, ++row) {
    g_lower[row] = time_gap_;
    g_upper[row] = kUnbounded;
  }
  for (int r = 0; r < strict_rows_; ++r, ++row) {
    g_lower[row] = -options_.epsilon;
    g_upper[row] = options_.epsilon;
  }
}

void MotionNlp::initial_point(double* x) const {
  std::copy(initial_x_.begin(), initial_x_.end(), x);
}

void MotionNlp::load(const double* x) {
  const std::size_t n = layout_.size();
  if (have_x_ && std::memcmp(x, x_.data(), n * sizeof(double)) == 0) return;
  x_.assign(x, x + n);
  have_x_ = true;
  have_wrenches_ = have_wrench_jacobians_ = have_keyframes_ = have_keyframe_values_ =
      have_gradient_ = false;
  for (auto& evaluator : derivatives_)
    evaluator->set_variables(x);
}

template <typename Body>
void MotionNlp::for_each_range(int count, Body&& body) {
  const int parts = pool_->parts();
  pool_->run([&](int p) {
    const int begin = count * p / parts, end = count * (p + 1) / parts;
    if (begin < end) body(p, begin, end);
  });
}

void MotionNlp::compute_wrenches() {
  if (have_wrenches_) return;
  const int samples = static_cast<int>(sample_times_.size());
  for_each_range(samples, [this](int part, int begin, int end) {
    for (int s = begin; s < end; ++s)
      wrench_[s] = derivatives_[part]->wrench(sample_times_[s]);
  });
  have_wrenches_ = true;
}

void MotionNlp::compute_wrench_jacobians() {
  if (have_wrench_jacobians_) return;
  const int samples = static_cast<int>(sample_times_.size());
  for_each_range(samples, [this](int part, int begin, int end) {
    for (int s = begin; s < end; ++s) {
      derivatives_[part]->wrench_jacobian(sample_times_[s], wrench_jacobian_[s]);
      wrench_[s] = wrench_jacobian_[s].value;
    }
  });
  have_wrenches_ = have_wrench_jacobians_ = true;
}

void MotionNlp::compute_keyframe_values() {
  // Line-search trial points need only the constraint values: plain double evaluation, not the
  // AD of every keyframe quantity (the derivatives follow once Ipopt accepts the point).
  if (have_keyframe_values_ || have_keyframes_) return;
  keyframe_times_ = keyframe_times_from(layout_, reference_, x_.data());
  for (int i = 0; i < layout_.keyframe_count; ++i) {
    translation_jacobian_[i].value = derivatives_[0]->keyframe_translation_value(i);
    for (int k = 0; k < layout_.segment_count; ++k)
      rotation_jacobian_[i * layout_.segment_count + k].value =
          derivatives_[0]->keyframe_rotation_value(i, k);
  }
  have_keyframe_values_ = true;
}

void MotionNlp::compute_keyframes() {
  if (have_keyframes_) return;
  keyframe_times_ = keyframe_times_from(layout_, reference_, x_.data());
  for_each_range(layout_.keyframe_count, [this](int part, int begin, int end) {
    RootWrenchDerivatives& evaluator = *derivatives_[part];
    for (int i = begin; i < end; ++i) {
      evaluator.keyframe_translation(i, translation_jacobian_[i]);
      for (int k = 0; k < layout_.segment_count; ++k)
        evaluator.keyframe_rotation(i, k, rotation_jacobian_[i * layout_.segment_count + k]);
    }
  });
  have_keyframes_ = true;
}

Eigen::Vector3d MotionNlp::root_target(int keyframe, double time) const {
  if (fixed_root_[keyframe]) return *fixed_root_[keyframe];
  return ballistic_com(takeoff_, time) - keyframe_com_offset_[keyframe];
}

double MotionNlp::force_objective(const double* x) {
  load(x);
  compute_wrenches();
  double j = 0.0;
  for (std::size_t s = 0; s < sample_times_.size(); ++s)
    j += sample_weights_[s] * wrench_[s].squaredNorm();
  return j;
}

double MotionNlp::objective(const double* x) {
  if (options_.formulation == Formulation::kRelaxed)
    return force_objective(x) + regularization(x, nullptr);
  load(x);
  compute_keyframe_values();
  double f = 0.0;
  for (int i = 0; i < layout_.keyframe_count; ++i) {
    f += (translation_jacobian_[i].value - root_target(i, keyframe_times_[i])).squaredNorm();
    for (int k = 0; k < layout_.segment_count; ++k) {
      const Eigen::Vector4d q = rotation_jacobian_[i * layout_.segment_count + k].value;
      f += (q - wxyz(aligned(keyframe_rotation_[i][k], q))).squaredNorm();
    }
  }
  return f + regularization(x, nullptr);
}

void MotionNlp::gradient(const double* x, double* out) {
  // Cached per x: Ipopt asks for it once per iteration and the Hessian's objective model
  // (hessian_values) needs it at the same point.
  load(x);
  if (!have_gradient_) {
    gradient_.resize(layout_.size());
    compute_gradient(gradient_.data());
    have_gradient_ = true;
  }
  std::copy(gradient_.begin(), gradient_.end(), out);
}

void MotionNlp::compute_gradient(double* gradient) {
  const double* x = x_.data();
  std::fill(gradient, gradient + layout_.size(), 0.0);
  if (options_.formulation == Formulation::kRelaxed) {
    compute_wrench_jacobians();
    for (std::size_t s = 0; s < sample_times_.size(); ++s) {
      const LocalJacobian<6>& jac = wrench_jacobian_[s];
      const Eigen::Matrix<double, 1, 6> w = 2.0 * sample_weights_[s] * wrench_[s].transpose();
      Eigen::Map<Eigen::RowVectorXd>(gradient + jac.first_control_variable, jac.control.cols()) +=
          w * jac.control;
      for (int p = 0; p < jac.time_count; ++p)
        gradient[jac.time_variable[p]] += w * jac.time.col(p);
    }
    regularization(x, gradient);
    return;
  }
  compute_keyframes();
  for (int i = 0; i < layout_.keyframe_count; ++i) {
    const LocalJacobian<3>& tj = translation_jacobian_[i];
    const Eigen::Vector3d r = tj.value - root_target(i, keyframe_times_[i]);
    const Eigen::Matrix<double, 1, 3> w = 2.0 * r.transpose();
    Eigen::Map<Eigen::RowVectorXd>(gradient + tj.first_control_variable, tj.control.cols()) +=
        w * tj.control;
    for (int p = 0; p < tj.time_count; ++p)
      gradient[tj.time_variable[p]] += w * tj.time.col(p);
    const int tv = layout_.time_variable(i);
    if (tv >= 0 && !fixed_root_[i])
      gradient[tv] -= w * ballistic_com_velocity(takeoff_, keyframe_times_[i]);
    for (int k = 0; k < layout_.segment_count; ++k) {
      const LocalJacobian<4>& rj = rotation_jacobian_[i * layout_.segment_count + k];
      const Eigen::Matrix<double, 1, 4> wq =
          2.0 * (rj.value - wxyz(aligned(keyframe_rotation_[i][k], rj.value))).transpose();
      Eigen::Map<Eigen::RowVectorXd>(gradient + rj.first_control_variable, rj.control.cols()) +=
          wq * rj.control;
      for (int p = 0; p < rj.time_count; ++p)
        gradient[rj.time_variable[p]] += wq * rj.time.col(p);
    }
  }
  regularization(x, gradient);
}

void MotionNlp::constraints(const double* x, double* g) {
  load(x);
  compute_keyframe_values();
  int row = 0;
  for (int i = 0; i < layout_.keyframe_count; ++i) {
    const Eigen::Vector3d r = translation_jacobian_[i].value - root_target(i, keyframe_times_[i]);
    for (int d = 0; d < 3; ++d)
      g[row++] = translation_scale_ * r[d];
  }
  for (int i = 0; i < layout_.keyframe_count; ++i) {
    for (int k = 0; k < layout_.segment_count; ++k) {
      const Eigen::Vector4d q = rotation_jacobian_[i * layout_.segment_count + k].value;
      g[row++] = rotation_scale_ * (q - wxyz(aligned(keyframe_rotation_[i][k], q))).squaredNorm();
    }
  }
  for (int i : order_pairs_)
    g[row++] = keyframe_times_[i + 1] - keyframe_times_[i];
  if (strict_rows_ > 0) {
    compute_wrenches();
    for (std::size_t s = 0; s < sample_times_.size(); ++s)
      for (int c = 0; c < 6; ++c)
        g[row++] = wrench_[s][c];
  }
}

void MotionNlp::jacobian_structure(int* rows, int* columns) const {
  std::copy(jacobian_rows_.begin(), jacobian_rows_.end(), rows);
  std::copy(jacobian_columns_.begin(), jacobian_columns_.end(), columns);
}

void MotionNlp::jacobian_values(const double* x, double* values) {
  load(x);
  compute_keyframes();
  if (strict_rows_ > 0) compute_wrench_jacobians();
  int row = 0;
  auto entries = [&](int r, auto&& derivative) {
    for (int e = row_begin_[r]; e < row_begin_[r + 1]; ++e)
      values[e] = derivative(jacobian_columns_[e]);
  };
  for (int i = 0; i < layout_.keyframe_count; ++i) {
    const LocalJacobian<3>& tj = translation_jacobian_[i];
    const int own_time = layout_.time_variable(i);
    const Eigen::Vector3d target_rate =
        fixed_root_[i] ? Eigen::Vector3d::Zero()
                       : Eigen::Vector3d(ballistic_com_velocity(takeoff_, keyframe_times_[i]));
    for (int d = 0; d < 3; ++d, ++row) {
      Eigen::Matrix<double, 1, 3> pick = Eigen::Matrix<double, 1, 3>::Zero();
      pick[d] = translation_scale_;
      entries(row, [&](int column) {
        return local_derivative<3>(tj, pick, column) -
               (column == own_time ? translation_scale_ * target_rate[d] : 0.0);
      });
    }
  }
  for (int i = 0; i < layout_.keyframe_count; ++i) {
    for (int k = 0; k < layout_.segment_count; ++k, ++row) {
      const LocalJacobian<4>& rj = rotation_jacobian_[i * layout_.segment_count + k];
      const Eigen::Matrix<double, 1, 4> w =
          2.0 * rotation_scale_ *
          (rj.value - wxyz(aligned(keyframe_rotation_[i][k], rj.value))).transpose();
      entries(row, [&](int column) { return local_derivative<4>(rj, w, column); });
    }
  }
  for (int i : order_pairs_) {
    const int earlier = layout_.time_variable(i);
    entries(row++, [&](int column) { return column == earlier ? -1.0 : 1.0; });
  }
  for (std::size_t s = 0; s < sample_times_.size() && strict_rows_ > 0; ++s) {
    for (int c = 0; c < 6; ++c, ++row) {
      Eigen::Matrix<double, 1, 6> pick = Eigen::Matrix<double, 1, 6>::Zero();
      pick[c] = 1.0;
      entries(row,
              [&](int column) { return local_derivative<6>(wrench_jacobian_[s], pick, column); });
    }
  }
}

void MotionNlp::hessian_structure(int* rows, int* columns) const {
  long e = 0;
  for (int r = 0; r < layout_.size(); ++r)
    for (int c = hessian_first_column_[r]; c <= r; ++c, ++e) {
      rows[e] = r;
      columns[e] = c;
    }
}

int MotionNlp::hessian_index(int row, int column) const {
  if (column > row) std::swap(row, column);
  return static_cast<int>(hessian_row_start_[row] + (column - hessian_first_column_[row]));
}

template <int Rows>
void MotionNlp::add_gauss_newton(const LocalJacobian<Rows>& jac, double weight,
                                 double* values) const {
  // weight·JᵀJ into the lower band. A keyframe quantity depends on one curve only (12 of the
  // block's columns), so the product runs over the non-zero columns alone.
  const int first = jac.first_control_variable;
  const int width = static_cast<int>(jac.control.cols());
  std::vector<int> used;
  for (int c = 0; c < width; ++c)
    if (!jac.control.col(c).isZero(0.0)) used.push_back(c);
  const int count = static_cast<int>(used.size());
  for (int a = 0; a < count; ++a) {
    const int ca = used[a];
    for (int b = 0; b <= a; ++b) {
      const int cb = used[b];
      values[hessian_index(first + ca, first + cb)] +=
          weight * jac.control.col(ca).dot(jac.control.col(cb));
    }
  }
  for (int p = 0; p < jac.time_count; ++p) {
    const int tv = jac.time_variable[p];
    for (int a = 0; a < count; ++a)
      values[hessian_index(tv, first + used[a])] +=
          weight * jac.time.col(p).dot(jac.control.col(used[a]));
    for (int q = 0; q < jac.time_count; ++q)
      if (jac.time_variable[q] <= tv)
        values[hessian_index(tv, jac.time_variable[q])] +=
            weight * jac.time.col(p).dot(jac.time.col(q));
  }
}

void MotionNlp::add_wrench_gauss_newton(double factor, double* values) {
  // Samples on one knot span share their columns (the span's control block and time slots), so
  // Σ w_s J_sᵀJ_s over the span is one symmetric rank-k update of the stacked, weighted rows
  // and one scatter into the band — instead of a dense product and a scatter per sample, which
  // made the Hessian the most expensive part of an iteration. The spans' blocks are computed in
  // parallel and scattered in span order, so the sums do not depend on the thread count.
  const std::size_t n = sample_times_.size();
  spans_.clear();
  for (std::size_t begin = 0; begin < n;) {
    const LocalJacobian<6>& first = wrench_jacobian_[begin];
    std::size_t end = begin + 1;
    while (end < n &&
           wrench_jacobian_[end].first_control_variable == first.first_control_variable &&
           wrench_jacobian_[end].time_count == first.time_count &&
           wrench_jacobian_[end].time_variable == first.time_variable)
      ++end;
    spans_.emplace_back(static_cast<int>(begin), static_cast<int>(end));
    begin = end;
  }
  span_blocks_.resize(spans_.size());
  const int span_count = static_cast<int>(spans_.size());
  for_each_range(span_count, [&](int part, int first_span, int end_span) {
    Eigen::MatrixXd& stacked = stacked_rows_[part];
    for (int index = first_span; index < end_span; ++index) {
      const auto [begin, end] = spans_[index];
      const LocalJacobian<6>& first = wrench_jacobian_[begin];
      const int width = static_cast<int>(first.control.cols());
      const int times = first.time_count;
      stacked.resize(6 * (end - begin), width + times);
      for (int s = begin; s < end; ++s) {
        const double root_weight = std::sqrt(factor * sample_weights_[s]);
        const int row = 6 * (s - begin);
        stacked.block(row, 0, 6, width) = root_weight * wrench_jacobian_[s].control;
        stacked.block(row, width, 6, times) =
            root_weight * wrench_jacobian_[s].time.leftCols(times);
      }
      Eigen::MatrixXd& block = span_blocks_[index];
      block.setZero(width + times, width + times);
      block.selfadjointView<Eigen::Lower>().rankUpdate(stacked.transpose());
    }
  });
  for (int index = 0; index < span_count; ++index) {
    const LocalJacobian<6>& first = wrench_jacobian_[spans_[index].first];
    const Eigen::MatrixXd& block = span_blocks_[index];
    const int width = static_cast<int>(first.control.cols());
    const int times = first.time_count;
    // Scatter the lower triangle: controls are contiguous from `first_control_variable`, time
    // slot p is variable time_variable[p] (beyond every control).
    const int base = first.first_control_variable;
    for (int a = 0; a < width; ++a)
      Eigen::Map<Eigen::RowVectorXd>(values + hessian_index(base + a, base), a + 1) +=
          block.row(a).head(a + 1);
    for (int p = 0; p < times; ++p) {
      const int tv = first.time_variable[p];
      Eigen::Map<Eigen::RowVectorXd>(values + hessian_index(tv, base), width) +=
          block.row(width + p).head(width);
      for (int q = 0; q < times; ++q) {
        const int other = first.time_variable[q];
        // Row width + max(p, q) holds the pair in the lower triangle.
        if (other <= tv)
          values[hessian_index(tv, other)] += block(width + std::max(p, q), width + std::min(p, q));
      }
    }
  }
}

LocalJacobian<3> MotionNlp::translation_residual_jacobian(int keyframe) const {
  // r = B(t_i) − B̄(t_i): the target moves along the parabola with the keyframe's time.
  LocalJacobian<3> jac = translation_jacobian_[keyframe];
  const int tv = layout_.time_variable(keyframe);
  if (tv < 0 || fixed_root_[keyframe]) return jac;
  int slot = 0;
  while (slot < jac.time_count && jac.time_variable[slot] != tv)
    ++slot;
  if (slot == jac.time_count) {
    jac.time_variable[jac.time_count++] = tv;
    jac.time.col(slot).setZero();
  }
  jac.time.col(slot) -= ballistic_com_velocity(takeoff_, keyframe_times_[keyframe]);
  return jac;
}

void MotionNlp::hessian_values(const double* x, double objective_factor, const double* multipliers,
                               double* values) {
  load(x);
  std::fill(values, values + hessian_nonzeros_, 0.0);
  compute_keyframes();
  if (options_.formulation == Formulation::kRelaxed) {
    // Gauss-Newton of J = Σ w_s ‖F_s‖², damped (Levenberg-Marquardt, see MotionNlpOptions).
    compute_wrench_jacobians();
    add_wrench_gauss_newton(2.0 * objective_factor, values);
    if (options_.adapt_damping && objective_factor > 0 && last_model_.valid) judge_last_step(x);
    const double damping = objective_factor * damping_.factor() * force_objective(x);
    for (int v = 0; v < layout_.size(); ++v)
      values[hessian_index(v, v)] += damping;
  } else {
    // Gauss-Newton of the keyframe distance Σ‖B − B̄‖² + Σ‖Q − Q̄‖² (exact at zero distance).
    // The force constraints' curvature is left out: it is not available.
    for (int i = 0; i < layout_.keyframe_count; ++i) {
      add_gauss_newton(translation_residual_jacobian(i), 2.0 * objective_factor, values);
      for (int k = 0; k < layout_.segment_count; ++k)
        add_gauss_newton(rotation_jacobian_[i * layout_.segment_count + k], 2.0 * objective_factor,
                         values);
    }
  }
  add_regularization_curvature(x, objective_factor, values);
  if (options_.formulation == Formulation::kRelaxed && options_.adapt_damping &&
      objective_factor > 0) {
    // Keep the objective's model (before the constraints' curvature joins it) for the next step.
    last_model_.x = x_;
    last_model_.gradient.resize(layout_.size());
    gradient(x, last_model_.gradient.data());
    last_model_.hessian.assign(values, values + hessian_nonzeros_);
    for (double& h : last_model_.hessian)
      h /= objective_factor;
    last_model_.objective = objective(x);
    last_model_.valid = true;
  }

  // Gauss-Newton curvature of the quaternion-distance constraints g = ‖r‖² (∇²g ≈ 2 JᵀJ),
  // counted only where the multiplier makes it positive semi-definite.
  for (int i = 0; i < layout_.keyframe_count; ++i) {
    for (int k = 0; k < layout_.segment_count; ++k) {
      const int index = i * layout_.segment_count + k;
      const double lambda = multipliers[translation_rows_ + index];
      if (lambda > 0)
        add_gauss_newton(rotation_jacobian_[index], 2.0 * rotation_scale_ * lambda, values);
    }
  }
}

void MotionNlp::step_taken(const StepTaken& step) {
  // A new run starts from scratch; a restoration step optimised something else (feasibility),
  // so the model kept before it says nothing about it.
  if (step.iteration == 0) damping_.reset();
  if (step.iteration == 0 || step.restoration) last_model_.valid = false;
  last_step_ = step;
}

double MotionNlp::regularization(const double* x, double* gradient) const {
  return proximity_term(x, gradient, nullptr) +
         (turn_penalty_ ? turn_penalty_->evaluate(x, gradient, nullptr) : 0.0);
}

void MotionNlp::add_regularization_curvature(const double* x, double factor, double* values) const {
  std::vector<double> proximity_curvature(layout_.size(), 0.0);
  proximity_term(x, nullptr, proximity_curvature.data());
  for (int v = 0; v < layout_.size(); ++v)
    values[hessian_index(v, v)] += factor * proximity_curvature[v];
  if (!turn_penalty_) return;
  std::vector<JointTurnPenalty::ActivePair> active;
  turn_penalty_->evaluate(x, nullptr, &active);
  // Gauss–Newton of ρ·r² with r = θ − L: 2ρ·∇θ∇θᵀ. Both controls are neighbours on one curve,
  // inside the band.
  const double scale = 2.0 * factor * turn_penalty_->weight();
  for (const JointTurnPenalty::ActivePair& pair : active)
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        if (pair.variables[b] <= pair.variables[a])
          values[hessian_index(pair.variables[a], pair.variables[b])] +=
              scale * pair.turn_gradient[a] * pair.turn_gradient[b];
}

std::vector<double> MotionNlp::band_product(const std::vector<double>& band,
                                            const double* s) const {
  const int n = layout_.size();
  std::vector<double> product(n, 0.0);
  for (int r = 0; r < n; ++r) {
    const long start = hessian_row_start_[r];
    const int first = hessian_first_column_[r];
    for (int c = first; c < r; ++c) {
      product[r] += band[start + (c - first)] * s[c];
      product[c] += band[start + (c - first)] * s[r];
    }
    product[r] += band[start + (r - first)] * s[r];
  }
  return product;
}

void MotionNlp::judge_last_step(const double* x) {
  const int n = layout_.size();
  std::vector<double> step(n);
  double length = 0.0;
  for (int v = 0; v < n; ++v) {
    step[v] = x[v] - last_model_.x[v];
    length += step[v] * step[v];
  }
  if (length == 0.0) return;  // the same point again: nothing to judge
  const std::vector<double> curvature = band_product(last_model_.hessian, step.data());
  double slope = 0.0, quadratic = 0.0;
  for (int v = 0; v < n; ++v) {
    slope += last_model_.gradient[v] * step[v];
    quadratic += step[v] * curvature[v];
  }
  const double predicted = -(slope + 0.5 * quadratic);
  const double actual = last_model_.objective - objective(x);
  // A step the model says goes uphill was taken for feasibility (Ipopt trades objective for
  // constraint violation): counted as poorly predicted, so that μ grows while the keyframe
  // constraints are being restored.
  const double ratio = predicted > 0 ? actual / predicted : -1.0;
  damping_.update(ratio, last_step_.line_search_trials > 1);
}

}  // namespace saltus
