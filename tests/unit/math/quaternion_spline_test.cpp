/// Tests of the Kim-Kim-Shin quaternion splines and their fit through keyframes (paper §5.2).
/// Every derivative is cross-checked by an independent path (finite differences, automatic
/// differentiation) rather than against stored numbers.

#include "saltus/math/quaternion_spline.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "saltus/math/quaternion.h"
#include "support/spline_fixtures.h"

namespace saltus {
namespace {

using test::AdDynamic;
using test::AdFixed;
using test::kNonUniformTimes;
using test::knots_for;

Quat<double> axis_angle(double angle, const Eigen::Vector3d& axis) {
  return Quat<double>(Eigen::AngleAxisd(angle, axis.normalized()));
}

/// Sign-aligned random control quaternions, each within `max_step` rad of its predecessor.
std::vector<Quat<double>> random_controls(int n, double max_step, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Quat<double>> q;
  q.push_back(Quat<double>(Eigen::Vector4d(uniform(rng), uniform(rng), uniform(rng), uniform(rng)))
                  .normalized());
  for (int j = 1; j < n; ++j) {
    const Eigen::Vector3d axis(uniform(rng), uniform(rng), uniform(rng));
    q.push_back(q.back() * axis_angle(max_step * std::abs(uniform(rng)), axis));
    if (q[j].coeffs().dot(q[j - 1].coeffs()) < 0) q[j].coeffs() *= -1.0;
  }
  return q;
}

/// Body angular velocity 2·vec(q* q̇) with q̇ from central differences of the curve.
Eigen::Vector3d omega_by_differences(const QuaternionSpline<double>& s, double t, double h) {
  const Quat<double> q = s.evaluate(t).q;
  const Eigen::Vector4d dq =
      (s.evaluate(t + h).q.coeffs() - s.evaluate(t - h).q.coeffs()) / (2 * h);
  return 2.0 * (q.conjugate() * Quat<double>(dq)).vec();
}

double max_rotation_error(const QuaternionSpline<double>& s, const std::vector<double>& times,
                          const std::vector<Quat<double>>& targets) {
  double worst = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i)
    worst = std::max(worst, rotation_angle_between(s.evaluate(times[i]).q, targets[i]));
  return worst;
}

QuaternionSpline<double> random_spline(int refine, unsigned seed, double max_step = 1.2) {
  const std::vector<double> k = knots_for(kNonUniformTimes, refine);
  return QuaternionSpline<double>(k, random_controls(control_count(k), max_step, seed));
}

TEST(QuaternionSpline, ConstructorChecksControlCount) {
  const std::vector<double> k = knots_for(kNonUniformTimes, 1);
  EXPECT_THROW(QuaternionSpline<double>(k, random_controls(control_count(k) - 1, 0.5, 1)),
               std::invalid_argument);
  EXPECT_NO_THROW(QuaternionSpline<double>(k, random_controls(control_count(k), 0.5, 1)));
}

TEST(QuaternionSpline, EvaluateMatchesSpanFunction) {
  // evaluate() uses the relative rotations cached by the constructor; the optimiser calls
  // evaluate_quaternion_span with raw control points. Both must agree.
  const QuaternionSpline<double> s = random_spline(3, 70);
  const auto& c = s.control();
  for (double t = 0.0; t <= 2.04; t += 0.0173) {
    const SpanBasis<double> b = cubic_basis(s.knots(), t);
    const int f = b.first_control();
    const QuaternionSample<double> x =
        evaluate_quaternion_span(c[f], c[f + 1], c[f + 2], c[f + 3], b);
    const QuaternionSample<double> y = s.evaluate(t);
    EXPECT_LT((x.q.coeffs() - y.q.coeffs()).norm(), 1e-15);
    EXPECT_LT((x.omega - y.omega).norm(), 1e-12);
    EXPECT_LT((x.alpha - y.alpha).norm(), 1e-10);
  }
}

TEST(QuaternionSpline, LargestControlTurnFollowsTheControlSigns) {
  // Turns of 0.3, 1.2 and 0.7 rad about different axes: the largest is 1.2. Flipping a control's
  // sign makes the curve take the long way between it and its neighbours (2π − angle), and a
  // control equal to minus its predecessor is a full turn: the log map's branch point.
  const std::vector<double> k = knots_for({0.0, 1.0, 2.0, 3.0}, 1);  // 6 controls
  std::vector<Quat<double>> c{Quat<double>::Identity()};
  const double angles[] = {0.3, 1.2, 0.7, 0.2, 0.4};
  const Eigen::Vector3d axes[] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                  Eigen::Vector3d::UnitZ(), Eigen::Vector3d(1, 1, 0),
                                  Eigen::Vector3d(0, 1, 1)};
  for (int j = 0; j < 5; ++j)
    c.push_back(c.back() * axis_angle(angles[j], axes[j]));
  EXPECT_NEAR(QuaternionSpline<double>(k, c).largest_control_turn(), 1.2, 1e-12);

  std::vector<Quat<double>> flipped = c;
  flipped[3].coeffs() *= -1.0;  // its turns 0.7 and 0.2 become 2π − 0.7 and 2π − 0.2
  EXPECT_NEAR(QuaternionSpline<double>(k, flipped).largest_control_turn(), 2 * M_PI - 0.2, 1e-12);

  std::vector<Quat<double>> full = c;
  full[4].coeffs() = -full[3].coeffs();
  EXPECT_NEAR(QuaternionSpline<double>(k, full).largest_control_turn(), 2 * M_PI, 1e-12);
}

TEST(QuaternionSpline, UnitNormAndEndInterpolation) {
  for (int refine = 1; refine <= 3; ++refine) {
    const QuaternionSpline<double> s = random_spline(refine, 10 + refine);
    for (double t = 0.0; t <= 2.04; t += 0.00731)
      EXPECT_NEAR(s.evaluate(t).q.norm(), 1.0, 1e-12);
    // Clamped ends: the curve starts at the first control and ends at the last.
    EXPECT_LT((s.evaluate(0.0).q.coeffs() - s.control().front().coeffs()).norm(), 1e-14);
    EXPECT_LT((s.evaluate(2.04).q.coeffs() - s.control().back().coeffs()).norm(), 1e-14);
    // Outside the range the end is held.
    EXPECT_LT((s.evaluate(3.0).q.coeffs() - s.control().back().coeffs()).norm(), 1e-14);
  }
}

TEST(QuaternionSpline, AngularVelocityAndAccelerationMatchFiniteDifferences) {
  for (int refine = 1; refine <= 3; ++refine) {
    const QuaternionSpline<double> s = random_spline(refine, 20 + refine);
    const double h = 1e-5;
    for (double t = 0.011; t < 2.04 - h; t += 0.0437) {
      const QuaternionSample<double> x = s.evaluate(t);
      const Eigen::Vector3d omega_fd = omega_by_differences(s, t, h);
      EXPECT_LT((x.omega - omega_fd).norm(), 1e-7 * (1 + x.omega.norm())) << "t=" << t;
      // α = 2·vec(q* q̈) with q̈ from the second central difference (independent of ω).
      const double h2 = 1e-4;
      const Eigen::Vector4d ddq =
          (s.evaluate(t + h2).q.coeffs() - 2 * x.q.coeffs() + s.evaluate(t - h2).q.coeffs()) /
          (h2 * h2);
      const Eigen::Vector3d alpha_fd = 2.0 * (x.q.conjugate() * Quat<double>(ddq)).vec();
      EXPECT_LT((x.alpha - alpha_fd).norm(), 1e-4 * (1 + x.alpha.norm())) << "t=" << t;
      // and α = dω/dt from central differences of the analytic ω.
      const Eigen::Vector3d domega = (s.evaluate(t + h).omega - s.evaluate(t - h).omega) / (2 * h);
      EXPECT_LT((x.alpha - domega).norm(), 1e-6 * (1 + x.alpha.norm())) << "t=" << t;
    }
  }
}

TEST(QuaternionSpline, DerivativesAreNotTrivial) {
  // Guards the finite-difference tests against a curve that does not move.
  const QuaternionSpline<double> s = random_spline(1, 5);
  EXPECT_GT(s.evaluate(1.0).omega.norm(), 0.1);
  EXPECT_GT(s.evaluate(1.0).alpha.norm(), 0.1);
}

TEST(QuaternionSpline, SecondOrderContinuousAtInteriorKnots) {
  for (int refine = 1; refine <= 3; ++refine) {
    const QuaternionSpline<double> s = random_spline(refine, 30 + refine);
    const std::vector<double>& k = s.knots();
    const int n = control_count(k);
    for (int span = 4; span <= n - 1; ++span) {
      const double t = k[span];
      // Left limit: the polynomial piece of the previous span evaluated at its right end.
      const SpanBasis<double> left_basis = cubic_basis_on_span(k, span - 1, t);
      const auto& c = s.control();
      const QuaternionSample<double> left =
          evaluate_quaternion_span(c[span - 4], c[span - 3], c[span - 2], c[span - 1], left_basis);
      const QuaternionSample<double> right = s.evaluate(t);
      EXPECT_LT((left.q.coeffs() - right.q.coeffs()).norm(), 1e-12) << "knot " << span;
      EXPECT_LT((left.omega - right.omega).norm(), 1e-10 * (1 + right.omega.norm()));
      EXPECT_LT((left.alpha - right.alpha).norm(), 1e-9 * (1 + right.alpha.norm()));
      // And by approaching from both sides through the public evaluate().
      const double eps = 1e-8;
      const QuaternionSample<double> a = s.evaluate(t - eps), b = s.evaluate(t + eps);
      EXPECT_LT((a.alpha - b.alpha).norm(), 1e-5 * (1 + right.alpha.norm()));
    }
  }
}

TEST(QuaternionSpline, LocalSupport) {
  const QuaternionSpline<double> s = random_spline(2, 40);
  const std::vector<double>& k = s.knots();
  const int n = control_count(k);
  for (int j = 0; j < n; ++j) {
    std::vector<Quat<double>> moved = s.control();
    moved[j] = moved[j] * quat_exp(Eigen::Vector3d(0.1, -0.05, 0.07));
    const QuaternionSpline<double> m(k, moved);
    // Control j acts on spans j..j+3, i.e. on (k_j, k_{j+4}); elsewhere the curve must be
    // bit-for-bit the same (the clamped ends are where control 0 / n-1 is the curve itself).
    std::vector<double> samples = {0.0, 2.04};
    for (int i = 1; i < 400; ++i)
      samples.push_back(2.04 * i / 400.0);
    for (double t : samples) {
      const double diff = (s.evaluate(t).q.coeffs() - m.evaluate(t).q.coeffs()).norm();
      const bool clamped_end = (j == 0 && t == 0.0) || (j == n - 1 && t == 2.04);
      if (clamped_end || (t > k[j] + 0.02 && t < k[j + 4] - 0.02)) {
        EXPECT_GT(diff, 1e-6) << "control " << j << " t=" << t;
      } else if (t < k[j] || t > k[j + 4]) {
        EXPECT_EQ(diff, 0.0) << "control " << j << " t=" << t;
      }
    }
  }
}

TEST(QuaternionSpline, AutoDiffMatchesDoubleAndFiniteDifferences) {
  const QuaternionSpline<double> s = random_spline(2, 50);
  const std::vector<double>& k = s.knots();
  const int j = 4;  // the control point to perturb in its tangent coordinates
  std::vector<AdFixed> kad(k.begin(), k.end());
  std::vector<Quat<AdFixed>> cad;
  for (int i = 0; i < control_count(k); ++i) {
    Quat<AdFixed> q = s.control()[i].cast<AdFixed>();
    if (i == j) {
      Vec3<AdFixed> delta;
      for (int a = 0; a < 3; ++a)
        delta[a] = AdFixed(0.0, 3, a);
      q = q * quat_exp(delta);
    }
    cad.push_back(q);
  }
  const QuaternionSpline<AdFixed> sad(kad, cad);
  const double h = 1e-6;
  for (double t = 0.05; t < 2.04; t += 0.0917) {
    const QuaternionSample<AdFixed> x = sad.evaluate(AdFixed(t));
    const QuaternionSample<double> ref = s.evaluate(t);
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(x.q.coeffs()[c].value(), ref.q.coeffs()[c], 1e-14);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(x.omega[c].value(), ref.omega[c], 1e-12);
      EXPECT_NEAR(x.alpha[c].value(), ref.alpha[c], 1e-10);
    }
    for (int a = 0; a < 3; ++a) {
      Eigen::Vector3d dp = Eigen::Vector3d::Zero(), dm = Eigen::Vector3d::Zero();
      dp[a] = h;
      dm[a] = -h;
      std::vector<Quat<double>> cp = s.control(), cm = s.control();
      cp[j] = cp[j] * quat_exp(dp);
      cm[j] = cm[j] * quat_exp(dm);
      const QuaternionSample<double> p = QuaternionSpline<double>(k, cp).evaluate(t);
      const QuaternionSample<double> m = QuaternionSpline<double>(k, cm).evaluate(t);
      for (int c = 0; c < 4; ++c) {
        const double fd = (p.q.coeffs()[c] - m.q.coeffs()[c]) / (2 * h);
        EXPECT_NEAR(x.q.coeffs()[c].derivatives()[a], fd, 1e-7) << "t=" << t;
      }
      for (int c = 0; c < 3; ++c) {
        const double fdw = (p.omega[c] - m.omega[c]) / (2 * h);
        EXPECT_NEAR(x.omega[c].derivatives()[a], fdw, 1e-6 * (1 + std::abs(fdw)));
        const double fda = (p.alpha[c] - m.alpha[c]) / (2 * h);
        EXPECT_NEAR(x.alpha[c].derivatives()[a], fda, 1e-5 * (1 + std::abs(fda)));
      }
    }
  }
}

TEST(QuaternionSpline, AutoDiffWithRespectToKeyframeTimeAndSampleTime) {
  // Dynamic-size AD: derivative 0 = an interior keyframe time, derivative 1 = the sample time.
  const std::vector<double> times = kNonUniformTimes;
  const std::vector<Quat<double>> control =
      random_controls(control_count(knots_for(times, 1)), 1.0, 60);
  std::vector<AdDynamic> tad;
  for (std::size_t i = 0; i < times.size(); ++i)
    tad.push_back(i == 2 ? AdDynamic(times[i], 2, 0) : AdDynamic(times[i]));
  std::vector<Quat<AdDynamic>> cad;
  for (const auto& q : control)
    cad.push_back(q.cast<AdDynamic>());
  const QuaternionSpline<AdDynamic> sad(clamped_cubic_knots(refine_breakpoints(tad, 1)), cad);
  const double h = 1e-6;
  std::vector<double> tp = times, tm = times;
  tp[2] += h;
  tm[2] -= h;
  const QuaternionSpline<double> sp(knots_for(tp, 1), control), sm(knots_for(tm, 1), control);
  const QuaternionSpline<double> s(knots_for(times, 1), control);
  for (double t : {0.1, 0.5, 0.95, 1.1, 1.7}) {
    const QuaternionSample<AdDynamic> x = sad.evaluate(AdDynamic(t, 2, 1));
    const QuaternionSample<double> p = sp.evaluate(t), m = sm.evaluate(t);
    const Quat<double> q = s.evaluate(t).q;
    // dq/dt = q·(0, ω/2).
    const Eigen::Vector3d half_omega = 0.5 * s.evaluate(t).omega;
    const Eigen::Vector4d qdot =
        (q * Quat<double>(0.0, half_omega.x(), half_omega.y(), half_omega.z())).coeffs();
    for (int c = 0; c < 4; ++c) {
      const auto& der = x.q.coeffs()[c].derivatives();
      ASSERT_EQ(der.size(), 2);
      EXPECT_NEAR(der[0], (p.q.coeffs()[c] - m.q.coeffs()[c]) / (2 * h), 1e-7) << "t=" << t;
      EXPECT_NEAR(der[1], qdot[c], 1e-12) << "t=" << t;
    }
    for (int c = 0; c < 3; ++c) {
      const double fd = (p.omega[c] - m.omega[c]) / (2 * h);
      EXPECT_NEAR(x.omega[c].derivatives()[0], fd, 1e-6 * (1 + std::abs(fd)));
      EXPECT_NEAR(x.omega[c].derivatives()[1], s.evaluate(t).alpha[c], 1e-9);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Quaternion fit (paper §5.2)

struct FitCase {
  std::vector<double> times;
  std::vector<Quat<double>> targets;
};

FitCase somersault(const std::vector<double>& times) {
  FitCase c{times, {}};
  for (std::size_t i = 0; i < times.size(); ++i)
    c.targets.push_back(axis_angle(2 * M_PI * i / (times.size() - 1), Eigen::Vector3d::UnitX()));
  return c;
}

FitCase twisting_somersault() {
  // A full back somersault (x) with a half twist about the body's long axis (y); the two
  // rotations do not commute, and consecutive keyframes are ~100 degrees apart.
  FitCase c{{0.0, 0.45, 0.98, 1.5, 2.04}, {}};
  for (std::size_t i = 0; i < c.times.size(); ++i) {
    const double u = static_cast<double>(i) / 4;
    c.targets.push_back(axis_angle(-2 * M_PI * u, Eigen::Vector3d::UnitX()) *
                        axis_angle(M_PI * u, Eigen::Vector3d::UnitY()));
  }
  return c;
}

/// Fits, checks the contract and returns the curve. `expect_aligned`: every consecutive pair of
/// control points has a non-negative dot product (true unless the keyframes force more than
/// 180° between two controls).
QuaternionSpline<double> expect_fit(const FitCase& c, int refine, bool expect_aligned = true) {
  const std::vector<double> k = knots_for(c.times, refine);
  const std::vector<Quat<double>> control = fit_quaternion_spline(k, c.times, c.targets);
  EXPECT_EQ(static_cast<int>(control.size()), control_count(k));
  for (std::size_t j = 0; j < control.size(); ++j) {
    EXPECT_NEAR(control[j].norm(), 1.0, 1e-12);
    if (j > 0 && expect_aligned) {
      EXPECT_GE(control[j].coeffs().dot(control[j - 1].coeffs()), 0.0) << "refine " << refine;
    }
  }
  const QuaternionSpline<double> s(k, control);
  EXPECT_LT(max_rotation_error(s, c.times, c.targets), 1e-6) << "refine " << refine;
  return s;
}

TEST(QuaternionFit, UniformSomersaultIsReproducedAtConstantRate) {
  // Keyframes of a constant-rate somersault: a rotation at constant angular velocity lies in the
  // spline space (linear precision), costs nothing in the rate-normalised smoothness term, and
  // so must come back exactly, for every knot refinement.
  const FitCase c = somersault({0.0, 0.51, 1.02, 1.53, 2.04});
  const double rate = 2 * M_PI / 2.04;
  for (int refine = 1; refine <= 3; ++refine) {
    const QuaternionSpline<double> s = expect_fit(c, refine);
    for (double t = 0.0; t <= 2.04; t += 0.01) {
      const QuaternionSample<double> x = s.evaluate(t);
      EXPECT_LT(rotation_angle_between(x.q, axis_angle(rate * t, Eigen::Vector3d::UnitX())), 1e-9)
          << "refine " << refine << " t=" << t;
      EXPECT_LT((x.omega - Eigen::Vector3d(rate, 0, 0)).norm(), 1e-8) << "t=" << t;
      EXPECT_LT(x.alpha.norm(), 1e-7) << "t=" << t;
    }
  }
}

TEST(QuaternionFit, FullSomersaultNonUniformTimes) {
  // 90° in 0.3 s after 90° in 0.59 s: with knots at the keyframes only, two consecutive
  // controls must be more than 180° apart (negative dot product), which the log map supports.
  const FitCase c = somersault(kNonUniformTimes);
  expect_fit(c, 1, false);
  for (int refine = 2; refine <= 3; ++refine) {
    const QuaternionSpline<double> s = expect_fit(c, refine);
    // By symmetry the fit stays a rotation about x.
    for (double t = 0.0; t <= 2.04; t += 0.01)
      EXPECT_LT(std::hypot(s.evaluate(t).q.y(), s.evaluate(t).q.z()), 1e-9);
  }
}

TEST(QuaternionFit, TwistingSomersault) {
  const FitCase c = twisting_somersault();
  for (std::size_t i = 1; i < c.targets.size(); ++i)
    ASSERT_LT(rotation_angle_between(c.targets[i - 1], c.targets[i]), 2.1);  // <= ~120°
  for (int refine = 1; refine <= 3; ++refine)
    expect_fit(c, refine);
  FitCase nonuniform = c;
  nonuniform.times = kNonUniformTimes;
  for (int refine = 1; refine <= 3; ++refine)
    expect_fit(nonuniform, refine, refine > 1);
}

TEST(QuaternionFit, HandlesFlippedTargetSignsAndUnsortedInput) {
  FitCase c = twisting_somersault();
  const QuaternionSpline<double> reference = expect_fit(c, 2);
  c.targets[1].coeffs() *= -1.0;
  c.targets[3].coeffs() *= -1.0;
  std::swap(c.times[1], c.times[2]);
  std::swap(c.targets[1], c.targets[2]);
  const std::vector<double>& k = reference.knots();
  const QuaternionSpline<double> s(k, fit_quaternion_spline(k, c.times, c.targets));
  for (double t = 0.0; t <= 2.04; t += 0.05)
    EXPECT_LT(rotation_angle_between(s.evaluate(t).q, reference.evaluate(t).q), 1e-9);
}

TEST(QuaternionFit, RandomRealisticKeyframes) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    FitCase c{kNonUniformTimes, {}};
    c.targets.push_back(
        axis_angle(M_PI * uniform(rng), Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng))));
    for (int i = 1; i < 5; ++i)
      c.targets.push_back(c.targets.back() *
                          axis_angle(2.09 * std::abs(uniform(rng)),
                                     Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng))));
    for (int refine = 1; refine <= 3; ++refine)
      expect_fit(c, refine, false);
  }
}

TEST(QuaternionFit, RejectsBadInput) {
  const FitCase c = somersault({0.0, 0.51, 1.02, 1.53, 2.04});
  const std::vector<double> k = knots_for(c.times, 1);
  std::vector<Quat<double>> fewer = c.targets;
  fewer.pop_back();
  EXPECT_THROW(fit_quaternion_spline(k, c.times, fewer), std::invalid_argument);
  std::vector<double> outside = c.times;
  outside.back() = 2.5;
  EXPECT_THROW(fit_quaternion_spline(k, outside, c.targets), std::invalid_argument);
  outside = c.times;
  outside.front() = -0.1;
  EXPECT_THROW(fit_quaternion_spline(k, outside, c.targets), std::invalid_argument);
  EXPECT_THROW(
      fit_quaternion_spline(std::vector<double>{0, 0, 0, 0, 1, 1, 1}, {0.0}, {c.targets[0]}),
      std::invalid_argument);
}

}  // namespace
}  // namespace saltus
