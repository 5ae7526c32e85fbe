// `saltus export --format mujoco` checked by MuJoCo itself (Debian's libmujoco 2.2.2): the
// exported model.xml loads, and at every sample of trajectory.csv mj_inverse gives the free
// joint the generalised force Saltus's inverse dynamics gives the root (force in the world,
// moment in the root frame about its origin: MuJoCo's free-joint convention), and every ball
// joint the moment its joint transmits, on M7, the dive and an imported capture; MuJoCo's total
// mass, CoM and composite inertia are Saltus's; and an optimised motion flown in MuJoCo from its
// exported take-off, the joints driven along the exported qpos/qvel/qacc, lands where the
// motion does. Saltus's side comes from the library (load_export_source, motion_trajectory,
// inverse dynamics), never from the exported files; the frame change is written here again.

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/dynamics/momentum.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/formats/csv_table.h"
#include "saltus/motion/interpolate.h"
#include "saltus/use_cases/captures.h"
#include "support/cli_runner.h"

namespace saltus::test {
namespace {

/// MuJoCo's world from Saltus's, written from docs/formats.md: MuJoCo x = Saltus z (forward),
/// y = Saltus x (left), z = Saltus y (up).
Eigen::Matrix3d mujoco_world() {
  Eigen::Matrix3d w = Eigen::Matrix3d::Zero();
  w(0, 2) = 1;
  w(1, 0) = 1;
  w(2, 1) = 1;
  return w;
}

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using MjModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using MjDataPtr = std::unique_ptr<mjData, DataDeleter>;

MjModelPtr load_model(const std::string& path) {
  char error[1000] = "";
  MjModelPtr m(mj_loadXML(path.c_str(), nullptr, error, sizeof error));
  EXPECT_TRUE(m) << path << ": " << error;
  return m;
}

/// The exported trajectory.csv: per row t, then qpos, qvel, qacc.
struct ExportedRows {
  std::vector<double> t;
  std::vector<Eigen::VectorXd> qpos, qvel, qacc;
};

ExportedRows read_rows(const std::string& path, const mjModel& m) {
  const CsvTable table = read_csv_table(path);
  ExportedRows rows;
  EXPECT_EQ(table.columns.size(), 1u + m.nq + 2u * m.nv) << "t, qpos, qvel, qacc";
  EXPECT_EQ(table.columns[1], "qpos.root.x");
  for (const std::vector<double>& r : table.rows) {
    rows.t.push_back(r[0]);
    rows.qpos.push_back(Eigen::Map<const Eigen::VectorXd>(&r[1], m.nq));
    rows.qvel.push_back(Eigen::Map<const Eigen::VectorXd>(&r[1 + m.nq], m.nv));
    rows.qacc.push_back(Eigen::Map<const Eigen::VectorXd>(&r[1 + m.nq + m.nv], m.nv));
  }
  return rows;
}

void set_state(const mjModel& m, mjData* d, const ExportedRows& rows, std::size_t k) {
  for (int i = 0; i < m.nq; ++i)
    d->qpos[i] = rows.qpos[k][i];
  for (int i = 0; i < m.nv; ++i) {
    d->qvel[i] = rows.qvel[k][i];
    d->qacc[i] = rows.qacc[k][i];
  }
}

/// Exports SOURCE as MuJoCo into `dir`/mujoco and returns its folder.
std::string export_mujoco(const std::string& source, const TempDir& dir,
                          const std::string& flags = "") {
  const std::string out = dir / "mujoco";
  const CliRun run =
      run_cli("export " + source + " --format mujoco --quiet " + flags + " --out " + out);
  EXPECT_EQ(run.status, 0) << run.output;
  return out;
}

/// RMS over samples of |a − b| against the RMS of |b|.
double relative_rms(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double difference = 0, reference = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    difference += (a[k] - b[k]).squaredNorm();
    reference += b[k].squaredNorm();
  }
  return std::sqrt(difference / reference);
}

/// mj_inverse at every exported sample against Saltus's root and joint wrenches.
void expect_inverse_dynamics_is_saltus(const std::string& source) {
  SCOPED_TRACE(source);
  TempDir dir;
  const std::string out = export_mujoco(source, dir);
  MjModelPtr m = load_model(out + "/model.xml");
  ASSERT_TRUE(m);
  MjDataPtr d(mj_makeData(m.get()));
  const ExportedRows rows = read_rows(out + "/trajectory.csv", *m);
  ASSERT_GE(rows.t.size(), 5u);
  EXPECT_EQ(m->nkey, static_cast<int>(rows.t.size())) << "one key per sample";

  const MotionFile motion = load_export_source(source);
  const BodyModel& model = motion.model;
  ASSERT_EQ(m->nbody, model.size() + 1) << "the world and one body per segment";
  ASSERT_EQ(m->nv, 6 + 3 * (model.size() - 1));
  const std::vector<SampleRecord> saltus =
      evaluate_trajectory(model, motion_trajectory(motion.motion, model), rows.t);

  const Eigen::Matrix3d w = mujoco_world();
  std::vector<Eigen::Vector3d> force_mj, force_saltus, moment_mj, moment_saltus;
  std::vector<Eigen::Vector3d> joint_mj, joint_saltus;
  for (std::size_t k = 0; k < rows.t.size(); ++k) {
    EXPECT_NEAR(m->key_time[k], rows.t[k], 1e-12);
    for (int i = 0; i < m->nq; ++i)
      EXPECT_NEAR(m->key_qpos[k * m->nq + i], rows.qpos[k][i], 1e-12);
    set_state(*m, d.get(), rows, k);
    mj_inverse(m.get(), d.get());
    const Eigen::Map<const Eigen::VectorXd> f(d->qfrc_inverse, m->nv);
    const SampleRecord& s = saltus[k];
    // Saltus's F1..F6: root frame, about the root origin. MuJoCo's free joint: the force in the
    // world, the moment in the body frame.
    force_mj.push_back(f.head<3>());
    force_saltus.push_back(w * (s.segment_rotation[0] * s.root_wrench.head<3>()));
    moment_mj.push_back(f.segment<3>(3));
    moment_saltus.push_back(s.root_wrench.tail<3>());
    // Ball joints: the moment the parent applies on the child, child frame, about the joint.
    for (int j = 1; j < m->njnt; ++j) {
      const int segment = model.segment_index(mj_id2name(m.get(), mjOBJ_BODY, m->jnt_bodyid[j]));
      ASSERT_GE(segment, 1);
      EXPECT_EQ(model.segments[segment].joint, mj_id2name(m.get(), mjOBJ_JOINT, j));
      joint_mj.push_back(f.segment<3>(m->jnt_dofadr[j]));
      joint_saltus.push_back(s.joint_wrench[segment].tail<3>());
    }
  }
  const double force = relative_rms(force_mj, force_saltus);
  const double moment = relative_rms(moment_mj, moment_saltus);
  const double joints = relative_rms(joint_mj, joint_saltus);
  EXPECT_LT(force, 1e-3) << "the free joint's force";
  EXPECT_LT(moment, 1e-3) << "the free joint's moment";
  EXPECT_LT(joints, 1e-3) << "the ball joints' moments";
  std::printf(
      "mj_inverse against Saltus, RMS relative: root force %.2g, root moment %.2g, "
      "joint moments %.2g (%zu samples)\n",
      force, moment, joints, rows.t.size());
  EXPECT_GT(std::sqrt(force_saltus.front().squaredNorm() + force_saltus.back().squaredNorm()), 1.0)
      << "a motion that does not obey Newton: the comparison is not of zeros";
}

TEST(MujocoExport, InverseDynamicsIsSaltusOnM7) {
  expect_inverse_dynamics_is_saltus(std::string(SALTUS_EXAMPLES_DIR) +
                                    "/motions/M7-double-front-one-and-a-half-twists.motion.json");
}

TEST(MujocoExport, InverseDynamicsIsSaltusOnTheDive) {
  expect_inverse_dynamics_is_saltus(std::string(SALTUS_EXAMPLES_DIR) +
                                    "/motions/dive-5m-front-one-and-a-half-twists.motion.json");
}

TEST(MujocoExport, InverseDynamicsIsSaltusOnACapture) {
  TempDir dir;
  const std::string folder = dir / "backflip";
  const CliRun run = run_cli("import " + std::string(SALTUS_CAPTURES_DIR) +
                             "/deepmimic-backflip.bvh --quiet --out " + folder);
  ASSERT_EQ(run.status, 0) << run.output;
  expect_inverse_dynamics_is_saltus(folder);
}

TEST(MujocoExport, MassCentreOfMassAndCompositeInertiaAreSaltus) {
  const std::string source = std::string(SALTUS_EXAMPLES_DIR) +
                             "/motions/M5-front-somersault-one-and-a-half-twists.motion.json";
  TempDir dir;
  const std::string out = export_mujoco(source, dir, "--fps 10");
  MjModelPtr m = load_model(out + "/model.xml");
  ASSERT_TRUE(m);
  MjDataPtr d(mj_makeData(m.get()));
  const ExportedRows rows = read_rows(out + "/trajectory.csv", *m);
  const MotionFile motion = load_export_source(source);
  const BodyModel& model = motion.model;
  EXPECT_NEAR(m->body_subtreemass[1], model.total_mass(), 1e-12);

  const Trajectory<double> trajectory = motion_trajectory(motion.motion, model);
  DynamicsData<double> data(model);
  BodyState<double> state(model.size());
  const Eigen::Matrix3d w = mujoco_world();
  for (std::size_t k = 0; k < rows.t.size(); ++k) {
    set_state(*m, d.get(), rows, k);
    mj_forward(m.get(), d.get());
    trajectory.sample(rows.t[k], state);
    inverse_dynamics(model, data, state);
    // Saltus's composite inertia (root frame, about the root origin) as mass, CoM and the
    // inertia about the CoM in world axes.
    const Mat6<double> composite = composite_inertia_at_root(model, data);
    const double mass = composite(5, 5);
    const Eigen::Matrix3d mc = composite.topRightCorner<3, 3>();  // m·[c]×
    const Eigen::Vector3d c(mc(2, 1) / mass, mc(0, 2) / mass, mc(1, 0) / mass);
    const Eigen::Matrix3d cx = mc / mass;
    const Eigen::Matrix3d about_com = composite.topLeftCorner<3, 3>() - mass * cx * cx.transpose();
    const Eigen::Matrix3d r = data.world_rotation[0];
    const Eigen::Vector3d com = data.world_position[0] + r * c;
    const Eigen::Matrix3d expected = w * r * about_com * r.transpose() * w.transpose();

    const Eigen::Map<const Eigen::Vector3d> com_mj(d->subtree_com + 3);
    EXPECT_LT((com_mj - w * com).norm(), 1e-9) << "t = " << rows.t[k];
    EXPECT_LT((com_mj - w * data.com).norm(), 1e-9);
    // MuJoCo's composite inertia of the tree (crb of the root body): about the subtree's CoM,
    // world axes, [xx yy zz xy xz yz], then m·offset (zero about its own CoM) and the mass.
    const mjtNum* crb = d->crb + 10;
    Eigen::Matrix3d mj;
    mj << crb[0], crb[3], crb[4], crb[3], crb[1], crb[5], crb[4], crb[5], crb[2];
    EXPECT_LT((mj - expected).norm(), 1e-9 * expected.norm()) << "t = " << rows.t[k];
    EXPECT_NEAR(crb[9], model.total_mass(), 1e-12);
  }
}

/// The root's turn, degrees, between two MuJoCo quaternions (w first).
double angle_deg(const Eigen::VectorXd& qpos_a, const Eigen::VectorXd& qpos_b) {
  const Eigen::Quaterniond a(qpos_a[3], qpos_a[4], qpos_a[5], qpos_a[6]);
  const Eigen::Quaterniond b(qpos_b[3], qpos_b[4], qpos_b[5], qpos_b[6]);
  return a.normalized().angularDistance(b.normalized()) * 180.0 / M_PI;
}

/// The free joint's acceleration (6) that leaves its generalised force zero, with the joints at
/// sample `k` (qpos, qvel, qacc) and the root at `root_qpos`, `root_qvel`: MuJoCo's mass matrix
/// and bias forces, M_ff·a_f = −(M_fj·a_j + bias_f). Checks with mj_inverse that the free joint's
/// force is then zero.
Eigen::Matrix<double, 6, 1> free_acceleration(const mjModel& m, mjData* d, const ExportedRows& rows,
                                              std::size_t k, const Eigen::VectorXd& root_qpos,
                                              const Eigen::VectorXd& root_qvel) {
  const int nv = m.nv;
  set_state(m, d, rows, k);
  for (int i = 0; i < 7; ++i)
    d->qpos[i] = root_qpos[i];
  for (int i = 0; i < 6; ++i)
    d->qvel[i] = root_qvel[i];
  mj_forward(&m, d);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> mass(nv, nv);
  mj_fullM(&m, mass.data(), d->qM);
  const Eigen::Map<const Eigen::VectorXd> bias(d->qfrc_bias, nv);
  const Eigen::VectorXd joints = rows.qacc[k].tail(nv - 6);
  const Eigen::Matrix<double, 6, 1> free = mass.topLeftCorner(6, 6).ldlt().solve(
      -(mass.topRightCorner(6, nv - 6) * joints + bias.head<6>()));
  // mj_forward left its own qacc: the exported one for the joints, the free one for the root.
  for (int i = 0; i < 6; ++i)
    d->qacc[i] = free[i];
  for (int i = 6; i < nv; ++i)
    d->qacc[i] = joints[i - 6];
  mj_inverse(&m, d);
  for (int i = 0; i < 6; ++i)
    EXPECT_LT(std::abs(d->qfrc_inverse[i]), 1e-6) << "a free flight";
  return free;
}

/// The root's qpos (7) moved by `velocity` (6: world linear, body angular) for `dt`, with
/// MuJoCo's own position integration.
Eigen::VectorXd integrated_root(const mjModel& m, const Eigen::VectorXd& root_qpos,
                                const Eigen::VectorXd& velocity, double dt) {
  std::vector<mjtNum> qpos(m.nq, 0.0), qvel(m.nv, 0.0);
  for (int i = 0; i < 7; ++i)
    qpos[i] = root_qpos[i];
  for (int i = 7; i < m.nq; i += 4)
    qpos[i] = 1.0;  // the ball joints' identity, unused
  for (int i = 0; i < 6; ++i)
    qvel[i] = velocity[i];
  mj_integratePos(&m, qpos.data(), qvel.data(), dt);
  return Eigen::Map<const Eigen::VectorXd>(qpos.data(), 7);
}

/// MuJoCo flies the exported motion: from the first sample's qpos and qvel, the ball joints
/// driven along the exported samples, the free joint left free (free_acceleration), one Heun
/// step (second order) per sample. Returns the root's turn at the end against the exported last
/// sample, degrees.
double mujoco_landing_error_deg(const std::string& out) {
  MjModelPtr m = load_model(out + "/model.xml");
  if (!m) return 1e9;
  MjDataPtr d(mj_makeData(m.get()));
  const ExportedRows rows = read_rows(out + "/trajectory.csv", *m);
  Eigen::VectorXd q = rows.qpos[0].head(7), v = rows.qvel[0].head(6);
  for (std::size_t k = 0; k + 1 < rows.t.size(); ++k) {
    const double h = rows.t[k + 1] - rows.t[k];
    const Eigen::VectorXd a = free_acceleration(*m, d.get(), rows, k, q, v);
    const Eigen::VectorXd q_guess = integrated_root(*m, q, v, h);
    const Eigen::VectorXd v_guess = v + h * a;
    const Eigen::VectorXd a_guess = free_acceleration(*m, d.get(), rows, k + 1, q_guess, v_guess);
    q = integrated_root(*m, q, 0.5 * (v + v_guess), h);
    v += 0.5 * h * (a + a_guess);
  }
  return angle_deg(q, rows.qpos.back());
}

TEST(MujocoExport, AnOptimisedMotionFlownInMujocoLandsAsTheMotion) {
  TempDir dir;
  const std::string optimised = dir / "m5";
  CliRun run = run_cli("optimize " + std::string(SALTUS_EXAMPLES_DIR) +
                       "/motions/M5-front-somersault-one-and-a-half-twists.motion.json --quiet "
                       "--knots-per-interval 3 --joint-load-weight 0 --out " +
                       optimised);
  ASSERT_EQ(run.status, 0) << run.output;
  const std::string out = export_mujoco(optimised, dir, "--fps 1000");
  const double error = mujoco_landing_error_deg(out);
  EXPECT_LT(error, 3.0) << "MuJoCo's flight lands within 3° of the optimised motion";
  std::printf("M5 optimised flown in MuJoCo: lands %.3f deg from the motion\n", error);

  // The dive as keyframed lands 13.7° off in Saltus's own simulation: MuJoCo finds it off too.
  TempDir dive_dir;
  const std::string dive = export_mujoco(
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/dive-5m-front-one-and-a-half-twists.motion.json",
      dive_dir, "--fps 1000");
  const double dive_error = mujoco_landing_error_deg(dive);
  EXPECT_GT(dive_error, 5.0) << "the check tells a motion that does not obey Newton";
  std::printf("the dive as keyframed flown in MuJoCo: lands %.3f deg from the motion\n",
              dive_error);
}

}  // namespace
}  // namespace saltus::test
