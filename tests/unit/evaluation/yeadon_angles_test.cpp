// Yeadon's somersault, tilt and twist (evaluation/yeadon_angles.h), checked by paths that do not
// use them: the Cardan product written out reads back to its angles; the rates solve the
// finite-differenced angles of a smooth path; a torque-free axisymmetric body flown by the
// free-flight integrator keeps its tilt and twists at the rate Euler's equations give in closed
// form, L·sin θ·(1/I − 1/J); a motion that only somersaults has no tilt or twist; the mirror
// image of a twisting flight, flown again, twists the other way as far.

#include "saltus/evaluation/yeadon_angles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "saltus/dynamics/free_flight.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/formats/motion_file.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

Eigen::Quaterniond cardan(double phi, double theta, double psi) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitX()) *
                            Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitY()));
}

TEST(YeadonAngles, TheCardanProductReadsBackToItsAngles) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double phi = 3.1 * u(rng), theta = 1.5 * u(rng), psi = 3.1 * u(rng);
    const Eigen::Vector3d a = somersault_tilt_twist(cardan(phi, theta, psi));
    EXPECT_NEAR(a[0], phi, 1e-12);
    EXPECT_NEAR(a[1], theta, 1e-12);
    EXPECT_NEAR(a[2], psi, 1e-12);
    // The quaternion's sign does not matter.
    const Eigen::Quaterniond q = cardan(phi, theta, psi);
    EXPECT_NEAR((somersault_tilt_twist(Eigen::Quaterniond(-q.coeffs())) - a).norm(), 0, 1e-12);
  }
}

TEST(YeadonAngles, RatesSolveTheFiniteDifferencedAngles) {
  // A smooth path with all three angles moving; ω in the body frame from the path itself.
  const auto path = [](double t) {
    return cardan(-4.0 * t + 0.3, 0.4 * std::sin(3 * t), 5.0 * t * t);
  };
  for (double t : {0.1, 0.5, 0.9, 1.3}) {
    const double h = 1e-6;
    const Eigen::Quaterniond q = path(t);
    const Eigen::Quaterniond dq(
        Eigen::Vector4d((path(t + h).coeffs() - path(t - h).coeffs()) / (2 * h)));
    const Eigen::Vector3d omega = 2.0 * (q.conjugate() * dq).vec();
    const Eigen::Vector3d rates = somersault_tilt_twist_rates(somersault_tilt_twist(q), omega);
    EXPECT_NEAR(rates[0], -4.0, 1e-6);
    EXPECT_NEAR(rates[1], 1.2 * std::cos(3 * t), 1e-6);
    EXPECT_NEAR(rates[2], 10.0 * t, 1e-6);
  }
}

TEST(YeadonAngles, ATorqueFreeAxisymmetricBodyKeepsItsTiltAndTwistsAtEulersRate) {
  // One rigid segment, axisymmetric about its long axis y: I about x and z, J about y.
  BodyModel body;
  body.name = "rigid axisymmetric";
  Segment s;
  s.name = "abdomen";
  s.joint = "root";
  s.mass = 60.0;
  const double I = 12.0, J = 1.1;
  s.inertia = Eigen::Vector3d(I, J, I).asDiagonal();
  body.segments.push_back(s);
  for (const double tilt_deg : {5.0, 15.0, 30.0}) {
    const double theta = tilt_deg * M_PI / 180.0, L = 60.0;
    FreeFlightInitialState initial;
    initial.com_velocity = Eigen::Vector3d(0, 5, 0);
    initial.angular_momentum = Eigen::Vector3d(L, 0, 0);  // about the somersault axis
    initial.root_orientation = cardan(0.0, theta, 0.0);
    std::vector<double> times;
    for (int i = 0; i <= 400; ++i)
      times.push_back(1.2 * i / 400);
    const std::vector<BodyState<double>> flown = simulate_free_flight(
        body, [](double, BodyState<double>&) {}, initial, times);
    std::vector<Eigen::Quaterniond> roots;
    for (const BodyState<double>& state : flown)
      roots.push_back(state.joints[0].q);
    const std::vector<Eigen::Vector3d> angles = unwrapped_angles(roots);
    for (std::size_t k = 0; k < angles.size(); ++k) {
      EXPECT_NEAR(angles[k][1], theta, 1e-6) << tilt_deg << "° at t = " << times[k];
      EXPECT_NEAR(angles[k][0], L / I * times[k], 1e-5) << tilt_deg;
      EXPECT_NEAR(angles[k][2], L * std::sin(theta) * (1.0 / I - 1.0 / J) * times[k], 1e-5)
          << tilt_deg;
      const Eigen::Vector3d rates =
          somersault_tilt_twist_rates(angles[k], flown[k].joints[0].omega);
      EXPECT_NEAR(rates[2], L * std::sin(theta) * (1.0 / I - 1.0 / J), 1e-6);
    }
  }
}

TEST(YeadonAngles, AMotionThatOnlySomersaultsHasNoTiltAndNoTwist) {
  const MotionFile m1 = load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                         "/motions/M1-straight-back-somersault.motion.json");
  const MotionEvaluation e = evaluate_motion(m1.motion, m1.model);
  const YeadonSummary s = yeadon_summary(e.trajectory);
  EXPECT_NEAR(s.somersaults, -1.0, 0.01);
  EXPECT_LT(s.max_tilt_deg, 1e-6);
  EXPECT_NEAR(s.twists, 0.0, 1e-9);
  EXPECT_EQ(s.description, "1 back somersault");
}

/// The motion reflected in the sagittal plane (x → −x): left and right swap, each rotation's
/// axis is reflected (w, x, y, z) → (w, x, −y, −z), the take-off mirrored.
Motion mirrored(const Motion& m, const BodyModel& model) {
  Motion out = m;
  const auto partner = [&](int k) {
    std::string name = model.segments[k].name;
    const std::size_t n = name.size();
    if (n > 2 && name.compare(n - 2, 2, "_l") == 0)
      name.replace(n - 2, 2, "_r");
    else if (n > 2 && name.compare(n - 2, 2, "_r") == 0)
      name.replace(n - 2, 2, "_l");
    for (int i = 0; i < model.size(); ++i)
      if (model.segments[i].name == name) return i;
    return k;
  };
  for (std::size_t i = 0; i < m.keyframes.size(); ++i)
    for (int k = 0; k < model.size(); ++k) {
      const Eigen::Quaterniond q = m.keyframes[i].rotations[partner(k)];
      out.keyframes[i].rotations[k] = Eigen::Quaterniond(q.w(), q.x(), -q.y(), -q.z());
    }
  out.takeoff.com_position.x() *= -1;
  out.takeoff.com_velocity.x() *= -1;
  if (m.takeoff.angular_momentum) {
    const Eigen::Vector3d L = *m.takeoff.angular_momentum;
    out.takeoff.angular_momentum = Eigen::Vector3d(L.x(), -L.y(), -L.z());
  }
  return out;
}

TEST(YeadonAngles, TheMirrorImageOfATwistingFlightTwistsTheOtherWay) {
  const MotionFile m5 =
      load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                       "/motions/M5-front-somersault-one-and-a-half-twists.motion.json");
  const SimulationResult a = simulate_motion(m5.motion, m5.model);
  const SimulationResult b = simulate_motion(mirrored(m5.motion, m5.model), m5.model);
  const auto roots = [](const SimulationResult& s) {
    std::vector<Eigen::Quaterniond> out;
    for (const SampleRecord& r : s.samples)
      out.push_back(r.segment_rotation[0]);
    return out;
  };
  const YeadonSummary sa = yeadon_summary(roots(a)), sb = yeadon_summary(roots(b));
  EXPECT_GT(std::abs(sa.twists), 1.0);
  EXPECT_NEAR(sb.twists, -sa.twists, 1e-6);
  EXPECT_NEAR(sb.somersaults, sa.somersaults, 1e-6);
  EXPECT_NEAR(sb.max_tilt_deg, sa.max_tilt_deg, 1e-4);
  const std::vector<Eigen::Vector3d> wa = unwrapped_angles(roots(a)),
                                     wb = unwrapped_angles(roots(b));
  for (std::size_t k = 0; k < wa.size(); ++k)
    EXPECT_NEAR(wb[k][1], -wa[k][1], 1e-6);
}

TEST(YeadonAngles, CountsInACoachsWords) {
  EXPECT_EQ(somersault_twist_words(0.02, 0.0), "no somersault");
  EXPECT_EQ(somersault_twist_words(-0.26, 0.0), "a ¼ back somersault");
  EXPECT_EQ(somersault_twist_words(1.49, 2.02), "1½ front somersaults with 2 twists to the left");
  EXPECT_EQ(somersault_twist_words(-2.0, -0.5), "2 back somersaults with ½ twist to the right");
  EXPECT_EQ(somersault_twist_words(1.0, -1.45), "1 front somersault with 1½ twists to the right");
  EXPECT_EQ(somersault_twist_words(0.5, 1.0), "a ½ front somersault with 1 twist to the left");
}

}  // namespace
}  // namespace saltus
