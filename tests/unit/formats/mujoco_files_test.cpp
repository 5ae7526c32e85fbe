// The MuJoCo export's files (formats/mujoco_files.h): MuJoCo's generalised coordinates of a
// state (z-up world, w-first quaternions, depth-first bodies), checked against the state's own
// poses and by finite differences along a motion (qvel is qpos's rate, qacc qvel's); the model
// holds Saltus's masses, CoMs and inertias exactly and one key per sample; the CSV reads back
// exactly. MuJoCo itself loads and checks these files in tests/mujoco/.

#include "saltus/formats/mujoco_files.h"

#include <gtest/gtest.h>

#include <sstream>

#include "saltus/formats/csv_table.h"
#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(MujocoFiles, TheWorldIsZUpWithTheAthleteFacingX) {
  const Eigen::Matrix3d w = mujoco_from_saltus().toRotationMatrix();
  EXPECT_TRUE((w * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitZ())) << "up";
  EXPECT_TRUE((w * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitX())) << "forward";
  EXPECT_TRUE((w * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY())) << "left";
  EXPECT_NEAR(w.determinant(), 1.0, 1e-15);
}

TEST(MujocoFiles, BodiesComeDepthFirstEachSubtreeTogether) {
  const BodyModel model = test::bundled_model();
  const std::vector<int> order = mujoco_body_order(model);
  ASSERT_EQ(static_cast<int>(order.size()), model.size());
  EXPECT_EQ(order.front(), 0);
  std::vector<int> position(model.size());
  for (int k = 0; k < model.size(); ++k)
    position[order[k]] = k;
  for (int s = 1; s < model.size(); ++s) {
    EXPECT_LT(position[model.segments[s].parent], position[s]) << "a parent before its child";
    // The segments right after a body, up to its subtree's size, are its descendants.
    int size = 0;
    for (int t = 0; t < model.size(); ++t)
      for (int a = t; a >= 0; a = model.segments[a].parent)
        if (a == s) ++size;
    for (int k = position[s]; k < position[s] + size; ++k) {
      bool inside = false;
      for (int a = order[k]; a >= 0; a = model.segments[a].parent)
        inside = inside || a == s;
      EXPECT_TRUE(inside) << model.segments[order[k]].name << " in " << model.segments[s].name;
    }
  }
  const std::vector<std::string> qpos = mujoco_qpos_names(model);
  const std::vector<std::string> qvel = mujoco_qvel_names(model);
  ASSERT_EQ(qpos.size(), 7u + 4u * (model.size() - 1));
  ASSERT_EQ(qvel.size(), 6u + 3u * (model.size() - 1));
  EXPECT_EQ(qpos[0], "root.x");
  EXPECT_EQ(qpos[3], "root.qw");
  EXPECT_EQ(qpos[7], model.segments[order[1]].joint + ".qw");
  EXPECT_EQ(qvel[3], "root.wx");
  EXPECT_EQ(qvel[6], model.segments[order[1]].joint + ".wx");
}

TEST(MujocoFiles, CoordinatesAreTheStatesPosesAndRatesInMujocosWorld) {
  const BodyModel model = test::bundled_model();
  const Motion motion = test::twist_motion(model);
  const Trajectory<double> trajectory = motion_trajectory(motion, model);
  const Eigen::Matrix3d w = mujoco_from_saltus().toRotationMatrix();
  const std::vector<int> order = mujoco_body_order(model);
  const double h = 1e-5;
  for (double t : {0.2, 0.7, 1.3}) {
    BodyState<double> state(model.size()), before(model.size()), after(model.size());
    trajectory.sample(t, state);
    trajectory.sample(t - h, before);
    trajectory.sample(t + h, after);
    const MujocoState q = mujoco_state(model, state);
    const MujocoState qb = mujoco_state(model, before), qa = mujoco_state(model, after);
    EXPECT_TRUE(q.qpos.head<3>().isApprox(w * state.root_position, 1e-14));
    const Eigen::Quaterniond root(q.qpos[3], q.qpos[4], q.qpos[5], q.qpos[6]);
    EXPECT_TRUE(root.toRotationMatrix().isApprox(w * state.joints[0].q.toRotationMatrix(), 1e-14));
    for (int k = 1; k < model.size(); ++k) {
      const Eigen::Quaterniond joint(q.qpos[3 + 4 * k], q.qpos[4 + 4 * k], q.qpos[5 + 4 * k],
                                     q.qpos[6 + 4 * k]);
      EXPECT_TRUE(joint.coeffs().isApprox(state.joints[order[k]].q.coeffs(), 1e-14));
    }
    // qvel's translation is qpos's rate, its rotations the body-frame angular velocities of the
    // quaternions' rates (ω = 2·q⁻¹·q̇), qacc qvel's rate: by central differences.
    const Eigen::VectorXd rate = (qa.qpos - qb.qpos) / (2 * h);
    EXPECT_LT((rate.head<3>() - q.qvel.head<3>()).norm(), 1e-6);
    for (int k = 0; k < model.size(); ++k) {
      const Eigen::Vector4d dq = rate.segment<4>(3 + 4 * k);
      const Eigen::Quaterniond qk(q.qpos[3 + 4 * k], q.qpos[4 + 4 * k], q.qpos[5 + 4 * k],
                                  q.qpos[6 + 4 * k]);
      const Eigen::Quaterniond omega =
          qk.conjugate() * Eigen::Quaterniond(dq[0], dq[1], dq[2], dq[3]);
      EXPECT_LT((2 * omega.vec() - q.qvel.segment<3>(3 + 3 * k)).norm(), 1e-5) << "body " << k;
    }
    EXPECT_LT(((qa.qvel - qb.qvel) / (2 * h) - q.qacc).norm(), 1e-4 * (1 + q.qacc.norm()));
  }
}

TEST(MujocoFiles, TheModelHoldsSaltussMassPropertiesAndOneKeyPerSample) {
  BodyModel model = test::bundled_model();
  model.segments[1].inertia(0, 2) = model.segments[1].inertia(2, 0) = 0.001;
  const Motion motion = test::tuck_motion(model);
  const Trajectory<double> trajectory = motion_trajectory(motion, model);
  const std::vector<double> times = {0.0, 0.5, 1.0};
  std::vector<BodyState<double>> states(times.size(), BodyState<double>(model.size()));
  for (std::size_t k = 0; k < times.size(); ++k)
    trajectory.sample(times[k], states[k]);
  const std::string xml = mujoco_model_xml(model, "tuck <1>", times, states);
  EXPECT_NE(xml.find("<mujoco model=\"tuck &lt;1&gt;\">"), std::string::npos);
  EXPECT_NE(xml.find("<option gravity=\"0 0 -9.81\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<freejoint name=\"root\"/>"), std::string::npos);
  const std::size_t pelvis = xml.find("<body name=\"pelvis\" pos=\"0 0 0\">");
  ASSERT_NE(pelvis, std::string::npos);
  EXPECT_LT(xml.find("<joint name=\"lumbar\" type=\"ball\"/>", pelvis),
            xml.find("<body", pelvis + 1))
      << "the pelvis's own joint";
  EXPECT_EQ(xml.find("<inertial ", pelvis),
            xml.find("<inertial pos=\"0 -0.087 0\" mass=\"8.1\" "
                     "fullinertia=\"0.053 0.059 0.066 0 0.001 0\"/>",
                     pelvis))
      << "Saltus's numbers, the matrix's entries in MuJoCo's order M11 M22 M33 M12 M13 M23";
  std::size_t keys = 0;
  for (std::size_t at = xml.find("<key "); at != std::string::npos; at = xml.find("<key ", at + 1))
    ++keys;
  EXPECT_EQ(keys, times.size());
  EXPECT_NE(xml.find("<key time=\"0.5\" qpos=\""), std::string::npos);
  EXPECT_EQ(xml.find("nan"), std::string::npos);

  EXPECT_THROW(mujoco_model_xml(model, "x", {0.0}, states), std::invalid_argument);
  EXPECT_THROW(mujoco_trajectory_csv(model, {}, {}), std::invalid_argument);
}

TEST(MujocoFiles, TheTrajectoryReadsBackExactly) {
  const BodyModel model = test::bundled_model();
  const Trajectory<double> trajectory = motion_trajectory(test::twist_motion(model), model);
  const std::vector<double> times = {0.0, 1.0 / 3.0, 0.9};
  std::vector<BodyState<double>> states(times.size(), BodyState<double>(model.size()));
  for (std::size_t k = 0; k < times.size(); ++k)
    trajectory.sample(times[k], states[k]);
  std::istringstream in(mujoco_trajectory_csv(model, times, states));
  const CsvTable table = parse_csv_table(in, "trajectory.csv");
  const std::size_t nq = 7 + 4 * (model.size() - 1), nv = 6 + 3 * (model.size() - 1);
  ASSERT_EQ(table.columns.size(), 1 + nq + 2 * nv);
  EXPECT_EQ(table.columns[0], "t");
  EXPECT_EQ(table.columns[1], "qpos.root.x");
  EXPECT_EQ(table.columns[1 + nq], "qvel.root.vx");
  EXPECT_EQ(table.columns[1 + nq + nv], "qacc.root.vx");
  ASSERT_EQ(table.rows.size(), times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    const MujocoState q = mujoco_state(model, states[k]);
    EXPECT_EQ(table.rows[k][0], times[k]);
    for (std::size_t i = 0; i < nq; ++i)
      EXPECT_EQ(table.rows[k][1 + i], q.qpos[i]);
    for (std::size_t i = 0; i < nv; ++i) {
      EXPECT_EQ(table.rows[k][1 + nq + i], q.qvel[i]);
      EXPECT_EQ(table.rows[k][1 + nq + nv + i], q.qacc[i]);
    }
  }
}

}  // namespace
}  // namespace saltus
