// Joint loads (evaluation/joint_loads.h and the dense check's joint peaks): a body that keeps its
// shape and does not turn falls with every joint unloaded to rounding (each segment's weight is all
// the acceleration it has); the dense peaks are the largest loads found on a much finer grid;
// ratios are after over before with small loads counted at the floors.

#include "saltus/evaluation/joint_loads.h"

#include <gtest/gtest.h>

#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/sampling.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(JointLoads, AShapeThatNeitherChangesNorTurnsFallsWithEveryJointUnloaded) {
  const BodyModel model = test::bundled_model();
  Motion m = test::base_motion("a pike held in free fall");
  const test::PoseDeg pike{0, 0, -150, 0, -100};
  m.keyframes = {test::keyframe(model, 0.0, pike), test::keyframe(model, 0.7, pike),
                 test::keyframe(model, 1.4, pike)};
  const MotionEvaluation e = evaluate_motion(m, model);
  ASSERT_EQ(static_cast<int>(e.check.joint_peaks.size()), model.size());
  for (int k = 1; k < model.size(); ++k) {
    EXPECT_LT(e.check.joint_peaks[k].force_N, 1e-3) << model.segments[k].joint;
    EXPECT_LT(e.check.joint_peaks[k].moment_Nm, 1e-3) << model.segments[k].joint;
  }
}

TEST(JointLoads, DensePeaksAreTheLargestLoadsOfAFinerGrid) {
  const BodyModel model = test::bundled_model();
  const Motion m = test::tuck_motion(model);
  const MotionEvaluation e = evaluate_motion(m, model);
  const double duration = e.trajectory.duration();
  const std::vector<SampleRecord> fine =
      evaluate_trajectory(model, e.trajectory, uniform_times(duration, 20001));
  for (int k = 1; k < model.size(); ++k) {
    double force = 0, moment = 0;
    for (const SampleRecord& s : fine) {
      force = std::max(force, s.joint_wrench[k].head<3>().norm());
      moment = std::max(moment, s.joint_wrench[k].tail<3>().norm());
    }
    const JointLoadPeak& peak = e.check.joint_peaks[k];
    EXPECT_NEAR(peak.force_N, force, 0.01 * force + 1e-9) << model.segments[k].joint;
    EXPECT_NEAR(peak.moment_Nm, moment, 0.01 * moment + 1e-9) << model.segments[k].joint;
    EXPECT_GE(peak.force_time_s, 0.0);
    EXPECT_LE(peak.force_time_s, duration);
  }
}

TEST(JointLoads, RatiosAreAfterOverBeforeWithFloors) {
  const BodyModel model = test::bundled_model();
  DenseCheck before, after;
  before.joint_peaks.assign(model.size(), JointLoadPeak{});
  after.joint_peaks = before.joint_peaks;
  const int hip = model.joint_index("hip_r"), knee = model.joint_index("knee_l");
  before.joint_peaks[hip] = {200.0, 0.1, 30.0, 0.2};
  after.joint_peaks[hip] = {300.0, 1.9, 15.0, 2.0};
  after.joint_peaks[knee] = {5.0, 0.0, 4.0, 2.04};  // from nothing: against the floors
  const std::vector<JointLoadRise> rises = joint_load_rises(model, before, after);
  ASSERT_EQ(static_cast<int>(rises.size()), model.size() - 1);
  const JointLoadRise& h = rises[hip - 1];
  EXPECT_EQ(h.joint, "hip_r");
  EXPECT_DOUBLE_EQ(h.force_ratio, 1.5);
  EXPECT_DOUBLE_EQ(h.moment_ratio, 0.5);
  EXPECT_DOUBLE_EQ(h.ratio(), 1.5);
  const JointLoadRise& k = rises[knee - 1];
  EXPECT_DOUBLE_EQ(k.force_ratio, 1.0);
  EXPECT_DOUBLE_EQ(k.moment_ratio, 4.0 / kJointMomentFloorNm);
  const JointLoadRise largest = largest_joint_load_rise(model, before, after);
  EXPECT_EQ(largest.joint, "knee_l");
  EXPECT_NEAR(body_weight_N(model), model.total_mass() * 9.81, 1e-9);
  // In words, by the larger ratio: the knee's moment, the hip's force in % of body weight.
  EXPECT_EQ(joint_load_rise_words(largest, 640.0),
            "knee_l, moment 4 N·m at t = 2.040 s after, 0 N·m before (4.00x)");
  EXPECT_EQ(joint_load_rise_words(h, 640.0),
            "hip_r, force 300 N (47 % of body weight) at t = 1.900 s after, 200 N before (1.50x)");
  // What it means: at the limit (1.5x) every joint is within it; above, the joint is named.
  EXPECT_EQ(joint_load_verdict_words(h), "every joint within 1.50x of its peak load before");
  EXPECT_EQ(joint_load_verdict_words(largest),
            "knee_l carries 4.00x its peak load before (more than 1.5x): the optimiser made it pay "
            "for the root force; do not read it as the athlete's");
}

}  // namespace
}  // namespace saltus
