// The analytic joint-wrench state Jacobian (moment and force) against central finite differences
// of the double inverse dynamics (an independent path: no derivative code involved), for every
// joint and every state entry, and its zero pattern (a joint's wrench ignores the states of
// unrelated limbs).

#include <gtest/gtest.h>

#include <random>

#include "saltus/dynamics/joint_wrench_state_jacobian.h"
#include "support/random_body_state.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// Every joint's wrench (n_j, f_j) (child frame, moment about the joint centre), stacked.
Eigen::VectorXd joint_wrenches(const BodyModel& model, const BodyState<double>& state) {
  DynamicsData<double> data(model);
  inverse_dynamics(model, data, state);
  Eigen::VectorXd out(6 * model.size());
  for (int j = 0; j < model.size(); ++j)
    out.segment<6>(6 * j) = data.joint_wrench[j];
  return out;
}

/// The root wrench's sweep and the joint wrenches' Jacobian at one state.
struct Sweeps {
  DynamicsData<double> data;
  RootWrenchStateJacobian root;
  JointWrenchStateJacobian joints;
  Sweeps(const BodyModel& model, const BodyState<double>& state)
      : data(model), root(model), joints(model) {
    inverse_dynamics(model, data, state);
    root_wrench_state_jacobian(model, data, state, root);
    joint_wrench_state_jacobian(model, data, state, root, joints);
  }
};

TEST(JointWrenchStateJacobian, MatchesCentralDifferencesForEveryJointAndState) {
  const BodyModel model = test::bundled_model();
  const int n = model.size();
  for (unsigned seed : {3u, 8u}) {
    const BodyState<double> state = test::random_body_state(n, seed);
    const Sweeps sweeps(model, state);
    const JointWrenchStateJacobian& jac = sweeps.joints;

    const double h = 1e-6;
    // Column `entry` of segment k's state (η, ω, α), or k = −1: the root's ṗ then p̈.
    auto difference = [&](int k, int entry) {
      Eigen::VectorXd side[2];
      for (int s = 0; s < 2; ++s) {
        BodyState<double> moved = state;
        const double step = s == 0 ? h : -h;
        Eigen::Vector3d delta = Eigen::Vector3d::Zero();
        delta[entry % 3] = step;
        if (k < 0) {
          (entry < 3 ? moved.root_velocity : moved.root_acceleration) += delta;
        } else {
          JointState<double>& joint = moved.joints[k];
          if (entry < 3) joint.q = joint.q * quat_exp(delta);
          if (entry >= 3 && entry < 6) joint.omega += delta;
          if (entry >= 6) joint.alpha += delta;
        }
        side[s] = joint_wrenches(model, moved);
      }
      return Eigen::VectorXd((side[0] - side[1]) / (2.0 * h));
    };
    for (int k = -1; k < n; ++k) {
      for (int entry = 0; entry < (k < 0 ? 6 : kJointStateTangentSize); ++entry) {
        const Eigen::VectorXd expected = difference(k, entry);
        for (int j = 0; j < n; ++j) {
          const Vector6d e = expected.segment<6>(6 * j);
          Vector6d got = Vector6d::Zero();
          if (k < 0)
            got = jac.root_translation[j].col(entry);
          else if (jac.touches[j * n + k])
            got = jac.joint[j * n + k].col(entry);
          EXPECT_LE((got - e).norm(), 1e-6 * (1.0 + e.norm()))
              << "joint " << j << ", state of " << k << ", entry " << entry << ", seed " << seed;
        }
      }
    }
  }
}

// What the joint bounds declare as a row's columns (joint_wrench_depends_on) is what the sweep
// fills; the test above shows every other column is zero. A knee's load leaves the arms out.
TEST(JointWrenchStateJacobian, TouchesTheJointsAncestorsAndSubtreeOnly) {
  const BodyModel model = test::bundled_model();
  const int n = model.size();
  const Sweeps sweeps(model, test::random_body_state(n, 4));
  int left_out = 0;
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) {
      EXPECT_EQ(sweeps.joints.touches[j * n + k] != 0, joint_wrench_depends_on(model, j, k))
          << "joint " << model.segments[j].joint << ", segment " << model.segments[k].name;
      left_out += !joint_wrench_depends_on(model, j, k);
    }
  EXPECT_GT(left_out, n * n / 3) << "most joints depend on a part of the body only";
}

TEST(JointWrenchStateJacobian, RootRowIsTheRootWrench) {
  const BodyModel model = test::bundled_model();
  const Sweeps sweeps(model, test::random_body_state(model.size(), 5));
  const RootWrenchStateJacobian& sweep = sweeps.root;
  const JointWrenchStateJacobian& jac = sweeps.joints;
  for (int k = 0; k < model.size(); ++k) {
    // root_wrench_state_jacobian's rows are force first.
    EXPECT_LE((jac.joint[k].topRows<3>() - sweep.joint[k].bottomRows<3>()).norm(),
              1e-10 * (1.0 + sweep.joint[k].norm()))
        << k;
    EXPECT_LE((jac.joint[k].bottomRows<3>() - sweep.joint[k].topRows<3>()).norm(),
              1e-10 * (1.0 + sweep.joint[k].norm()))
        << k;
  }
  EXPECT_LE((jac.root_translation[0].topRows<3>() - sweep.root_translation.bottomRows<3>()).norm(),
            1e-10);
  EXPECT_LE((jac.root_translation[0].bottomRows<3>() - sweep.root_translation.topRows<3>()).norm(),
            1e-10);
}

}  // namespace
}  // namespace saltus
