// Sampling a motion through inverse dynamics (evaluation/sampling.h): the time grid, and the
// recorded CoM velocity, momentum and residual against finite differences over the samples
// themselves (the residual is dP/dt − m·g and dL_G/dt, docs/formats.md).

#include "saltus/evaluation/sampling.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(UniformTimes, SpanTheDurationWithBothEndsExact) {
  const std::vector<double> t = uniform_times(2.04, 5);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t.front(), 0.0);
  EXPECT_EQ(t.back(), 2.04);
  for (std::size_t k = 1; k < t.size(); ++k)
    EXPECT_NEAR(t[k] - t[k - 1], 0.51, 1e-15);
  EXPECT_EQ(uniform_times(1.0, 2), (std::vector<double>{0.0, 1.0}));
  EXPECT_THROW(uniform_times(1.0, 1), std::invalid_argument);
}

struct Tuck {
  BodyModel model = test::bundled_model();
  Trajectory<double> trajectory = interpolate_keyframes(test::tuck_motion(model), model);
};

TEST(EvaluateTrajectory, CentreOfMassMomentumAndResidualMatchFiniteDifferences) {
  const Tuck tuck;
  const double h = 1e-5;
  std::vector<double> times;
  for (double t : {0.11, 0.52, 1.07, 1.63, 1.98}) {
    times.push_back(t - h);
    times.push_back(t);
    times.push_back(t + h);
  }
  const std::vector<SampleRecord> s = evaluate_trajectory(tuck.model, tuck.trajectory, times);
  const double mass = tuck.model.total_mass();
  for (std::size_t k = 1; k < s.size(); k += 3) {
    const SampleRecord& before = s[k - 1];
    const SampleRecord& here = s[k];
    const SampleRecord& after = s[k + 1];
    const Eigen::Vector3d com_rate = (after.com - before.com) / (2 * h);
    EXPECT_LT((here.com_velocity - com_rate).norm(), 1e-6 * com_rate.norm()) << here.time;
    const Eigen::Vector3d force =
        mass * (after.com_velocity - before.com_velocity) / (2 * h) - mass * gravity();
    const Eigen::Vector3d moment = (after.angular_momentum - before.angular_momentum) / (2 * h);
    EXPECT_GT(here.residual.head<3>().norm(), 1.0) << "an interpolation is not a free flight";
    EXPECT_LT((here.residual.head<3>() - force).norm(), 1e-4 * (1 + force.norm())) << here.time;
    EXPECT_LT((here.residual.tail<3>() - moment).norm(), 1e-4 * (1 + moment.norm())) << here.time;
  }
}

TEST(EvaluateStates, RecordsWhatEvaluateTrajectoryRecordsForTheSameStates) {
  const Tuck tuck;
  const std::vector<double> times = uniform_times(2.04, 7);
  std::vector<BodyState<double>> states(times.size(), BodyState<double>(tuck.model.size()));
  for (std::size_t k = 0; k < times.size(); ++k)
    tuck.trajectory.sample(times[k], states[k]);
  const auto a = evaluate_states(tuck.model, times, states);
  const auto b = evaluate_trajectory(tuck.model, tuck.trajectory, times);
  ASSERT_EQ(a.size(), times.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].time, times[k]);
    EXPECT_EQ(a[k].root_wrench, b[k].root_wrench);
    EXPECT_EQ(a[k].com, b[k].com);
    ASSERT_EQ(a[k].segment_position.size(), static_cast<std::size_t>(tuck.model.size()));
    ASSERT_EQ(a[k].joint_wrench.size(), static_cast<std::size_t>(tuck.model.size()));
    // The root segment's record is the root's: its origin, and its joint's wrench is F1..F6.
    EXPECT_EQ(a[k].segment_position[0], states[k].root_position);
    EXPECT_EQ(a[k].joint_wrench[0], a[k].root_wrench);
  }
  states.pop_back();
  EXPECT_THROW(evaluate_states(tuck.model, times, states), std::invalid_argument);
}

}  // namespace
}  // namespace saltus
