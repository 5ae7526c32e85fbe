#pragma once
/// @file
/// What the objective terms and constraint blocks share at one point x, each computed at most
/// once per point and in parallel on a worker pool: the keyframe times, the root translation and
/// every rotation at the keyframes (values alone for line-search trial points, or with their
/// derivatives), and the root wrench at sample times. Ipopt asks for the objective, gradient,
/// constraints, Jacobian and Hessian at the same x in separate calls; this is where they meet.
///
/// Results do not depend on the thread count: each part of a task fills its own entries.

#include <memory>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/optim/root_wrench_derivatives.h"
#include "saltus/optim/trajectory_layout.h"
#include "saltus/optim/worker_pool.h"

namespace saltus {

class NlpEvaluations {
 public:
  /// @param threads  evaluation threads (>= 1); each gets its own evaluator and workspace
  NlpEvaluations(const BodyModel& model, const TrajectoryLayout& layout,
                 const TrajectoryReference& reference, int threads);
  ~NlpEvaluations();

  const TrajectoryLayout& layout() const { return layout_; }
  const TrajectoryReference& reference() const { return reference_; }

  /// Makes x the current point; a no-op when it is the current one already.
  void load(const double* x);
  const double* x() const { return x_.data(); }
  /// Bumped whenever the point changes: caches of the terms compare it.
  long generation() const { return generation_; }

  /// Keyframe times at the current point (s).
  const std::vector<double>& keyframe_times() const { return keyframe_times_; }

  /// Keyframe i's root translation and segment k's rotation (w, x, y, z) at its time: values
  /// only (`value` members), or values and derivatives.
  void need_keyframe_values();
  void need_keyframe_derivatives();
  const LocalJacobian<3>& keyframe_translation(int keyframe) const {
    return translation_[keyframe];
  }
  const LocalJacobian<4>& keyframe_rotation(int keyframe, int segment) const {
    return rotation_[keyframe * layout_.segment_count + segment];
  }

  int parts() const { return pool_->parts(); }
  /// Runs body(part, evaluator, first, end) over [0, count) split into contiguous ranges, one
  /// per pool part; each part has its own evaluator (loaded with the current point).
  template <typename Body>
  void for_each_range(int count, Body&& body) {
    const int parts = pool_->parts();
    pool_->run([&](int p) {
      const int begin = count * p / parts, end = count * (p + 1) / parts;
      if (begin < end) body(p, *evaluators_[p], begin, end);
    });
  }
  RootWrenchDerivatives& evaluator(int part = 0) { return *evaluators_[part]; }

 private:
  TrajectoryLayout layout_;
  TrajectoryReference reference_;
  std::vector<std::unique_ptr<RootWrenchDerivatives>> evaluators_;
  std::unique_ptr<WorkerPool> pool_;
  std::vector<double> x_;
  long generation_ = 0;
  std::vector<double> keyframe_times_;
  bool have_keyframe_values_ = false, have_keyframe_derivatives_ = false;
  std::vector<LocalJacobian<3>> translation_;  ///< [keyframe]
  std::vector<LocalJacobian<4>> rotation_;     ///< [keyframe * segments + segment]
};

/// The root wrench at fixed sample times and, on demand, its derivatives, cached per point.
class WrenchSamples {
 public:
  explicit WrenchSamples(std::vector<double> times) : times_(std::move(times)) {
    values_.resize(times_.size());
    jacobians_.resize(times_.size());
  }
  const std::vector<double>& times() const { return times_; }
  int size() const { return static_cast<int>(times_.size()); }
  /// F1..F6 at every sample time at the current point of `at`.
  const std::vector<Vector6d>& values(NlpEvaluations& at);
  /// The same with their derivatives (the values are those of values()).
  const std::vector<LocalJacobian<6>>& jacobians(NlpEvaluations& at);

 private:
  std::vector<double> times_;
  std::vector<Vector6d> values_;
  std::vector<LocalJacobian<6>> jacobians_;
  long values_generation_ = -1, jacobians_generation_ = -1;
};

/// The root wrench at Gauss–Lobatto nodes on every knot span (nodes that move with the knots
/// when the keyframe times move) and, on demand, its derivatives, cached per point. A node's
/// quadrature weight is (k_{s+1} − k_s)·ω / T; span_length_rates() gives how the span length
/// k_{s+1} − k_s moves with the keyframe times in each node's time slots.
class SpanQuadrature {
 public:
  struct Node {
    int span = 3;         ///< knot span s
    double xi = 0.5;      ///< t = k_s + ξ·(k_{s+1} − k_s)
    double weight = 1.0;  ///< the rule's weight on [0, 1]
  };
  /// Gauss–Lobatto nodes on every knot span of positive length: at least `min_nodes`, and
  /// enough that they are at most `max_spacing` apart on the span's length in `knots` (the
  /// starting knots: the nodes stay fixed in number while the knots move).
  SpanQuadrature(const TrajectoryLayout& layout, const std::vector<double>& knots, int min_nodes,
                 double max_spacing);

  const std::vector<Node>& nodes() const { return nodes_; }
  int size() const { return static_cast<int>(nodes_.size()); }
  /// Node n's time at the current point of `at` (s).
  double time(NlpEvaluations& at, int node) const;
  /// Node n's span length at the current point (s).
  double span_length(NlpEvaluations& at, int node) const;
  const std::vector<Vector6d>& values(NlpEvaluations& at);
  const std::vector<LocalJacobian<6>>& jacobians(NlpEvaluations& at);
  /// d(span length)/dτ per node, in the time slots of its jacobian (valid after jacobians()).
  const std::vector<Eigen::Matrix<double, 1, kMaxLocalTimes>>& span_length_rates() const {
    return span_length_rates_;
  }

 private:
  std::vector<Node> nodes_;
  std::vector<Vector6d> values_;
  std::vector<LocalJacobian<6>> jacobians_;
  std::vector<Eigen::Matrix<double, 1, kMaxLocalTimes>> span_length_rates_;
  long values_generation_ = -1, jacobians_generation_ = -1;
};

}  // namespace saltus
