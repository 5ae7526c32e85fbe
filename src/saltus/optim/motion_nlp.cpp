#include "saltus/optim/motion_nlp.h"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "saltus/math/bspline_basis.h"
#include "saltus/optim/terms/force_bound_block.h"
#include "saltus/optim/terms/joint_acceleration_term.h"
#include "saltus/optim/terms/joint_bound_block.h"
#include "saltus/optim/terms/joint_load_term.h"
#include "saltus/optim/terms/joint_turn_term.h"
#include "saltus/optim/terms/keyframe_distance_term.h"
#include "saltus/optim/terms/keyframe_rotation_block.h"
#include "saltus/optim/terms/keyframe_translation_block.h"
#include "saltus/optim/terms/proximity_term.h"
#include "saltus/optim/terms/root_wrench_term.h"
#include "saltus/optim/terms/time_order_block.h"

namespace saltus {

MotionNlp::MotionNlp(const Motion& motion, const BodyModel& model,
                     const Trajectory<double>& initial, const MotionNlpOptions& options)
    : options_(options), damping_(options.damping) {
  const int n_key = static_cast<int>(motion.keyframes.size());
  if (n_key < 2) throw std::invalid_argument("a motion needs at least two keyframes");
  if (options.samples < 2) throw std::invalid_argument("samples must be at least 2");
  if (options.knots_per_interval < 1)
    throw std::invalid_argument("knots per interval must be at least 1");
  if (options.formulation == Formulation::kStrict && !(options.epsilon > 0))
    throw std::invalid_argument("epsilon must be positive");
  if (!(motion.tolerances.translation_m > 0) || !(motion.tolerances.quaternion > 0))
    throw std::invalid_argument("keyframe tolerances must be positive");

  layout_.segment_count = model.size();
  layout_.keyframe_count = n_key;
  layout_.set_subdivisions(options.spans_per_interval(n_key));
  layout_.optimize_timing = options.optimize_timing && n_key >= 3;
  if (static_cast<int>(initial.knots.size()) != layout_.control_count() + 4)
    throw std::invalid_argument("initial trajectory is not on the layout's knots");
  for (const Keyframe& k : motion.keyframes)
    reference_.keyframe_times.push_back(k.time);
  for (const auto& r : initial.rotations)
    reference_.joint_control.push_back(r.control());
  initial_x_ = variables_from(layout_, reference_, initial, reference_.keyframe_times);
  duration_ = motion.flight_time();
  given_times_ = options.given_keyframe_times.empty() ? reference_.keyframe_times
                                                      : options.given_keyframe_times;
  if (static_cast<int>(given_times_.size()) != n_key)
    throw std::invalid_argument("one given time per keyframe is needed");
  double shortest = duration_;
  for (int i = 0; i + 1 < n_key; ++i)
    shortest = std::min(shortest, given_times_[i + 1] - given_times_[i]);
  time_gap_ = std::min(options.min_time_gap, 0.5 * shortest);

  sample_times_ = uniform_times(duration_, options.samples);
  if (options.quadrature_nodes < 1 || !(options.quadrature_spacing > 0))
    throw std::invalid_argument("the quadrature needs at least one node per knot span");

  int threads = options.threads > 0
                    ? options.threads
                    : std::min(4, static_cast<int>(std::thread::hardware_concurrency()));
  // A thread below ~20 evaluations costs more to start than it saves.
  const int evaluations =
      std::max(options.samples, std::max((layout_.control_count() - 3) * options.quadrature_nodes,
                                         static_cast<int>(duration_ / options.quadrature_spacing)));
  threads = std::max(1, std::min(threads, evaluations / 20));
  at_ = std::make_unique<NlpEvaluations>(model, layout_, reference_, threads);
  band_ = HessianBand(layout_);
  targets_ = std::make_unique<KeyframeTargets>(motion, model);

  // The objective: the terms each formulation sums, in order.
  const bool relaxed = options.formulation == Formulation::kRelaxed;
  auto add_term = [this](std::unique_ptr<ObjectiveTerm> term) {
    objective_.push_back(term.get());
    owned_terms_.push_back(std::move(term));
  };
  auto root_wrench = std::make_unique<RootWrenchTerm>(
      SpanQuadrature(layout_, initial.knots, options.quadrature_nodes, options.quadrature_spacing),
      duration_, &damping_, relaxed ? options.root_moment_weight : 1.0);
  root_wrench_ = root_wrench.get();
  if (relaxed) {
    add_term(std::move(root_wrench));
    if (options.keyframe_weight > 0) {
      const double e1 = std::max(motion.tolerances.translation_m, 1e-9);
      const double e2 = std::max(motion.tolerances.quaternion, 1e-9);
      add_term(std::make_unique<KeyframeDistanceTerm>(
          *targets_, options.keyframe_weight / (e1 * e1), options.keyframe_weight / (e2 * e2)));
    }
  } else {
    owned_terms_.push_back(std::move(root_wrench));  // reported, not minimised
    add_term(std::make_unique<KeyframeDistanceTerm>(*targets_));
  }
  if (options.regularization > 0)
    add_term(std::make_unique<ProximityTerm>(layout_, options.regularization));
  if (relaxed && options.joint_effort > 0)
    add_term(std::make_unique<JointAccelerationTerm>(layout_, model, initial.knots,
                                                     options.joint_effort));
  if (relaxed && options.joint_load_weight > 0)
    add_term(std::make_unique<JointLoadTerm>(layout_, initial.knots, duration_,
                                             options.joint_load_weight, options.joint_load_scales));
  if (options.limits_joint_turns())
    add_term(std::make_unique<JointTurnTerm>(layout_, reference_, options.joint_turn_limit,
                                             options.joint_turn_weight));

  // The constraints: keyframe rows in units of their tolerance, with bounds kKeyframeBoundMargin
  // inside it (the solver may stop at a point that violates its bounds by half that, see
  // SolverOptions::acceptable_constraint_violation, and the written motion must still meet ε1
  // and ε2).
  const double bound = 1.0 - kKeyframeBoundMargin;
  owned_blocks_.push_back(std::make_unique<KeyframeTranslationBlock>(
      layout_, *targets_, motion.tolerances.translation_m, bound));
  owned_blocks_.push_back(std::make_unique<KeyframeRotationBlock>(
      layout_, *targets_, motion.tolerances.quaternion, bound));
  if (layout_.optimize_timing)
    owned_blocks_.push_back(std::make_unique<TimeOrderBlock>(layout_, time_gap_));
  if (!options.joint_moment_bounds.empty())
    owned_blocks_.push_back(std::make_unique<JointBoundBlock>(
        model, layout_, options.joint_moment_bounds, options.joint_force_bounds));
  if (!relaxed) {
    // A sample's span can change when the times move: its row covers every span it can reach
    // within the time bounds (exactly one span when timing is fixed).
    std::vector<double> x_lower(layout_.size()), x_upper(layout_.size());
    variable_bounds(x_lower.data(), x_upper.data());
    const auto knots_at = [&](const std::vector<double>& x) {
      return clamped_cubic_knots(refine_breakpoints(
          keyframe_times_from(layout_, reference_, x.data()), layout_.subdivisions()));
    };
    owned_blocks_.push_back(std::make_unique<ForceBoundBlock>(
        layout_, sample_times_, knots_at(x_lower), knots_at(x_upper), options.epsilon));
  }
  for (const auto& block : owned_blocks_) {
    constraint_.push_back(block.get());
    block_row_.push_back(rows_);
    block_entry_.push_back(static_cast<int>(jacobian_columns_.size()));
    for (const std::vector<int>& columns : block->sparsity()) {
      for (int c : columns) {
        jacobian_rows_.push_back(rows_);
        jacobian_columns_.push_back(c);
      }
      ++rows_;
    }
    if (rows_ - block_row_.back() != block->rows())
      throw std::logic_error(block->name() + ": sparsity does not match its row count");
  }
}

MotionNlp::~MotionNlp() = default;

void MotionNlp::variable_bounds(double* x_lower, double* x_upper) const {
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
    const double t0 = given_times_[i];
    x_lower[v] = std::max(t0 - options_.max_time_shift, time_gap_ * i);
    x_upper[v] = std::min(t0 + options_.max_time_shift,
                          duration_ - time_gap_ * (layout_.keyframe_count - 1 - i));
  }
}

void MotionNlp::bounds(double* x_lower, double* x_upper, double* g_lower, double* g_upper) const {
  variable_bounds(x_lower, x_upper);
  for (std::size_t b = 0; b < constraint_.size(); ++b)
    constraint_[b]->bounds(g_lower + block_row_[b], g_upper + block_row_[b]);
}

void MotionNlp::initial_point(double* x) const {
  std::copy(initial_x_.begin(), initial_x_.end(), x);
}

double MotionNlp::force_objective(const double* x) {
  at_->load(x);
  return root_wrench_->unweighted_value(*at_);
}

double MotionNlp::objective(const double* x) {
  at_->load(x);
  // The formulation's own term plus the regularising ones, these summed apart first: they are
  // small against it, and their sum keeps its digits.
  double regularization = 0.0;
  for (std::size_t t = 1; t < objective_.size(); ++t)
    regularization += objective_[t]->value(*at_);
  return objective_.front()->value(*at_) + regularization;
}

void MotionNlp::gradient(const double* x, double* out) {
  // Cached per point: Ipopt asks for it once per iteration and the Hessian's objective model
  // (hessian_values) needs it at the same point.
  at_->load(x);
  if (gradient_generation_ != at_->generation()) {
    gradient_.assign(layout_.size(), 0.0);
    for (ObjectiveTerm* term : objective_)
      term->add_gradient(*at_, gradient_.data());
    gradient_generation_ = at_->generation();
  }
  std::copy(gradient_.begin(), gradient_.end(), out);
}

void MotionNlp::constraints(const double* x, double* g) {
  at_->load(x);
  for (std::size_t b = 0; b < constraint_.size(); ++b)
    constraint_[b]->values(*at_, g + block_row_[b]);
}

void MotionNlp::jacobian_structure(int* rows, int* columns) const {
  std::copy(jacobian_rows_.begin(), jacobian_rows_.end(), rows);
  std::copy(jacobian_columns_.begin(), jacobian_columns_.end(), columns);
}

void MotionNlp::jacobian_values(const double* x, double* values) {
  at_->load(x);
  for (std::size_t b = 0; b < constraint_.size(); ++b)
    constraint_[b]->jacobian(*at_, values + block_entry_[b]);
}

void MotionNlp::hessian_structure(int* rows, int* columns) const {
  band_.structure(rows, columns);
}

void MotionNlp::hessian_values(const double* x, double objective_factor, const double* multipliers,
                               double* values) {
  at_->load(x);
  std::fill(values, values + band_.nonzeros(), 0.0);
  at_->need_keyframe_derivatives();
  const bool relaxed = options_.formulation == Formulation::kRelaxed;
  const bool adapting = relaxed && options_.adapt_damping && objective_factor > 0;
  if (relaxed) {
    // The damping's factor μ follows how well the last step was predicted (judged on the
    // derivatives' values, so computed first).
    root_wrench_->prepare_derivatives(*at_);
    if (adapting && last_model_.valid) judge_last_step(x);
  }
  for (ObjectiveTerm* term : objective_)
    term->add_curvature(*at_, objective_factor, band_, values);
  if (adapting) {
    // Keep the objective's model (before the constraints' curvature joins it) for the next step.
    last_model_.x.assign(x, x + layout_.size());
    last_model_.gradient.resize(layout_.size());
    gradient(x, last_model_.gradient.data());
    last_model_.hessian.assign(values, values + band_.nonzeros());
    for (double& h : last_model_.hessian)
      h /= objective_factor;
    last_model_.objective = objective(x);
    last_model_.valid = true;
  }
  for (std::size_t b = 0; b < constraint_.size(); ++b)
    constraint_[b]->add_curvature(*at_, multipliers + block_row_[b], band_, values);
}

std::vector<double> MotionNlp::keyframe_time_spreads(const double* x, double rise) {
  const int n = layout_.size();
  at_->load(x);
  at_->need_keyframe_derivatives();
  std::vector<double> values(band_.nonzeros(), 0.0);
  if (root_wrench_) root_wrench_->prepare_derivatives(*at_);
  for (ObjectiveTerm* term : objective_)
    term->add_curvature(*at_, 1.0, band_, values.data());
  if (root_wrench_ && options_.formulation == Formulation::kRelaxed) {
    // The root wrench term adds μ·J to the diagonal (the solver's damping); take it out.
    const double damping = damping_.factor() * root_wrench_->value(*at_);
    for (int v = 0; v < n; ++v)
      values[band_.index(v, v)] -= damping;
  }
  std::vector<int> rows(band_.nonzeros()), columns(band_.nonzeros());
  band_.structure(rows.data(), columns.data());
  std::vector<Eigen::Triplet<double>> triplets;
  for (int e = 0; e < band_.nonzeros(); ++e)
    triplets.emplace_back(std::max(rows[e], columns[e]), std::min(rows[e], columns[e]), values[e]);
  Eigen::SparseMatrix<double> lower(n, n);
  lower.setFromTriplets(triplets.begin(), triplets.end());
  // Each constraint as a quadratic wall that costs `rise` where the constraint uses up the
  // slack it has at x (a constraint at its bound: a slack of 1e-6, nearly an equality).
  const int m = rows_;
  std::vector<double> g(m), g_lower(m), g_upper(m), x_lower(n), x_upper(n);
  constraints(x, g.data());
  bounds(x_lower.data(), x_upper.data(), g_lower.data(), g_upper.data());
  std::vector<int> jacobian_rows(jacobian_nonzeros()), jacobian_cols(jacobian_nonzeros());
  std::vector<double> jacobian(jacobian_nonzeros());
  jacobian_structure(jacobian_rows.data(), jacobian_cols.data());
  jacobian_values(x, jacobian.data());
  std::vector<Eigen::Triplet<double>> weighted;
  for (int e = 0; e < jacobian_nonzeros(); ++e) {
    const int row = jacobian_rows[e];
    const double slack =
        std::max(1e-6, std::min(std::abs(g[row] - g_lower[row]), std::abs(g_upper[row] - g[row])));
    weighted.emplace_back(row, jacobian_cols[e], jacobian[e] * std::sqrt(rise) / slack);
  }
  Eigen::SparseMatrix<double> walls(m, n);
  walls.setFromTriplets(weighted.begin(), weighted.end());
  // The factorization reads the lower triangle only. In the layout's order (control-major,
  // times last) the matrix is a band with a border of keyframe-time rows, which the natural
  // order factors without fill outside them: M7's 2489 variables in 20 ms, 31 ms after AMD.
  const Eigen::SparseMatrix<double> wall_curvature = walls.transpose() * walls;
  const Eigen::SparseMatrix<double> hessian =
      lower + Eigen::SparseMatrix<double>(wall_curvature.triangularView<Eigen::Lower>());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower,
                              Eigen::NaturalOrdering<int>>
      ldlt(hessian);
  std::vector<double> spreads(layout_.keyframe_count, 0.0);
  for (int i = 0; i < layout_.keyframe_count; ++i) {
    const int v = layout_.time_variable(i);
    if (v < 0) continue;
    double spread = options_.max_time_shift;  // a flat direction: nothing pins the time
    if (ldlt.info() == Eigen::Success) {
      const Eigen::VectorXd unit = Eigen::VectorXd::Unit(n, v);
      const double inverse = ldlt.solve(unit)(v);
      if (inverse > 0 && std::isfinite(inverse))
        spread = std::min(spread, std::sqrt(2.0 * rise * inverse));
    }
    spreads[i] = spread;
  }
  return spreads;
}

void MotionNlp::step_taken(const StepTaken& step) {
  // A new run starts from scratch; a restoration step optimised something else (feasibility),
  // so the model kept before it says nothing about it.
  if (step.iteration == 0) damping_.reset();
  if (step.iteration == 0 || step.restoration) last_model_.valid = false;
  last_step_ = step;
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
  const double quadratic = band_.quadratic_form(last_model_.hessian, step.data());
  double slope = 0.0;
  for (int v = 0; v < n; ++v)
    slope += last_model_.gradient[v] * step[v];
  const double predicted = -(slope + 0.5 * quadratic);
  const double actual = last_model_.objective - objective(x);
  // A step the model says goes uphill was taken for feasibility (Ipopt trades objective for
  // constraint violation): counted as poorly predicted, so that μ grows while the keyframe
  // constraints are being restored.
  const double ratio = predicted > 0 ? actual / predicted : -1.0;
  damping_.update(ratio, last_step_.line_search_trials > 1);
}

}  // namespace saltus
