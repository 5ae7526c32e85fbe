#pragma once
/// @file
/// The derivatives of one quaternion-spline span evaluation (detail::evaluate_span_from_logs)
/// in closed form, for the optimiser's spline stage: the sample's rotation tangent η
/// (q(ε) = q·exp(η)), ω and α, differentiated along `Cols` directions, given how the span's
/// inputs move along them — the first control's tangent θ₀ (c₀(ε) = c₀·exp(θ₀)), the relative
/// logs w_j and the cumulative basis values b_j, ḃ_j, b̈_j.
///
/// Forward-mode AD through the same code did this with a derivative vector on every scalar
/// operation; the closed form propagates 3 × Cols blocks through the product's recursion with
/// one 3 × 3 matrix per step (why: docs/optimizer.md, "Measurement history"). The recursion,
/// with E_j = exp(v_j), v_j = w_j b_j and dφ_j its right perturbation (E_j(ε) = E_j·exp(dφ_j)):
///   dφ_j = Jr(2 v_j) dv_j                (Jr: SO(3)'s right Jacobian of the rotation 2 v_j),
///   d(Rᵀx) = Rᵀ dx + 2 (Rᵀx) × dφ_j     for R = R(E_j),
///   η = R(E₀E₁E₂)ᵀ θ₀ + R(E₁E₂)ᵀ dφ₀ + R(E₂)ᵀ dφ₁ + dφ₂,
/// and ω, α as in evaluate_span_from_logs. Checked against AD of that function in
/// tests/unit/math/quaternion_span_derivatives_test.cpp.

#include <Eigen/Core>

#include "saltus/math/quaternion.h"
#include "saltus/math/quaternion_spline.h"

namespace saltus {

/// The span's controls as evaluate_span_from_logs takes them, and their derivatives along Cols
/// directions (they do not depend on t: computed once per span).
template <int Cols>
struct QuaternionSpanControls {
  using Block = Eigen::Matrix<double, 3, Cols>;
  Eigen::Quaterniond first;  ///< c₀
  Block first_tangent;       ///< dθ₀
  Eigen::Vector3d logs[3];   ///< w_j = log(c_j⁻¹ c_{j+1})
  Block log_derivative[3];   ///< dw_j
};

/// The cumulative basis at the sample and its derivatives along the same directions (shared by
/// every curve on the span).
template <int Cols>
struct CumulativeBasisDerivatives {
  /// value[d][j] = d-th time derivative of B̃ for log j (SpanBasis::cumulative[d][j + 1])
  double value[3][3];
  Eigen::Matrix<double, 1, Cols> derivative[3][3];
};

/// The sample (as evaluate_span_from_logs gives it) and its derivatives: rows 0-2 dη, 3-5 dω,
/// 6-8 dα.
template <int Cols>
struct QuaternionSpanDerivatives {
  QuaternionSample<double> sample;
  Eigen::Matrix<double, 9, Cols> jacobian;
};

namespace detail {

inline Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

/// dφ = J dv for exp(v) in the half-angle convention of quat_exp: Jr of the rotation θ = 2v,
///   Jr(θ) = I − (1 − cos a)/a² [θ]× + (a − sin a)/a³ [θ]×²,  a = |θ|.
inline Eigen::Matrix3d exp_right_jacobian(const Eigen::Vector3d& v) {
  const Eigen::Vector3d theta = 2.0 * v;
  const double a2 = theta.squaredNorm();
  double first, second;
  if (a2 < 1e-8) {
    first = 0.5 - a2 / 24.0;
    second = 1.0 / 6.0 - a2 / 120.0;
  } else {
    const double a = std::sqrt(a2);
    first = (1.0 - std::cos(a)) / a2;
    second = (a - std::sin(a)) / (a2 * a);
  }
  const Eigen::Matrix3d k = cross_matrix(theta);
  return Eigen::Matrix3d::Identity() - first * k + second * (k * k);
}

}  // namespace detail

template <int Cols>
QuaternionSpanDerivatives<Cols> quaternion_span_derivatives(
    const QuaternionSpanControls<Cols>& in, const CumulativeBasisDerivatives<Cols>& basis) {
  using Block = Eigen::Matrix<double, 3, Cols>;
  const double(&b)[3][3] = basis.value;
  const Eigen::Matrix<double, 1, Cols>(&db)[3][3] = basis.derivative;
  Eigen::Quaterniond step[3];
  Block perturbation[3];  // dφ_j
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d v = in.logs[j] * b[0][j];
    step[j] = quat_exp(v);
    const Block dv = in.log_derivative[j] * b[0][j] + in.logs[j] * db[0][j];
    perturbation[j].noalias() = detail::exp_right_jacobian(v) * dv;
  }
  QuaternionSpanDerivatives<Cols> out;
  Eigen::Vector3d omega = in.logs[0] * (2.0 * b[1][0]);
  Eigen::Vector3d alpha = in.logs[0] * (2.0 * b[2][0]);
  Block d_omega = 2.0 * (in.log_derivative[0] * b[1][0] + in.logs[0] * db[1][0]);
  Block d_alpha = 2.0 * (in.log_derivative[0] * b[2][0] + in.logs[0] * db[2][0]);
  for (int j = 1; j < 3; ++j) {
    const Eigen::Vector3d omega_step = in.logs[j] * (2.0 * b[1][j]);
    const Eigen::Vector3d alpha_step = in.logs[j] * (2.0 * b[2][j]);
    const Block d_omega_step = 2.0 * (in.log_derivative[j] * b[1][j] + in.logs[j] * db[1][j]);
    const Block d_alpha_step = 2.0 * (in.log_derivative[j] * b[2][j] + in.logs[j] * db[2][j]);
    const Eigen::Matrix3d rt = step[j].toRotationMatrix().transpose();
    const Eigen::Vector3d omega_rotated = rt * omega;
    const Eigen::Vector3d alpha_rotated = rt * alpha;
    Block d_omega_rotated = rt * d_omega;
    d_omega_rotated.noalias() += 2.0 * detail::cross_matrix(omega_rotated) * perturbation[j];
    Block d_alpha_rotated = rt * d_alpha;
    d_alpha_rotated.noalias() += 2.0 * detail::cross_matrix(alpha_rotated) * perturbation[j];
    // α ← Rᵀα − s × (Rᵀω) + a_step, s = omega_step: d(s × u) = ds × u + s × du.
    d_alpha = d_alpha_rotated + d_alpha_step;
    d_alpha.noalias() += detail::cross_matrix(omega_rotated) * d_omega_step;
    d_alpha.noalias() -= detail::cross_matrix(omega_step) * d_omega_rotated;
    alpha = alpha_rotated - omega_step.cross(omega_rotated) + alpha_step;
    d_omega = d_omega_rotated + d_omega_step;
    omega = omega_rotated + omega_step;
  }
  // η: each factor's perturbation carried to the right end of q = c₀·E₀·E₁·E₂.
  const Eigen::Matrix3d r2t = step[2].toRotationMatrix().transpose();
  const Eigen::Matrix3d r12t = (step[1] * step[2]).toRotationMatrix().transpose();
  const Eigen::Matrix3d r012t = (step[0] * step[1] * step[2]).toRotationMatrix().transpose();
  Block d_eta = perturbation[2];
  d_eta.noalias() += r2t * perturbation[1];
  d_eta.noalias() += r12t * perturbation[0];
  d_eta.noalias() += r012t * in.first_tangent;
  out.sample.q = in.first * step[0] * step[1] * step[2];
  out.sample.omega = omega;
  out.sample.alpha = alpha;
  out.jacobian.template topRows<3>() = d_eta;
  out.jacobian.template middleRows<3>(3) = d_omega;
  out.jacobian.template bottomRows<3>() = d_alpha;
  return out;
}

}  // namespace saltus
