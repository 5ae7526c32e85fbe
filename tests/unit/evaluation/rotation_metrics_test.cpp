// Rotation metrics (angular momentum, whole-body inertia, somersault and twist rates and counts)
// checked by independent paths: the composite rigid-body inertia of dynamics/momentum.h, a brick
// of known principal inertia, rigid spins at known rates (L = I·ω), and a free flight.

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/dynamics/momentum.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/rotation_metrics.h"
#include "saltus/evaluation/simulate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// A tucked pose (the tuck motion's second keyframe) as a body state at rest.
BodyState<double> tucked_state(const BodyModel& model) {
  const Keyframe k = test::keyframe(model, 0.0, {-60, 0, -60, -60, -110, 120, 10});
  BodyState<double> state(model.size());
  for (int i = 0; i < model.size(); ++i)
    state.joints[i].q = k.rotations[i];
  return state;
}

/// The body frozen in `pose`, its root turning at constant world angular velocity `omega` about
/// its CoM's neighbourhood: root orientation exp(ω t)·q0. For constant world ω the body-frame
/// rate Rᵀω has zero derivative, so alpha = 0.
std::vector<SampleRecord> rigid_spin(const BodyModel& model, const BodyState<double>& pose,
                                     const Eigen::Vector3d& omega, double duration, int count) {
  const std::vector<double> times = uniform_times(duration, count);
  std::vector<BodyState<double>> states;
  for (double t : times) {
    BodyState<double> s = pose;
    const double angle = omega.norm() * t;
    const Eigen::Quaterniond turn =
        omega.norm() > 0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega.normalized()))
                         : Eigen::Quaterniond::Identity();
    s.joints[0].q = turn * pose.joints[0].q;
    s.joints[0].omega = s.joints[0].q.conjugate() * omega;
    s.joints[0].alpha.setZero();
    s.root_position = Eigen::Vector3d(0.3, 2.0, -0.1);
    s.root_velocity = Eigen::Vector3d(0.1, 3.0, 0.2);  // translation does not change L_G
    states.push_back(s);
  }
  return evaluate_states(model, times, states);
}

TEST(RotationMetrics, InertiaMatchesCompositeRigidBodyInertiaShiftedToCom) {
  const BodyModel model = test::bundled_model();
  BodyState<double> state = tucked_state(model);
  state.joints[0].q =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -2, 0.5).normalized()));
  state.joints[model.joint_index("shoulder_l")].q =
      Eigen::Quaterniond(Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, 0.2, 1).normalized()));
  state.root_position = Eigen::Vector3d(1.0, 2.5, -0.4);

  // Path 1: Featherstone's composite inertia about the root origin, root frame, then the
  // parallel-axis theorem to the CoM and rotation into the world.
  DynamicsData<double> data(model);
  inverse_dynamics(model, data, state);
  const Mat6<double> ic = composite_inertia_at_root(model, data);
  const double mass = model.total_mass();
  const Eigen::Matrix3d root_to_world = data.world_rotation[0];
  const Eigen::Vector3d c = root_to_world.transpose() * (data.com - data.world_position[0]);
  const Eigen::Matrix3d about_com_root =
      ic.topLeftCorner<3, 3>() -
      mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  const Eigen::Matrix3d expected = root_to_world * about_com_root * root_to_world.transpose();

  // Path 2: the direct sum over segments in rotation_metrics.
  const SampleRecord record = evaluate_states(model, {0.0}, {state}).front();
  const Eigen::Matrix3d actual = whole_body_inertia_about_com(model, record);
  EXPECT_LT((actual - expected).norm(), 1e-10 * expected.norm());
  EXPECT_LT((actual - actual.transpose()).norm(), 1e-12);
}

TEST(RotationMetrics, BrickOfKnownInertiaSpinsWithLEqualIOmega) {
  BodyModel model;
  model.name = "brick";
  Segment s;
  s.name = "brick";
  s.joint = "root";
  s.mass = 7.0;
  s.com = Eigen::Vector3d(0.05, -0.1, 0.02);
  s.inertia = Eigen::Vector3d(0.1, 0.2, 0.3).asDiagonal();
  model.segments.push_back(s);

  BodyState<double> pose(1);
  pose.joints[0].q = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()));
  const Eigen::Vector3d omega(2.0, -1.0, 0.5);
  const std::vector<SampleRecord> samples = rigid_spin(model, pose, omega, 1.0, 5);
  const std::vector<RotationSample> rotation = rotation_metrics(model, samples);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    // Analytic: principal inertia rotated into the world by the brick's current orientation.
    const Eigen::Matrix3d r = samples[k].segment_rotation[0].toRotationMatrix();
    const Eigen::Matrix3d expected_inertia = r * s.inertia * r.transpose();
    EXPECT_LT((rotation[k].inertia - expected_inertia).norm(), 1e-12);
    EXPECT_LT((rotation[k].angular_momentum - expected_inertia * omega).norm(), 1e-10);
    EXPECT_LT((rotation[k].angular_velocity - omega).norm(), 1e-10);
    EXPECT_NEAR(rotation[k].somersault_inertia, expected_inertia(0, 0), 1e-12);
  }
}

TEST(RotationMetrics, ArticulatedBodyInRigidSpinRecoversItsAngularVelocity) {
  const BodyModel model = test::bundled_model();
  const Eigen::Vector3d omega(-4.0, 1.5, 0.7);
  const std::vector<SampleRecord> samples = rigid_spin(model, tucked_state(model), omega, 0.8, 9);
  const std::vector<RotationSample> rotation = rotation_metrics(model, samples);
  for (const RotationSample& r : rotation) {
    // L comes from the spatial-momentum recursion of dynamics/momentum.h, I from the segment sum.
    EXPECT_LT((r.angular_momentum - r.inertia * omega).norm(), 1e-9 * r.angular_momentum.norm());
    EXPECT_LT((r.angular_velocity - omega).norm(), 1e-9);
    EXPECT_NEAR(r.somersault_rate, omega.x(), 1e-9);
  }
}

TEST(RotationMetrics, CountsSomersaultsOfAConstantSpin) {
  const BodyModel model = test::bundled_model();
  const double duration = 2.0;
  const double revolutions = -1.25;  // one and a quarter backward somersaults
  const Eigen::Vector3d omega(2.0 * M_PI * revolutions / duration, 0, 0);
  const std::vector<SampleRecord> samples =
      rigid_spin(model, BodyState<double>(model.size()), omega, duration, 41);
  const std::vector<RotationSample> rotation = rotation_metrics(model, samples);
  EXPECT_NEAR(rotation.front().somersaults, 0.0, 1e-15);
  EXPECT_NEAR(rotation.back().somersaults, revolutions, 1e-9);
  EXPECT_NEAR(rotation[20].somersaults, revolutions / 2, 1e-9);
  EXPECT_NEAR(rotation.back().twists, 0.0, 1e-9);
}

TEST(RotationMetrics, CountsTwistsAboutTheLongAxis) {
  const BodyModel model = test::bundled_model();
  const double duration = 1.5;
  // Upright straight body turning about its own long axis (world y): a pure twist.
  const Eigen::Vector3d omega(0, 2.0 * M_PI * 2.0 / duration, 0);
  const std::vector<SampleRecord> samples =
      rigid_spin(model, BodyState<double>(model.size()), omega, duration, 31);
  const std::vector<RotationSample> rotation = rotation_metrics(model, samples);
  EXPECT_NEAR(rotation.back().twists, 2.0, 1e-9);
  EXPECT_NEAR(rotation.back().somersaults, 0.0, 1e-9);
  EXPECT_NEAR(rotation[10].twist_rate, omega.y(), 1e-9);
}

TEST(RotationMetrics, TuckedFreeFlightSpinsFasterWhenInertiaIsSmaller) {
  const BodyModel model = test::bundled_model();
  const Motion motion = test::tuck_motion(model);
  EvaluateOptions options;
  options.samples = 161;
  const SimulationResult flight = simulate_motion(motion, model, options);
  const std::vector<RotationSample> rotation = rotation_metrics(model, flight.samples);

  const RotationSample& start = rotation.front();
  double min_inertia = start.somersault_inertia;
  double max_rate = std::abs(start.somersault_rate);
  for (const RotationSample& r : rotation) {
    // Free flight: L is constant; a left-right symmetric body without twist has no products of
    // inertia with x, so ω_x = L_x / I_xx exactly.
    EXPECT_LT((r.angular_momentum - start.angular_momentum).norm(),
              1e-4 * start.angular_momentum.norm());
    EXPECT_NEAR(r.somersault_rate * r.somersault_inertia, r.angular_momentum.x(),
                1e-6 * std::abs(r.angular_momentum.x()));
    min_inertia = std::min(min_inertia, r.somersault_inertia);
    max_rate = std::max(max_rate, std::abs(r.somersault_rate));
  }
  // The tuck at least halves the inertia of the open take-off pose and spins correspondingly
  // faster: the teaching point.
  EXPECT_LT(min_inertia, 0.5 * start.somersault_inertia);
  EXPECT_NEAR(max_rate / std::abs(start.somersault_rate), start.somersault_inertia / min_inertia,
              1e-3 * start.somersault_inertia / min_inertia);
  // A backward somersault: the whole body's ω_x never changes sign in free flight (L_x < 0 and
  // I_xx > 0), so its integral only ever grows in size; the trunk's own somersault angle
  // (Yeadon's, the counts) may lead or lag it while the shape changes, and ends backward too.
  for (const RotationSample& r : rotation)
    EXPECT_LT(r.somersault_rate, 0.0);
  EXPECT_LT(rotation.back().somersaults, -0.5);
  EXPECT_NEAR(rotation.back().somersault_deg - rotation.front().somersault_deg,
              360.0 * rotation.back().somersaults, 1e-9);
}

}  // namespace
}  // namespace saltus
