// The analytic root-wrench state Jacobian against two separate code paths: forward-mode AD through
// the full templated inverse dynamics, and central finite differences of the double version.

#include <gtest/gtest.h>

#include <random>

#include "saltus/dynamics/root_wrench_state_jacobian.h"
#include "support/random_body_state.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

using Ad = Eigen::AutoDiffScalar<Eigen::Matrix<double, kJointStateTangentSize, 1>>;
using Columns = Eigen::Matrix<double, 6, kJointStateTangentSize>;

Ad seeded(double value, int direction) {
  Ad a(value);
  a.derivatives()[direction] = 1.0;
  return a;
}

/// Root wrench derivatives by AD: segment k's (η, ω, α), or for k = −1 (ṗ, p̈) in columns 0..5.
Columns ad_columns(const BodyModel& model, const BodyState<double>& state, int k) {
  BodyState<Ad> s(model.size());
  for (int d = 0; d < 3; ++d) {
    s.root_position[d] = Ad(state.root_position[d]);
    s.root_velocity[d] = k < 0 ? seeded(state.root_velocity[d], d) : Ad(state.root_velocity[d]);
    s.root_acceleration[d] =
        k < 0 ? seeded(state.root_acceleration[d], 3 + d) : Ad(state.root_acceleration[d]);
  }
  for (int i = 0; i < model.size(); ++i) {
    const JointState<double>& joint = state.joints[i];
    Vec3<Ad> eta;
    for (int d = 0; d < 3; ++d) {
      eta[d] = i == k ? seeded(0.0, d) : Ad(0.0);
      s.joints[i].omega[d] = i == k ? seeded(joint.omega[d], 3 + d) : Ad(joint.omega[d]);
      s.joints[i].alpha[d] = i == k ? seeded(joint.alpha[d], 6 + d) : Ad(joint.alpha[d]);
    }
    s.joints[i].q = joint.q.cast<Ad>() * quat_exp(eta);
  }
  DynamicsData<Ad> data(model);
  inverse_dynamics(model, data, s);
  const Vec6<Ad> f = root_wrench_force_first(data);
  Columns out;
  for (int r = 0; r < 6; ++r)
    out.row(r) = f[r].derivatives().transpose();
  return out;
}

Vec6<double> root_wrench(const BodyModel& model, const BodyState<double>& state) {
  DynamicsData<double> data(model);
  inverse_dynamics(model, data, state);
  return root_wrench_force_first(data);
}

RootWrenchStateJacobian analytic(const BodyModel& model, const BodyState<double>& state) {
  DynamicsData<double> data(model);
  inverse_dynamics(model, data, state);
  RootWrenchStateJacobian out(model);
  root_wrench_state_jacobian(model, data, state, out);
  return out;
}

TEST(RootWrenchStateJacobian, MatchesAutomaticDifferentiationOfInverseDynamics) {
  const BodyModel model = test::bundled_model();
  for (unsigned seed : {1u, 2u, 3u}) {
    const BodyState<double> state = test::random_body_state(model.size(), seed);
    const RootWrenchStateJacobian jac = analytic(model, state);
    for (int k = 0; k < model.size(); ++k) {
      const Columns expected = ad_columns(model, state, k);
      EXPECT_LE((jac.joint[k] - expected).norm(), 1e-11 * (1.0 + expected.norm()))
          << "segment " << k << " seed " << seed << "\nanalytic\n"
          << jac.joint[k] << "\nAD\n"
          << expected;
    }
    const Columns expected = ad_columns(model, state, -1);
    EXPECT_LE((jac.root_translation - expected.leftCols<6>()).norm(),
              1e-11 * (1.0 + expected.norm()))
        << "root translation, seed " << seed;
  }
}

TEST(RootWrenchStateJacobian, MatchesCentralDifferences) {
  const BodyModel model = test::bundled_model();
  const BodyState<double> state = test::random_body_state(model.size(), 7);
  const RootWrenchStateJacobian jac = analytic(model, state);
  const double h = 1e-6;
  // Perturbs one state entry of segment k (η, ω, α) by ±h and differences the wrench.
  auto difference = [&](int k, int entry) {
    Vec6<double> side[2];
    for (int s = 0; s < 2; ++s) {
      BodyState<double> moved = state;
      const double step = s == 0 ? h : -h;
      Eigen::Vector3d delta = Eigen::Vector3d::Zero();
      delta[entry % 3] = step;
      JointState<double>& joint = moved.joints[k];
      if (entry < 3) joint.q = joint.q * quat_exp(delta);
      if (entry >= 3 && entry < 6) joint.omega += delta;
      if (entry >= 6) joint.alpha += delta;
      side[s] = root_wrench(model, moved);
    }
    return Vec6<double>((side[0] - side[1]) / (2.0 * h));
  };
  for (int k = 0; k < model.size(); ++k) {
    for (int entry = 0; entry < kJointStateTangentSize; ++entry) {
      const Vec6<double> expected = difference(k, entry);
      EXPECT_LE((jac.joint[k].col(entry) - expected).norm(), 1e-6 * (1.0 + expected.norm()))
          << "segment " << k << " entry " << entry;
    }
  }
}

TEST(RootWrenchStateJacobian, AccelerationColumnsAreTheCompositeInertia) {
  // The wrench is linear in p̈: F(p̈ + d) − F(p̈) is exact for any d, not only small ones.
  const BodyModel model = test::bundled_model();
  const BodyState<double> state = test::random_body_state(model.size(), 11);
  const RootWrenchStateJacobian jac = analytic(model, state);
  const Eigen::Vector3d d(2.0, -5.0, 1.5);
  BodyState<double> moved = state;
  moved.root_acceleration += d;
  const Vec6<double> change = root_wrench(model, moved) - root_wrench(model, state);
  EXPECT_LE((jac.root_translation.rightCols<3>() * d - change).norm(), 1e-10 * change.norm());
}

}  // namespace
}  // namespace saltus
