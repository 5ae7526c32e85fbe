/// The closed-form span derivatives against forward-mode AD of the span evaluation itself
/// (detail::evaluate_span_from_logs), on random spans: turns from tiny (the series branches)
/// to nearly a half revolution per log, random basis values and random input directions.

#include "saltus/math/quaternion_span_derivatives.h"

#include <gtest/gtest.h>

#include <random>
#include <unsupported/Eigen/AutoDiff>

namespace saltus {
namespace {

constexpr int kCols = 7;
using Ad = Eigen::AutoDiffScalar<Eigen::Matrix<double, kCols, 1>>;

Ad with_derivative(double value, const Eigen::Matrix<double, 1, kCols>& row) {
  Ad a(value);
  a.derivatives() = row.transpose();
  return a;
}

struct Case {
  QuaternionSpanControls<kCols> controls;
  CumulativeBasisDerivatives<kCols> basis;
  QuaternionSample<Ad> ad;
};

/// Random inputs with logs of norm `scale`·U(0, 1), and the AD evaluation of the same span.
Case random_case(unsigned seed, double scale) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto vector = [&] { return Eigen::Vector3d(u(rng), u(rng), u(rng)); };
  Case c;
  QuaternionSpanControls<kCols>& in = c.controls;
  CumulativeBasisDerivatives<kCols>& cumulative = c.basis;
  in.first = Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng))).normalized();
  in.first_tangent.setRandom();
  for (int j = 0; j < 3; ++j) {
    in.logs[j] = vector().normalized() * scale * std::abs(u(rng));
    in.log_derivative[j].setRandom();
    for (int d = 0; d < 3; ++d) {
      cumulative.value[d][j] = d == 0 ? 0.5 + 0.5 * u(rng) : 5.0 * u(rng);
      cumulative.derivative[d][j].setRandom();
    }
  }
  // c₀(ε) = c₀·exp(θ₀ ε): an AD vector of value 0 whose derivatives are θ₀'s directions.
  Vec3<Ad> tangent;
  for (int i = 0; i < 3; ++i)
    tangent[i] = with_derivative(0.0, in.first_tangent.row(i));
  const Quat<Ad> first = in.first.cast<Ad>() * quat_exp(tangent);
  Vec3<Ad> logs[3];
  SpanBasis<Ad> basis;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i)
      logs[j][i] = with_derivative(in.logs[j][i], in.log_derivative[j].row(i));
    for (int d = 0; d < 3; ++d)
      basis.cumulative[d][j + 1] =
          with_derivative(cumulative.value[d][j], cumulative.derivative[d][j]);
  }
  c.ad = detail::evaluate_span_from_logs(first, logs, basis);
  return c;
}

void expect_matches_ad(const Case& c) {
  const QuaternionSpanDerivatives<kCols> closed = quaternion_span_derivatives(c.controls, c.basis);
  const Eigen::Quaterniond q(c.ad.q.w().value(), c.ad.q.x().value(), c.ad.q.y().value(),
                             c.ad.q.z().value());
  EXPECT_LT((closed.sample.q.coeffs() - q.coeffs()).norm(), 1e-14);
  for (int dir = 0; dir < kCols; ++dir) {
    const Eigen::Quaterniond dq(c.ad.q.w().derivatives()[dir], c.ad.q.x().derivatives()[dir],
                                c.ad.q.y().derivatives()[dir], c.ad.q.z().derivatives()[dir]);
    // q(ε) = q·exp(η ε) ⇒ dη = vec(q⁻¹ dq).
    const Eigen::Vector3d d_eta = (q.conjugate() * dq).vec();
    Eigen::Matrix<double, 9, 1> expected;
    for (int i = 0; i < 3; ++i) {
      expected[i] = d_eta[i];
      expected[3 + i] = c.ad.omega[i].derivatives()[dir];
      expected[6 + i] = c.ad.alpha[i].derivatives()[dir];
    }
    const double size = 1.0 + expected.norm();
    EXPECT_LT((closed.jacobian.col(dir) - expected).norm(), 1e-11 * size)
        << "direction " << dir << "\nclosed " << closed.jacobian.col(dir).transpose() << "\nAD     "
        << expected.transpose();
  }
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(closed.sample.omega[i], c.ad.omega[i].value(), 1e-12);
    EXPECT_NEAR(closed.sample.alpha[i], c.ad.alpha[i].value(), 1e-12);
  }
}

TEST(QuaternionSpanDerivatives, MatchAutomaticDifferentiationOfTheSpan) {
  for (unsigned seed = 1; seed <= 40; ++seed) {
    SCOPED_TRACE(seed);
    expect_matches_ad(random_case(seed, 1.5));
  }
}

TEST(QuaternionSpanDerivatives, MatchOnTinyTurnsWhereTheSeriesBranchesAct) {
  for (unsigned seed = 41; seed <= 60; ++seed) {
    SCOPED_TRACE(seed);
    expect_matches_ad(random_case(seed, 1e-5));
  }
}

TEST(QuaternionSpanDerivatives, MatchAtRestWithZeroLogs) {
  Case c = random_case(61, 0.0);
  expect_matches_ad(c);
}

}  // namespace
}  // namespace saltus
