#include "saltus/math/quaternion_spline.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "saltus/math/banded_ldlt.h"

namespace saltus {

namespace {

/// Forward-mode scalar for one residual block: the 4 active control points of a span, 3 tangent
/// coordinates each (the smoothness residuals use the first 9).
using Ad = Eigen::AutoDiffScalar<Eigen::Matrix<double, 12, 1>>;

/// The fit problem with its inputs validated, sorted by time and sign-aligned.
struct FitProblem {
  std::vector<double> knots;
  std::vector<SpanBasis<double>> bases;  ///< basis at each target time
  std::vector<Quat<double>> targets;     ///< sorted by time, sign-aligned to their predecessor
  std::vector<double> times;             ///< sorted
  double sqrt_weight = 0.0;              ///< sqrt(smoothness_weight)
  /// h̄/(τ_j − τ_{j−1}) for j >= 1 (index 0 unused): Greville spacing normalised by its mean h̄.
  std::vector<double> rate_scale;
  int controls = 0;

  int target_rows() const { return 3 * static_cast<int>(targets.size()); }
  int smoothness_rows() const { return 3 * std::max(controls - 2, 0); }
  int rows() const { return target_rows() + smoothness_rows(); }
  int cols() const { return 3 * controls; }
};

void sign_align(std::vector<Quat<double>>& q) {
  for (std::size_t i = 1; i < q.size(); ++i)
    if (q[i - 1].coeffs().dot(q[i].coeffs()) < 0.0) q[i].coeffs() = -q[i].coeffs();
}

SpanBasis<Ad> to_ad(const SpanBasis<double>& b) {
  SpanBasis<Ad> out;
  out.span = b.span;
  for (int d = 0; d < 3; ++d) {
    for (int j = 0; j < 4; ++j) {
      out.value[d][j] = Ad(b.value[d][j]);
      out.cumulative[d][j] = Ad(b.cumulative[d][j]);
    }
  }
  return out;
}

/// q·exp(δ) with δ = 0 seeded as derivative directions 3·slot .. 3·slot + 2: the local tangent
/// coordinates of docs/method.md.
Quat<Ad> seeded(const Quat<double>& q, int slot) {
  Vec3<Ad> delta;
  for (int k = 0; k < 3; ++k)
    delta[k] = Ad(0.0, 12, 3 * slot + k);
  return Quat<Ad>(q.cast<Ad>()) * quat_exp(delta);
}

/// log(target⁻¹ q) with the target's sign chosen nearest to q: half the rotation vector of the
/// keyframe error, independent of the quaternions' signs.
template <typename Scalar>
Vec3<Scalar> keyframe_error(const Quat<double>& target, const Quat<Scalar>& q) {
  Quat<Scalar> d = Quat<Scalar>(target.conjugate().cast<Scalar>()) * q;
  if (value_of(d.w()) < 0.0) d.coeffs() = -d.coeffs();
  return quat_log(d);
}

/// The smoothness residual of QuaternionFitOptions for controls j−1, j, j+1:
/// w_{j+1}·σ_{j+1} − w_j·σ_j with w_j = log(q_{j−1}⁻¹ q_j) and σ_j = h̄/(τ_j − τ_{j−1}).
/// With uniform Greville spacing this is w_{j+1} − w_j. The spacing makes w_j/(τ_j − τ_{j−1})
/// a rate: a curve turning at constant angular velocity about a fixed axis has w_j proportional
/// to τ_j − τ_{j−1} (linear precision of B-splines, Σ τ_j B_j(t) = t), so it costs nothing, while
/// the plain difference would penalise the short control intervals at the clamped ends and push
/// the fit to spin fast at t = 0 and t = T.
template <typename Scalar>
Vec3<Scalar> control_difference(const FitProblem& p, int j, const Quat<Scalar>& a,
                                const Quat<Scalar>& b, const Quat<Scalar>& c) {
  return quat_log(Quat<Scalar>(b.conjugate() * c)) * Scalar(p.rate_scale[j + 1]) -
         quat_log(Quat<Scalar>(a.conjugate() * b)) * Scalar(p.rate_scale[j]);
}

Eigen::VectorXd residuals(const FitProblem& p, const std::vector<Quat<double>>& q) {
  Eigen::VectorXd r(p.rows());
  for (std::size_t i = 0; i < p.targets.size(); ++i) {
    const int f = p.bases[i].first_control();
    const QuaternionSample<double> sample =
        evaluate_quaternion_span(q[f], q[f + 1], q[f + 2], q[f + 3], p.bases[i]);
    r.segment<3>(3 * i) = keyframe_error(p.targets[i], sample.q);
  }
  for (int j = 1; j + 1 < p.controls; ++j)
    r.segment<3>(p.target_rows() + 3 * (j - 1)) =
        p.sqrt_weight * control_difference(p, j, q[j - 1], q[j], q[j + 1]);
  return r;
}

/// The Jacobian of the fit's residuals, row by row: each row's non-zero entries are the columns
/// first[row] .. first[row] + width[row] − 1 (4 control points × 3 tangent coordinates for a
/// keyframe row, 3 × 3 for a smoothness row), so a fit of m keyframes costs O(m) to linearise.
struct SparseJacobian {
  static constexpr int kMaxWidth = 12;
  /// Sub-diagonals of JᵀJ: columns of one row are at most kMaxWidth − 1 apart.
  static constexpr int kNormalBandwidth = kMaxWidth - 1;
  Eigen::Matrix<double, Eigen::Dynamic, kMaxWidth, Eigen::RowMajor> values;
  std::vector<int> first;
  std::vector<int> width;

  void resize(int rows) {
    values.setZero(rows, kMaxWidth);
    first.assign(static_cast<std::size_t>(rows), 0);
    width.assign(static_cast<std::size_t>(rows), 0);
  }
  int rows() const { return static_cast<int>(first.size()); }
  double row_dot(int row, const Eigen::VectorXd& x) const {
    double sum = 0.0;
    for (int k = 0; k < width[row]; ++k)
      sum += values(row, k) * x[first[row] + k];
    return sum;
  }
  /// Jᵀ·r over the first `rows` rows.
  Eigen::VectorXd transpose_times(const Eigen::VectorXd& r, int rows, int cols) const {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(cols);
    for (int row = 0; row < rows; ++row)
      for (int k = 0; k < width[row]; ++k)
        out[first[row] + k] += values(row, k) * r[row];
    return out;
  }
  /// JᵀJ as a band matrix.
  BandedLdlt normal(int cols) const {
    BandedLdlt out(cols, kNormalBandwidth);
    for (int row = 0; row < rows(); ++row)
      for (int a = 0; a < width[row]; ++a)
        for (int b = 0; b <= a; ++b)
          out(first[row] + a, first[row] + b) += values(row, a) * values(row, b);
    return out;
  }
};

/// Residuals and their exact Jacobian with respect to the tangent coordinates δ (forward AD).
void linearise(const FitProblem& p, const std::vector<Quat<double>>& q, Eigen::VectorXd& r,
               SparseJacobian& jacobian) {
  r.resize(p.rows());
  jacobian.resize(p.rows());
  for (std::size_t i = 0; i < p.targets.size(); ++i) {
    const int f = p.bases[i].first_control();
    const QuaternionSample<Ad> sample =
        evaluate_quaternion_span(seeded(q[f], 0), seeded(q[f + 1], 1), seeded(q[f + 2], 2),
                                 seeded(q[f + 3], 3), to_ad(p.bases[i]));
    const Vec3<Ad> e = keyframe_error(p.targets[i], sample.q);
    for (int k = 0; k < 3; ++k) {
      const int row = 3 * static_cast<int>(i) + k;
      r[row] = e[k].value();
      jacobian.first[row] = 3 * f;
      jacobian.width[row] = 12;
      jacobian.values.row(row) = e[k].derivatives().transpose();
    }
  }
  for (int j = 1; j + 1 < p.controls; ++j) {
    const Vec3<Ad> s =
        control_difference(p, j, seeded(q[j - 1], 0), seeded(q[j], 1), seeded(q[j + 1], 2));
    for (int k = 0; k < 3; ++k) {
      const int row = p.target_rows() + 3 * (j - 1) + k;
      r[row] = p.sqrt_weight * s[k].value();
      jacobian.first[row] = 3 * (j - 1);
      jacobian.width[row] = 9;
      jacobian.values.row(row).head<9>() = p.sqrt_weight * s[k].derivatives().head<9>().transpose();
    }
  }
}

/// The minimum-norm solution δ = J_rᵀ (J_r J_rᵀ)⁻¹ r of J_r δ = r, J_r the first `rows` rows
/// (the keyframe rows, sorted by time, so J_r J_rᵀ is banded too: two keyframes interact when
/// their spans share a control point). Returns an empty vector when J_r J_rᵀ is singular to
/// working precision (the keyframes cannot all be met exactly).
Eigen::VectorXd minimum_norm_step(const SparseJacobian& jacobian, const Eigen::VectorXd& r,
                                  int rows, int cols) {
  int bandwidth = 0;
  for (int a = 0; a < rows; ++a)
    for (int b = a + 1; b < rows && jacobian.first[b] < jacobian.first[a] + jacobian.width[a]; ++b)
      bandwidth = std::max(bandwidth, b - a);
  BandedLdlt gram(rows, bandwidth);
  for (int a = 0; a < rows; ++a) {
    for (int b = std::max(0, a - bandwidth); b <= a; ++b) {
      const int begin = std::max(jacobian.first[a], jacobian.first[b]);
      const int end =
          std::min(jacobian.first[a] + jacobian.width[a], jacobian.first[b] + jacobian.width[b]);
      double sum = 0.0;
      for (int c = begin; c < end; ++c)
        sum +=
            jacobian.values(a, c - jacobian.first[a]) * jacobian.values(b, c - jacobian.first[b]);
      gram(a, b) = sum;
    }
  }
  // J_r J_rᵀ squares J_r's condition number: a pivot below 1e-12 of the largest means J_r's
  // smallest singular value is below 1e-6 of its largest, where the dense complete orthogonal
  // decomposition this replaces was already unreliable; the projection then stops.
  if (!gram.factorize() || !(gram.pivots().minCoeff() > 1e-12 * gram.pivots().maxCoeff()))
    return {};
  const Eigen::VectorXd y = gram.solve(r.head(rows));
  return jacobian.transpose_times(y, rows, cols);
}

/// q_j ← q_j·exp(δ_j), renormalised against rounding drift. Not sign-aligned: the sign of a
/// control point is part of the curve (w_j = log(q_{j−1}⁻¹ q_j) takes the long way round when
/// the dot product is negative), so flipping one mid-iteration would make the residuals jump.
std::vector<Quat<double>> retract(const std::vector<Quat<double>>& q, const Eigen::VectorXd& step) {
  std::vector<Quat<double>> out(q.size());
  for (std::size_t j = 0; j < q.size(); ++j)
    out[j] = (q[j] * quat_exp<double>(step.segment<3>(3 * j))).normalized();
  return out;
}

/// Initial control points (paper §5.2): at each control point's Greville abscissa
/// τ_j = (k_{j+1} + k_{j+2} + k_{j+3})/3, the slerp of the two targets around it.
std::vector<Quat<double>> initial_control(const FitProblem& p) {
  std::vector<Quat<double>> q(p.controls);
  const std::size_t m = p.targets.size();
  for (int j = 0; j < p.controls; ++j) {
    const double tau = (p.knots[j + 1] + p.knots[j + 2] + p.knots[j + 3]) / 3.0;
    if (tau <= p.times.front()) {
      q[j] = p.targets.front();
    } else if (tau >= p.times.back()) {
      q[j] = p.targets.back();
    } else {
      const std::size_t hi = static_cast<std::size_t>(
          std::upper_bound(p.times.begin(), p.times.end(), tau) - p.times.begin());
      const std::size_t lo = hi - 1;
      const double gap = p.times[hi] - p.times[lo];
      const double u = gap > 0.0 ? (tau - p.times[lo]) / gap : 0.0;
      q[j] = p.targets[lo].slerp(u, p.targets[std::min(hi, m - 1)]).normalized();
    }
  }
  sign_align(q);
  return q;
}

FitProblem make_problem(const std::vector<double>& knots, const std::vector<double>& times,
                        const std::vector<Quat<double>>& targets,
                        const QuaternionFitOptions& options) {
  if (knots.size() < 8)
    throw std::invalid_argument(
        "fit_quaternion_spline: a cubic knot vector needs at least 8 "
        "knots, got " +
        std::to_string(knots.size()));
  if (times.size() != targets.size())
    throw std::invalid_argument("fit_quaternion_spline: " + std::to_string(times.size()) +
                                " times but " + std::to_string(targets.size()) + " targets");
  if (targets.empty()) throw std::invalid_argument("fit_quaternion_spline: no targets to fit");
  if (!(options.smoothness_weight >= 0.0))
    throw std::invalid_argument("fit_quaternion_spline: smoothness_weight must be non-negative");
  FitProblem p;
  p.knots = knots;
  p.controls = control_count(knots);
  const double t_begin = knots[3];
  const double t_end = knots[p.controls];
  std::vector<std::size_t> order(times.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return times[a] < times[b]; });
  for (const std::size_t i : order) {
    const double t = times[i];
    if (!(t >= t_begin && t <= t_end))
      throw std::invalid_argument("fit_quaternion_spline: time " + std::to_string(t) +
                                  " outside the knot range [" + std::to_string(t_begin) + ", " +
                                  std::to_string(t_end) + "]");
    const double norm = targets[i].norm();
    if (!(norm > 0.0) || !std::isfinite(norm))
      throw std::invalid_argument("fit_quaternion_spline: target " + std::to_string(i) +
                                  " is not a valid quaternion");
    p.times.push_back(t);
    p.targets.push_back(targets[i].normalized());
    p.bases.push_back(cubic_basis(knots, t));
  }
  sign_align(p.targets);
  p.sqrt_weight = std::sqrt(options.smoothness_weight);
  std::vector<double> greville(p.controls);
  for (int j = 0; j < p.controls; ++j)
    greville[j] = (knots[j + 1] + knots[j + 2] + knots[j + 3]) / 3.0;
  const double mean_spacing = (greville.back() - greville.front()) / (p.controls - 1);
  p.rate_scale.assign(p.controls, 0.0);
  for (int j = 1; j < p.controls; ++j) {
    const double spacing = greville[j] - greville[j - 1];
    if (!(spacing > 0.0))
      throw std::invalid_argument(
          "fit_quaternion_spline: the knots must increase strictly between the clamped ends");
    p.rate_scale[j] = mean_spacing / spacing;
  }
  return p;
}

}  // namespace

std::vector<Quat<double>> fit_quaternion_spline(const std::vector<double>& knots,
                                                const std::vector<double>& times,
                                                const std::vector<Quat<double>>& targets,
                                                const QuaternionFitOptions& options) {
  const FitProblem p = make_problem(knots, times, targets, options);
  std::vector<Quat<double>> q = initial_control(p);

  // Phase 1: Levenberg-Marquardt on ‖r‖² + λ Σ‖w_{j+1} − w_j‖² (damping update of Nielsen 1999,
  // as in Madsen, Nielsen & Tingleff, "Methods for non-linear least squares problems", §3.2).
  // The normal matrix JᵀJ is a band (SparseJacobian::kNormalBandwidth): every step costs O(m).
  Eigen::VectorXd r;
  SparseJacobian jacobian;
  linearise(p, q, r, jacobian);
  double cost = r.squaredNorm();
  BandedLdlt normal = jacobian.normal(p.cols());
  Eigen::VectorXd gradient = jacobian.transpose_times(r, p.rows(), p.cols());
  double mu = 1e-6 * std::max(normal.max_diagonal(), 1e-12);
  double nu = 2.0;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    BandedLdlt damped = normal;
    damped.add_to_diagonal(mu);
    if (!damped.factorize()) break;
    const Eigen::VectorXd step = damped.solve(-gradient);
    if (!step.allFinite()) break;
    if (step.norm() < options.tolerance) break;
    const std::vector<Quat<double>> candidate = retract(q, step);
    const double candidate_cost = residuals(p, candidate).squaredNorm();
    double linearised_cost = 0.0;
    for (int row = 0; row < p.rows(); ++row) {
      const double value = r[row] + jacobian.row_dot(row, step);
      linearised_cost += value * value;
    }
    const double predicted = cost - linearised_cost;
    const double rho = predicted > 0.0 ? (cost - candidate_cost) / predicted : -1.0;
    if (rho > 0.0 && std::isfinite(candidate_cost)) {
      q = candidate;
      linearise(p, q, r, jacobian);
      cost = r.squaredNorm();
      normal = jacobian.normal(p.cols());
      gradient = jacobian.transpose_times(r, p.rows(), p.cols());
      mu *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3));
      nu = 2.0;
    } else {
      mu *= nu;
      nu *= 2.0;
    }
  }

  // Phase 2: the penalty optimum misses the keyframes by O(λ). When the keyframes can be met
  // exactly (no more target rows than unknowns, full row rank), project onto them with
  // minimum-norm Gauss-Newton steps δ = −J_r⁺ r: the curve then interpolates to rounding while
  // moving the controls only O(λ) away from the smoothest fit.
  if (p.target_rows() <= p.cols()) {
    const int rows = p.target_rows();
    for (int iteration = 0; iteration < 20; ++iteration) {
      linearise(p, q, r, jacobian);
      const Eigen::VectorXd r_target = r.head(rows);
      const double error = r_target.norm();
      if (error < 1e-15) break;
      const Eigen::VectorXd step = -minimum_norm_step(jacobian, r_target, rows, p.cols());
      if (step.size() == 0 || !step.allFinite()) break;
      const std::vector<Quat<double>> candidate = retract(q, step);
      if (!(residuals(p, candidate).head(rows).norm() < error)) break;
      q = candidate;
      if (step.norm() < options.tolerance) break;
    }
  }
  // The start was sign-aligned and the iterations move the controls continuously, so the result
  // stays aligned unless the keyframes force more than 180° between two consecutive controls
  // (a fast turn over a short knot interval). Then the negative dot product is what the curve
  // needs and is returned as is: flipping it would change the curve.
  return q;
}

}  // namespace saltus
