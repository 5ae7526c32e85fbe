// Keyframes too far apart for the twist (evaluation/keyframe_spacing.h), on an analytic case: the
// standing body spinning about its long axis, L = I·ω from its own inertia, keyed every 270° of
// spin (the interpolation turns the short way, -90°, each time) and every 90° (it keeps up); and
// on the hard twisting family (studies/exact_flights.h), exact flights keyed at 7-11 times.

#include "saltus/evaluation/keyframe_spacing.h"

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/base/constants.h"
#include "saltus/body/mass_properties.h"
#include "saltus/studies/exact_flights.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// The standing body spinning at `degrees_per_interval` about its long axis y, keyed at
/// `intervals` + 1 equal times over 1 s with the root turned as the spin turns it.
Motion spinning_body(const BodyModel& model, double degrees_per_interval, int intervals) {
  const double duration = 1.0;
  const double omega = degrees_per_interval / kDegreesPerRadian * intervals / duration;
  Motion motion;
  motion.name = "spin";
  motion.model = model.name;
  motion.takeoff.com_velocity = Eigen::Vector3d(0.0, 0.5 * kStandardGravity * duration, 0.0);
  motion.takeoff.angular_momentum =
      standing_body(model).body.inertia * Eigen::Vector3d(0.0, omega, 0.0);
  for (int i = 0; i <= intervals; ++i) {
    Keyframe k;
    k.time = duration * i / intervals;
    k.rotations.assign(model.size(), Eigen::Quaterniond::Identity());
    k.rotations[0] =
        Eigen::Quaterniond(Eigen::AngleAxisd(omega * k.time, Eigen::Vector3d::UnitY()));
    motion.keyframes.push_back(k);
  }
  return motion;
}

TEST(SparseTwistIntervals, ASpinKeyedEvery270DegreesIsFlaggedInEachInterval) {
  const BodyModel model = test::bundled_model();
  const std::vector<SparseTwistInterval> found =
      sparse_twist_intervals(spinning_body(model, 270.0, 3), model);
  ASSERT_EQ(found.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    SCOPED_TRACE(sparse_twist_words(found[i]));
    EXPECT_EQ(found[i].first_keyframe, i);
    EXPECT_NEAR(found[i].flight_twist_deg, 270.0, 15.0);
    EXPECT_NEAR(found[i].interpolation_twist_deg, -90.0, 15.0);
  }
  const std::string words = sparse_twist_words(found[1]);
  EXPECT_NE(words.find("keyframes 2-3 (0.33-0.67 s)"), std::string::npos) << words;
  EXPECT_NE(words.find("add a keyframe near t = 0.50 s"), std::string::npos) << words;
}

TEST(SparseTwistIntervals, ASpinKeyedEvery90DegreesHolds) {
  const BodyModel model = test::bundled_model();
  EXPECT_TRUE(sparse_twist_intervals(spinning_body(model, 90.0, 9), model).empty());
}

TEST(SparseTwistIntervals, TheMixedFamilyHoldsAndTheHardFamilyIsNamedWhereItLosesATwist) {
  const BodyModel model = test::bundled_model();
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const ExactFlight f = make_exact_flight(model, seed);
    EXPECT_TRUE(sparse_twist_intervals(f.motion, model).empty()) << f.description();
  }
  // Seed 12: 2 twists on 7 keyframes, ~120 deg of twist each interval on average.
  const ExactFlight hard = make_hard_twisting_flight(model, 12);
  const std::vector<SparseTwistInterval> found = sparse_twist_intervals(hard.motion, model);
  ASSERT_FALSE(found.empty()) << hard.description();
  double flight_total = 0.0;
  for (const SparseTwistInterval& i : found) {
    EXPECT_GT(std::abs(i.flight_twist_deg), 90.0) << sparse_twist_words(i);
    flight_total += i.flight_twist_deg;
  }
  EXPECT_GT(std::abs(flight_total), 0.0);
}

}  // namespace
}  // namespace saltus
