// Tests for optim/result_standing.h: runs rank solved first, then the joints within the joint
// policy, then the smaller root force, each rule on runs built to trigger it; the human-joints
// warning only where the run made a joint pay and its bounded try flies off.

#include "saltus/optim/result_standing.h"

#include <gtest/gtest.h>

#include "support/test_motions.h"

namespace saltus {
namespace {

/// A run on `model` whose average root force after is `force` (N) and whose joint `joint`
/// (segment index >= 1) carries `rise` times its peak moment before; every other joint as
/// before.
OptimizationResult standing_run(const BodyModel& model, bool solved, double force, int joint,
                                double rise) {
  OptimizationResult r;
  r.solve.solved = solved;
  r.solve.status = solved ? "solved" : "cancelled";
  r.after.metrics.avg_root_force = force;
  r.before.metrics.avg_root_force = 100.0;
  JointLoadPeak peak;
  peak.force_N = 200.0;
  peak.moment_Nm = 20.0;
  r.before.check.joint_peaks.assign(model.size(), peak);
  r.after.check.joint_peaks = r.before.check.joint_peaks;
  r.after.check.joint_peaks[joint].moment_Nm = 20.0 * rise;
  return r;
}

TEST(ResultStanding, ReadsTheSolveTheJointRiseAndTheRootForce) {
  const BodyModel model = test::bundled_model();
  const ResultStanding paying = result_standing(standing_run(model, true, 0.2, 3, 4.71), model);
  EXPECT_TRUE(paying.solved);
  EXPECT_FALSE(paying.joints_within_policy);
  EXPECT_EQ(paying.largest_rise.joint, model.segments[3].joint);
  EXPECT_NEAR(paying.largest_rise.ratio(), 4.71, 1e-12);
  EXPECT_EQ(paying.avg_root_force, 0.2);
  // At the bar itself the joints are within it.
  EXPECT_TRUE(result_standing(standing_run(model, true, 0.2, 3, kJointLoadRiseLimit), model)
                  .joints_within_policy);
}

TEST(ResultStanding, RanksSolvedThenJointsWithinThePolicyThenTheSmallerRootForce) {
  const BodyModel model = test::bundled_model();
  auto standing = [&](bool solved, double force, double rise) {
    return result_standing(standing_run(model, solved, force, 5, rise), model);
  };
  // The case: a cancelled run at 0.08 N with an ankle at 4.71x against the full run at
  // 0.239 N with every joint within 1.27x.
  const ResultStanding cancelled = standing(false, 0.08, 4.71);
  const ResultStanding full = standing(true, 0.239, 1.27);
  EXPECT_TRUE(ranks_above(full, cancelled));
  EXPECT_FALSE(ranks_above(cancelled, full));
  // Both solved: the joints within the policy first, whatever the root force.
  const ResultStanding paying = standing(true, 0.08, 4.71);
  EXPECT_TRUE(ranks_above(full, paying));
  EXPECT_FALSE(ranks_above(paying, full));
  // Both within: the smaller root force.
  const ResultStanding better = standing(true, 0.1, 1.1);
  EXPECT_TRUE(ranks_above(better, full));
  EXPECT_FALSE(ranks_above(full, better));
  // Unsolved runs among themselves: the same rules.
  EXPECT_TRUE(ranks_above(standing(false, 3.0, 1.0), standing(false, 1.0, 2.0)));
  // A tie ranks neither above the other.
  EXPECT_FALSE(ranks_above(full, standing(true, 0.239, 1.27)));
}

TEST(ResultStanding, WarnsOfHumanJointsOnlyWhenAJointPaysAndItsBoundedTryFliesOff) {
  const BodyModel model = test::bundled_model();
  OptimizationResult r = standing_run(model, true, 0.234, 8, 3.52);
  JointLoadPolish polish;
  polish.bounded_alternative = JointLoadPolish::BoundedAlternative{171.0, 0.53, 1.21};
  r.joint_load_polish = polish;
  const JointLoadRise rise = result_standing(r, model).largest_rise;
  EXPECT_EQ(human_joints_warning(r, rise),
            "with human joints instead: the polish's bounded try closest to flying as shown "
            "(every joint within 1.21x its input peak, 0.53 N) has a free flight that lands 171 "
            "deg from it: with the joints its input needs, this body does not fly these "
            "keyframes");
  // Its bounded try lands within the drift the optimiser accepts: no warning.
  r.joint_load_polish->bounded_alternative->landing_drift_deg =
      AutomaticResolution{}.max_landing_drift_deg;
  EXPECT_EQ(human_joints_warning(r, rise), "");
  // The joints within the policy: no warning.
  r.joint_load_polish->bounded_alternative->landing_drift_deg = 171.0;
  const OptimizationResult within = standing_run(model, true, 0.234, 8, 1.2);
  OptimizationResult within_polished = within;
  within_polished.joint_load_polish = r.joint_load_polish;
  EXPECT_EQ(human_joints_warning(within_polished, result_standing(within, model).largest_rise), "");
  // No polish (or no bounded try that solved): no warning.
  r.joint_load_polish.reset();
  EXPECT_EQ(human_joints_warning(r, rise), "");
}

}  // namespace
}  // namespace saltus
