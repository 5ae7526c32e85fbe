// The exact-flight generator (studies/exact_flights.h): the same seed gives the same flight; the
// family covers the skills, take-offs and times the issue names; the flights do what was asked
// (somersaults as flown, the CoM lands where the apparatus says); disturbed times stay typed and
// in order. Optimising the family is tests/integration/exact_flights_test.cpp.

#include "saltus/studies/exact_flights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "saltus/base/constants.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(ExactFlights, TheSameSeedGivesTheSameFlight) {
  const BodyModel model = test::bundled_model();
  const ExactFlight a = make_exact_flight(model, 17), b = make_exact_flight(model, 17);
  ASSERT_EQ(a.motion.keyframes.size(), b.motion.keyframes.size());
  for (std::size_t i = 0; i < a.motion.keyframes.size(); ++i) {
    EXPECT_EQ(a.motion.keyframes[i].time, b.motion.keyframes[i].time);
    for (std::size_t k = 0; k < a.motion.keyframes[i].rotations.size(); ++k)
      EXPECT_EQ(a.motion.keyframes[i].rotations[k].coeffs(),
                b.motion.keyframes[i].rotations[k].coeffs());
  }
  EXPECT_NE(make_exact_flight(model, 18).description(), a.description());
}

TEST(ExactFlights, TheFamilyCoversTheSkillsAUserBrings) {
  const BodyModel model = test::bundled_model();
  std::set<FlightShape> shapes;
  int twisting = 0, platform = 0, backwards = 0, forwards = 0, many = 0, none = 0;
  double shortest = 10, longest = 0;
  for (std::uint64_t seed = 1; seed <= 80; ++seed) {
    const ExactFlight f = make_exact_flight(model, seed);
    const Motion& m = f.motion;
    SCOPED_TRACE(f.description());
    shapes.insert(f.shape);
    twisting += f.twists > 0;
    platform += f.platform;
    backwards += f.somersaults < 0;
    forwards += f.somersaults > 0;
    many += std::abs(f.somersaults) >= 2.5;
    none += f.somersaults == 0;
    shortest = std::min(shortest, m.flight_time());
    longest = std::max(longest, m.flight_time());
    ASSERT_GE(m.keyframes.size(), 5u);
    ASSERT_LE(m.keyframes.size(), 40u);
    EXPECT_GE(m.flight_time(), 0.4);
    EXPECT_LE(m.flight_time(), 2.5);
    for (std::size_t i = 0; i < m.keyframes.size(); ++i) {
      const double t = m.keyframes[i].time;
      EXPECT_NEAR(t * 100, std::round(t * 100), 1e-9) << "typed with two decimals";
      if (i > 0) {
        EXPECT_GT(t, m.keyframes[i - 1].time);
      }
    }
    // The asked-for somersault is what was flown (L calibrated on the flight itself), for the
    // flights without a twist, whose root turn is the somersault alone.
    if (f.twists == 0 && std::abs(f.somersaults) >= 1) {
      EXPECT_NEAR(f.root_turn_deg / 360.0, std::abs(f.somersaults), 0.1 * std::abs(f.somersaults));
    }
    // The motion's take-off is the flight's: a trampoline lands where it took off, a platform
    // flight lands its drop lower (the CoM parabola at T).
    const double g = kStandardGravity;
    const double fall =
        m.takeoff.com_velocity.y() * m.flight_time() - 0.5 * g * m.flight_time() * m.flight_time();
    EXPECT_NEAR(-fall, f.drop_m, 1e-6);
  }
  EXPECT_EQ(shapes.size(), 3u);
  EXPECT_GE(twisting, 5);
  EXPECT_GE(platform, 5);
  EXPECT_GE(backwards, 10);
  EXPECT_GE(forwards, 10);
  EXPECT_GE(many, 3);
  EXPECT_GE(none, 3);
  EXPECT_LT(shortest, 0.7);
  EXPECT_GT(longest, 2.2);
}

TEST(ExactFlights, DisturbedTimesStayInOrderAndTyped) {
  const BodyModel model = test::bundled_model();
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const Motion truth = make_exact_flight(model, seed).motion;
    const Motion moved = disturb_interior_times(truth, 0.1, seed);
    EXPECT_EQ(moved.keyframes.front().time, truth.keyframes.front().time);
    EXPECT_EQ(moved.keyframes.back().time, truth.keyframes.back().time);
    for (std::size_t i = 1; i < moved.keyframes.size(); ++i) {
      EXPECT_GT(moved.keyframes[i].time, moved.keyframes[i - 1].time);
      EXPECT_LE(std::abs(moved.keyframes[i].time - truth.keyframes[i].time), 0.1 + 1e-9);
      EXPECT_NEAR(moved.keyframes[i].time * 100, std::round(moved.keyframes[i].time * 100), 1e-9);
    }
  }
}

TEST(ExactFlights, TwistingFlightsTwistFromWhereTheySay) {
  const BodyModel model = test::bundled_model();
  int from_takeoff = 0, from_arm = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const ExactFlight f = make_twisting_flight(model, seed);
    SCOPED_TRACE(f.description());
    EXPECT_EQ(make_twisting_flight(model, seed).description(), f.description());
    const double duration = f.motion.flight_time();
    EXPECT_GE(duration, 1.0);
    EXPECT_LE(duration, 2.0);
    EXPECT_GE(std::abs(f.somersaults), 1.0);
    ASSERT_TRUE(f.motion.takeoff.angular_momentum);
    const Eigen::Vector3d L = *f.motion.takeoff.angular_momentum;
    // The momentum's tilt from the somersault axis is the one drawn, and only the take-off
    // twists have one.
    const double tilt = std::atan2(L.y(), std::abs(L.x())) * kDegreesPerRadian;
    if (f.twist_source == "take-off") {
      ++from_takeoff;
      EXPECT_NEAR(tilt, f.takeoff_tilt_deg, 1e-9);
      EXPECT_GE(std::abs(tilt), 5.0 - 1e-9);
      EXPECT_LE(std::abs(tilt), 30.0 + 1e-9);
    } else {
      ++from_arm;
      EXPECT_EQ(f.twist_source, "arm");
      EXPECT_EQ(L.y(), 0.0);
      EXPECT_EQ(L.z(), 0.0);
    }
    // They twist: from the take-off at least the one twist asked for nearly (the tilt is bounded
    // by 30°), from one arm a little at least.
    EXPECT_GE(std::abs(f.flown_twists), f.twist_source == "take-off" ? 0.75 : 0.05);
  }
  EXPECT_GT(from_takeoff, 0);
  EXPECT_GT(from_arm, 0);
}

/// The hard family is what issue 45's held-out flight is: one straight somersault of 1.5-2.0 s,
/// 2-3 twists from a tilted take-off with both arms coming in from overhead, 7-11 keyframes
/// whatever the body turns between them.
TEST(ExactFlights, HardTwistingFlightsAreFastTwistsOnFewKeyframes) {
  const BodyModel model = test::bundled_model();
  const int shoulder = model.joint_index("shoulder_l");
  double most_turn_per_interval = 0.0;
  std::set<std::size_t> counts;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const ExactFlight f = make_hard_twisting_flight(model, seed);
    SCOPED_TRACE(f.description());
    EXPECT_EQ(make_hard_twisting_flight(model, seed).description(), f.description());
    EXPECT_EQ(f.twist_source, "take-off");
    EXPECT_EQ(std::abs(f.somersaults), 1.0);
    const double duration = f.motion.flight_time();
    EXPECT_GE(duration, 1.5);
    EXPECT_LE(duration, 2.0);
    const std::size_t keys = f.motion.keyframes.size();
    EXPECT_GE(keys, 7u);
    EXPECT_LE(keys, 11u);
    counts.insert(keys);
    ASSERT_TRUE(f.motion.takeoff.angular_momentum);
    const Eigen::Vector3d L = *f.motion.takeoff.angular_momentum;
    const double tilt = std::atan2(L.y(), std::abs(L.x())) * kDegreesPerRadian;
    EXPECT_NEAR(tilt, f.takeoff_tilt_deg, 1e-9);
    EXPECT_LE(std::abs(tilt), 40.0 + 1e-9);
    // Nearly the 2-3 twists asked for (the tilt's three passes land within a quarter twist).
    EXPECT_GE(f.twists, 1.75);
    EXPECT_LE(f.twists, 3.25);
    // Arms overhead at take-off (shoulder flexed past 150°), in by the second keyframe's shape.
    const Eigen::AngleAxisd up(f.motion.keyframes.front().rotations[shoulder]);
    EXPECT_GT(up.angle() * kDegreesPerRadian, 150.0);
    most_turn_per_interval = std::max(most_turn_per_interval, f.root_turn_deg / (keys - 1));
  }
  EXPECT_GT(most_turn_per_interval, 150.0) << "past the other families' 150° between keyframes";
  EXPECT_GT(counts.size(), 1u) << "keyframe counts drawn, not fixed";
}

}  // namespace
}  // namespace saltus
