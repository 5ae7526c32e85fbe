// Free-flight simulation is the ground truth of the project: its root wrench must vanish when
// measured by an independent path (finite differences of the simulated root pose fed to inverse
// dynamics), its angular momentum must be conserved and its CoM must follow the parabola.
//
// A gap between output times of more RK4 steps than an int holds was a double-to-int cast past
// its range, undefined behaviour (issue 16: a flight of 2.2e8 s); it is refused with a message
// instead. The sanitizer build (float-cast-overflow) catches the cast.

#include <gtest/gtest.h>

#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/dynamics/free_flight.h"
#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/dynamics/momentum.h"
#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

struct Case {
  const char* name;
  Motion (*make)(const BodyModel&);
  Eigen::Vector3d angular_momentum;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

class FreeFlight : public ::testing::TestWithParam<Case> {};

JointMotion joints_of(const Trajectory<double>& trajectory) {
  return [&trajectory](double t, BodyState<double>& state) {
    for (int k = 1; k < trajectory.segment_count(); ++k) {
      const auto s = trajectory.rotations[k].evaluate(t);
      state.joints[k] = {s.q, s.omega, s.alpha};
    }
  };
}

/// Take-off as in every test motion (test::base_motion) with the case's angular momentum.
FreeFlightInitialState initial_state(const Trajectory<double>& trajectory) {
  const Motion reference = test::base_motion("take-off");
  FreeFlightInitialState initial;
  initial.com_position = reference.takeoff.com_position;
  initial.com_velocity = reference.takeoff.com_velocity;
  initial.root_orientation = trajectory.rotations[0].evaluate(0.0).q;
  return initial;
}

Eigen::Vector3d body_rate(const Eigen::Quaterniond& before, const Eigen::Quaterniond& after,
                          const Eigen::Quaterniond& at, double span) {
  // ω = 2 vec(q* q̇), q̇ by central difference (quaternions kept in one hemisphere).
  Eigen::Quaterniond b = before, a = after;
  if (b.coeffs().dot(at.coeffs()) < 0) b.coeffs() *= -1;
  if (a.coeffs().dot(at.coeffs()) < 0) a.coeffs() *= -1;
  Eigen::Quaterniond qdot;
  qdot.coeffs() = (a.coeffs() - b.coeffs()) / span;
  return 2.0 * (at.conjugate() * qdot).vec();
}

TEST_P(FreeFlight, RootWrenchVanishesByFiniteDifferences) {
  const BodyModel model = test::bundled_model();
  const Trajectory<double> trajectory = interpolate_keyframes(GetParam().make(model), model);
  FreeFlightInitialState initial = initial_state(trajectory);
  initial.angular_momentum = GetParam().angular_momentum;

  const double h = 2e-3;
  std::vector<double> times;
  const std::vector<double> probes{0.3, 0.85, 1.4, 1.95};
  for (double t : probes)
    for (int k = -2; k <= 2; ++k)
      times.push_back(t + k * h);
  const auto states = simulate_free_flight(model, joints_of(trajectory), initial, times);

  DynamicsData<double> data(model);
  for (std::size_t p = 0; p < probes.size(); ++p) {
    const auto& s = [&](int k) -> const BodyState<double>& { return states[5 * p + 2 + k]; };
    BodyState<double> fd = s(0);  // joints from the splines; root from differences only
    const auto omega_at = [&](int k) {
      return body_rate(s(k - 1).joints[0].q, s(k + 1).joints[0].q, s(k).joints[0].q, 2 * h);
    };
    fd.joints[0].omega = omega_at(0);
    fd.joints[0].alpha = (omega_at(1) - omega_at(-1)) / (2 * h);
    fd.root_velocity = (s(1).root_position - s(-1).root_position) / (2 * h);
    fd.root_acceleration =
        (s(1).root_position - 2 * s(0).root_position + s(-1).root_position) / (h * h);
    inverse_dynamics(model, data, fd);
    const double free_wrench = root_wrench_force_first(data).norm();

    BodyState<double> frozen = s(0);  // same pose and joint motion, root held still
    frozen.joints[0].omega.setZero();
    frozen.joints[0].alpha.setZero();
    frozen.root_velocity.setZero();
    frozen.root_acceleration.setZero();
    inverse_dynamics(model, data, frozen);
    const double frozen_wrench = root_wrench_force_first(data).norm();

    EXPECT_GT(frozen_wrench, 100.0) << GetParam().name << " t=" << probes[p];
    EXPECT_LT(free_wrench / frozen_wrench, 1e-4)
        << GetParam().name << " t=" << probes[p] << ": free " << free_wrench << " frozen "
        << frozen_wrench;
  }
}

TEST_P(FreeFlight, ConservesAngularMomentumAndFollowsTheParabola) {
  const BodyModel model = test::bundled_model();
  const Trajectory<double> trajectory = interpolate_keyframes(GetParam().make(model), model);
  FreeFlightInitialState initial = initial_state(trajectory);
  initial.angular_momentum = GetParam().angular_momentum;
  std::vector<double> times;
  for (int k = 0; k <= 51; ++k)
    times.push_back(2.04 * k / 51);
  const auto states = simulate_free_flight(model, joints_of(trajectory), initial, times);

  DynamicsData<double> data(model);
  for (std::size_t k = 0; k < times.size(); ++k) {
    inverse_dynamics(model, data, states[k]);
    const auto momentum = whole_body_momentum(model, data);
    EXPECT_LT((momentum.angular_about_com - initial.angular_momentum).norm(), 1e-6)
        << GetParam().name << " t=" << times[k];
    const Eigen::Vector3d parabola = initial.com_position + initial.com_velocity * times[k] +
                                     0.5 * gravity() * times[k] * times[k];
    EXPECT_LT((momentum.com - parabola).norm(), 1e-8) << GetParam().name << " t=" << times[k];
  }
}

INSTANTIATE_TEST_SUITE_P(
    Skills, FreeFlight,
    ::testing::Values(Case{"tuck", &test::tuck_motion, Eigen::Vector3d(-45, 0, 0)},
                      Case{"pike", &test::pike_motion, Eigen::Vector3d(40, 0, 0)},
                      Case{"twist", &test::twist_motion, Eigen::Vector3d(35, 6, 2)}),
    [](const ::testing::TestParamInfo<Case>& param_info) {
      return std::string(param_info.param.name);
    });

// Hardening (issue 16).
namespace hardening {

BodyModel one_segment() {
  BodyModel model;
  Segment s;
  s.name = "abdomen";
  s.joint = "root";
  s.mass = 10;
  s.inertia = Eigen::Vector3d(0.1, 0.2, 0.25).asDiagonal();
  model.segments.push_back(s);
  return model;
}

TEST(FreeFlight, TooManyStepsAreRefusedNotCast) {
  const BodyModel model = one_segment();
  const JointMotion still = [](double, BodyState<double>& state) {
    for (auto& joint : state.joints) {
      joint.omega.setZero();
      joint.alpha.setZero();
    }
  };
  FreeFlightInitialState initial;
  initial.com_position = Eigen::Vector3d(0, 1, 0);
  initial.com_velocity = Eigen::Vector3d(0, 5, 0);
  initial.angular_momentum = Eigen::Vector3d(1, 0, 0);
  EXPECT_THROW(simulate_free_flight(model, still, initial, {0.0, 2.2e8}, {}),
               std::invalid_argument);
  // Where it fits, the flight is simulated.
  EXPECT_EQ(simulate_free_flight(model, still, initial, {0.0, 0.01, 0.02}, {}).size(), 3u);
}

}  // namespace hardening

}  // namespace
}  // namespace saltus
