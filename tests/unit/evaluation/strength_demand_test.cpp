// What a motion asks of the athlete's strength: a static hold whose moment is known from the
// lever alone (an arm held forward against gravity) needs that moment over the gymnast's curve at
// that angle, in flexion; the dense check's peak is the largest share of a much finer grid; the
// words name the joint, the share, the moment and the capacity.

#include "saltus/evaluation/strength_demand.h"

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/base/constants.h"
#include "saltus/body/mass_properties.h"
#include "saltus/body/strength_tables.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/sampling.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(StrengthDemand, AnArmHeldForwardNeedsItsLeverOverTheGymnastsCurve) {
  const BodyModel model = test::bundled_model();  // the elite gymnast's strength at 65.5 kg
  const int upper = model.segment_index("upper_arm_r"), fore = model.segment_index("forearm_r");
  // At rest, supported at the root, the right arm raised forward to the horizontal.
  BodyState<double> state(model.size());
  state.joints[upper].q =
      Eigen::Quaterniond(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()));
  const std::vector<SampleRecord> samples = evaluate_states(model, {0.0}, {state});
  // The moment gravity makes about the shoulder: each segment's weight times its CoM's reach.
  const Segment& u = model.segments[upper];
  const Segment& f = model.segments[fore];
  const double lever_moment =
      kStandardGravity * (u.mass * -u.com.y() + f.mass * (-f.joint_position.y() - f.com.y()));
  EXPECT_NEAR(samples[0].joint_wrench[upper].tail<3>().norm(), lever_moment, 1e-9);
  // The gymnast's shoulder flexion (91.1388 N·m, peak at 0.890118 rad, σ 1.2898 rad) scaled by
  // mass × height to this body, at 90° and at rest.
  const double scale =
      model.total_mass() * standing_body(model).height() / (kGymnastMassKg * kGymnastHeightM);
  const double d = (M_PI / 2 - 0.890118) / 1.2898;
  const double capacity = 91.1388 * scale * std::exp(-0.5 * d * d);
  const AthleteStrength strength = athlete_strength(model);
  const StrengthDemand demand = strength_demand(strength, upper, state.joints[upper],
                                                samples[0].joint_wrench[upper].tail<3>());
  EXPECT_EQ(demand.coordinate, 0);
  EXPECT_TRUE(demand.positive);  // flexion holds the arm up
  EXPECT_NEAR(demand.angle_rad, M_PI / 2, 1e-12);
  EXPECT_NEAR(demand.shortening_speed, 0.0, 1e-12);
  EXPECT_NEAR(demand.moment_Nm, lever_moment, 1e-9);
  EXPECT_NEAR(demand.capacity_Nm, capacity, 1e-9 * capacity);
  EXPECT_NEAR(demand.share, lever_moment / capacity, 1e-9);
  EXPECT_FALSE(demand.extrapolated);
  EXPECT_NEAR(samples[0].strength_share[upper], demand.share, 1e-15);
  EXPECT_EQ(strength_direction_words(model, upper, demand), "right shoulder flexion");
}

TEST(StrengthDemand, DensePeaksAreTheLargestSharesOfAFinerGrid) {
  const BodyModel model = test::bundled_model();
  const Motion m = test::tuck_motion(model);
  const MotionEvaluation e = evaluate_motion(m, model);
  const std::vector<SampleRecord> fine =
      evaluate_trajectory(model, e.trajectory, uniform_times(e.trajectory.duration(), 20001));
  for (int k = 1; k < model.size(); ++k) {
    double share = 0.0;
    for (const SampleRecord& s : fine)
      share = std::max(share, s.strength_share[k]);
    const JointStrengthPeak& peak = e.check.strength_peaks[k];
    ASSERT_GE(peak.coordinate, 0) << model.segments[k].joint;
    EXPECT_NEAR(peak.share, share, 0.01 * share + 1e-9) << model.segments[k].joint;
    EXPECT_NEAR(peak.share, peak.moment_Nm / peak.capacity_Nm, 1e-12);
  }
}

TEST(StrengthDemand, WordsNameTheJointTheShareAndTheLoad) {
  BodyModel model = test::bundled_model();
  model.strength.female = true;
  std::vector<JointStrengthPeak> peaks(model.size());
  const int hip = model.joint_index("hip_l"), knee = model.joint_index("knee_r");
  peaks[hip].coordinate = 0;
  peaks[hip].positive = true;
  peaks[hip].share = 1.3;
  peaks[hip].moment_Nm = 142.0;
  peaks[hip].capacity_Nm = 109.2;
  peaks[hip].angle_rad = 95 * M_PI / 180;
  peaks[hip].shortening_speed = 3.1;
  peaks[hip].time_s = 0.42;
  peaks[knee].coordinate = 0;
  peaks[knee].positive = false;
  peaks[knee].share = 0.64;
  const std::vector<std::string> lines = over_strength_lines(model, peaks);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0],
            "left hip flexion would need 130 % of her strength at t = 0.42 s (142 of 109 N·m at "
            "95°, shortening at 3.1 rad/s)");
  EXPECT_EQ(
      strength_verdict_words(model, peaks),
      "1 joint beyond the athlete's strength (largest: left hip flexion, 130 % at t = 0.42 s)");
  peaks[hip].share = 0.5;
  EXPECT_EQ(strength_verdict_words(model, peaks),
            "every joint within the athlete's strength (largest: right knee extension, 64 % at t = "
            "0.00 s)");
  EXPECT_TRUE(over_strength_lines(model, peaks).empty());
}

}  // namespace
}  // namespace saltus
