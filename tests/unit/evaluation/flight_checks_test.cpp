// Flight sanity checks against independent answers: a free-flight simulation (the ground truth,
// docs/testing.md) keeps its CoM on the take-off parabola and its angular momentum; a keyframed
// motion whose root is moved off does not; the ballistic flight time matches stepping the parabola.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "saltus/evaluation/flight_checks.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(FlightChecks, AFreeFlightStaysOnItsParabolaAndKeepsItsAngularMomentum) {
  const BodyModel model = test::bundled_model();
  const Motion motion = test::tuck_motion(model);
  EvaluateOptions options;
  options.samples = 121;
  const SimulationResult flight = simulate_motion(motion, model, options);
  const FlightChecks checks = flight_checks(motion.takeoff, flight.samples);
  ASSERT_EQ(checks.samples.size(), flight.samples.size());
  EXPECT_LT(checks.max_com_off_parabola_m, 1e-6);
  EXPECT_LT(checks.max_angular_momentum_drift_percent, 1e-2);
  EXPECT_DOUBLE_EQ(checks.flight_time, flight.samples.back().time);
  // The simulated CoM ends on the parabola, so the ballistic time to its final height is the
  // flight's own length.
  EXPECT_NEAR(checks.ballistic_flight_time, checks.flight_time, 1e-6);
  const FlightCheckVerdict verdict = judge_flight(checks);
  EXPECT_TRUE(verdict.on_parabola && verdict.angular_momentum_kept && verdict.flight_time_matches);
  EXPECT_EQ(verdict.failed(), 0);
}

TEST(FlightChecks, AMotionOffItsParabolaIsMeasured) {
  const BodyModel model = test::bundled_model();
  const Motion motion = test::tuck_motion(model);
  EvaluateOptions options;
  options.samples = 61;
  std::vector<SampleRecord> samples = simulate_motion(motion, model, options).samples;
  // Lift the whole flight by 5 cm after take-off: the check must say 5 cm.
  for (std::size_t k = 1; k < samples.size(); ++k)
    samples[k].com.y() += 0.05;
  samples[30].angular_momentum *= 1.1;
  const FlightChecks checks = flight_checks(motion.takeoff, samples);
  EXPECT_NEAR(checks.max_com_off_parabola_m, 0.05, 1e-6);
  EXPECT_NEAR(checks.samples[30].angular_momentum_drift_percent, 10.0, 1e-2);
  EXPECT_NEAR(checks.max_angular_momentum_drift_percent, 10.0, 1e-2);
  // 5 cm off the parabola and 10 % of L fail; the last CoM 5 cm higher comes down 5 cm later,
  // about 10 ms at the landing speed here: the flight time is judged on its own.
  const FlightCheckVerdict verdict = judge_flight(checks);
  EXPECT_FALSE(verdict.on_parabola);
  EXPECT_FALSE(verdict.angular_momentum_kept);
  EXPECT_EQ(verdict.flight_time_matches, std::abs(checks.ballistic_flight_time -
                                                  checks.flight_time) <= kFreeFlightTimeToleranceS);
  FlightChecks late = checks;
  late.ballistic_flight_time = late.flight_time + 0.011;
  EXPECT_FALSE(judge_flight(late).flight_time_matches);
  late.ballistic_flight_time = std::numeric_limits<double>::quiet_NaN();  // never comes down
  EXPECT_FALSE(judge_flight(late).flight_time_matches);
  EXPECT_EQ(judge_flight(late).failed(), 3);
}

TEST(FlightChecks, BallisticFlightTimeMatchesSteppingTheParabola) {
  Takeoff takeoff;
  takeoff.com_position = Eigen::Vector3d(0, 6.0, 0);
  takeoff.com_velocity = Eigen::Vector3d(0, 4.0, -0.5);
  // Independent path: walk the parabola of the library's ballistic_com in 10 µs steps until it
  // comes down to 1.05 m.
  double t = 0.0;
  while (ballistic_com(takeoff, t).y() > 1.05)
    t += 1e-5;
  EXPECT_NEAR(ballistic_flight_time(takeoff, 1.05), t, 2e-5);
  // Landing where it took off: 2 v / g.
  EXPECT_NEAR(ballistic_flight_time(takeoff, 6.0), 2.0 * 4.0 / 9.81, 1e-12);
  // Thrown too low to reach 8 m.
  EXPECT_TRUE(std::isnan(ballistic_flight_time(takeoff, 8.0)));
}

TEST(FlightChecks, ForwardIsNamedFromTheWayTheAthleteFacesAtTakeOff) {
  SampleRecord facing_plus_z;
  facing_plus_z.segment_rotation = {Eigen::Quaterniond::Identity()};
  EXPECT_EQ(forward_somersault_sign(facing_plus_z), 1.0);
  // Turned half a turn about the vertical (the dive faces −z): forward is negative about x.
  SampleRecord facing_minus_z;
  facing_minus_z.segment_rotation = {
      Eigen::Quaterniond(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitY()))};
  EXPECT_EQ(forward_somersault_sign(facing_minus_z), -1.0);
  // Independent check of the convention: rotating the upright body a little positively about its
  // left axis moves its head (+y) towards where it faces (+z).
  const Eigen::Vector3d head =
      Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitY();
  EXPECT_GT(head.z(), 0.0);
}

}  // namespace
}  // namespace saltus
