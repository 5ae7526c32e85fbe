// simulate_motion (evaluation/simulate.h): the free flight of a motion's joint movements obeys the
// conservation laws — the take-off angular momentum about the CoM stays, the CoM follows the
// ballistic parabola, no root wrench is needed — and the joints, which follow the keyframes,
// land on them, so only the whole body's orientation can miss.

#include "saltus/evaluation/simulate.h"

#include <gtest/gtest.h>

#include "saltus/evaluation/sampling.h"
#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(SimulateMotion, ConservesTheTakeoffMomentumAndFollowsTheParabola) {
  const BodyModel model = test::bundled_model();
  for (Motion motion : {test::tuck_motion(model), test::twist_motion(model)}) {
    SCOPED_TRACE(motion.name);
    motion.takeoff.angular_momentum = Eigen::Vector3d(-30.0, 2.0, 1.0);
    EvaluateOptions options;
    options.samples = 61;
    const SimulationResult r = simulate_motion(motion, model, options);
    EXPECT_TRUE(r.angular_momentum_from_file);
    EXPECT_EQ(r.angular_momentum, *motion.takeoff.angular_momentum);
    ASSERT_EQ(r.samples.size(), 61u);
    for (const SampleRecord& s : r.samples) {
      EXPECT_LT((s.angular_momentum - r.angular_momentum).norm(), 1e-6 * 30) << s.time;
      EXPECT_LT((s.com - ballistic_com(motion.takeoff, s.time)).norm(), 1e-6) << s.time;
    }
    EXPECT_LT(r.landing_com_error_m, 1e-6);
    EXPECT_LT(r.metrics.avg_root_force, 1e-6);
  }
}

TEST(SimulateMotion, WithoutATakeoffMomentumUsesTheAverageOfTheMotionsOwn) {
  // The constant nearest the interpolation's L(t): its time average, here by Simpson's rule on
  // a finer grid than the library's; the flight then keeps it.
  const BodyModel model = test::bundled_model();
  const Motion motion = test::tuck_motion(model);
  ASSERT_FALSE(motion.takeoff.angular_momentum);
  const SimulationResult r = simulate_motion(motion, model, {});
  EXPECT_FALSE(r.angular_momentum_from_file);
  const std::vector<SampleRecord> own = evaluate_trajectory(
      model, interpolate_keyframes(motion, model), uniform_times(motion.flight_time(), 1001));
  Eigen::Vector3d average = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < own.size(); ++k) {
    const double weight = k == 0 || k + 1 == own.size() ? 1.0 : (k % 2 ? 4.0 : 2.0);
    average += weight * own[k].angular_momentum;
  }
  average /= 3.0 * (own.size() - 1);
  EXPECT_LT((r.angular_momentum - average).norm(), 1e-3 * average.norm());
  EXPECT_LT((r.samples.back().angular_momentum - r.angular_momentum).norm(), 1e-6 * average.norm());
  EXPECT_GT(r.angular_momentum_spread, 1.0) << "an interpolation does not conserve L";
}

TEST(SimulateMotion, OnlyTheWholeBodyOrientationCanMissTheLanding) {
  const BodyModel model = test::bundled_model();
  Motion motion = test::pike_motion(model);
  motion.takeoff.angular_momentum = Eigen::Vector3d(25.0, 0.0, 0.0);
  const SimulationResult r = simulate_motion(motion, model, {});
  ASSERT_EQ(r.landing_joint_error_deg.size(), static_cast<std::size_t>(model.size()));
  for (const Segment& s : model.segments) {
    ASSERT_EQ(r.landing_joint_error_deg.count(s.joint), 1u) << s.joint;
    if (s.parent >= 0) {
      EXPECT_LT(r.landing_joint_error_deg.at(s.joint), 1e-4) << s.joint;
    }
  }
  EXPECT_EQ(r.landing_root_error_deg, r.landing_joint_error_deg.at("root"));
  // A guessed take-off momentum does not land the somersault where the keyframes say.
  EXPECT_GT(r.landing_root_error_deg, 1.0);
}

}  // namespace
}  // namespace saltus
