// "Can this athlete land it?" (core/athlete_landing.h): M7 on its own model lands, as its root
// keyframes were read off that body's free flight; on a 1.45 m, 38 kg junior with the same
// take-off spin it does not, and the check says so first, with `saltus simulate --model`'s
// landing error (the library's simulate, called here), Yeadon's words for both flights, the
// joints against the junior's strength in the CLI's words, and after a run the warnings of
// `saltus optimize` in its words.

#include "core/athlete_landing.h"

#include <gtest/gtest.h>

#include "core/athletes.h"
#include "saltus/evaluation/strength_demand.h"
#include "saltus/formats/motion_file.h"
#include "saltus/optim/result_standing.h"
#include "saltus/use_cases/athlete_models.h"
#include "support/junior_athlete.h"

namespace saltus::gui {
namespace {

MotionFile m7() {
  return load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                          "/motions/M7-double-front-one-and-a-half-twists.motion.json");
}

TEST(AthleteLanding, M7LandsOnItsOwnBody) {
  const AthleteLanding own = athlete_landing(m7(), EvaluateOptions{});
  EXPECT_TRUE(own.lands) << own.headline;
  EXPECT_EQ(own.headline.rfind("Lands it: ", 0), 0u) << own.headline;
  EXPECT_NE(own.flight_words.find("Flies 2 front somersaults with 1½ twists"), std::string::npos)
      << own.flight_words;
  EXPECT_TRUE(own.warnings.empty());
}

TEST(AthleteLanding, AJuniorWithTheSameSpinDoesNotAndTheCheckSaysSoFirst) {
  const MotionFile on_junior = motion_on_athlete(m7(), saltus::test::junior_athlete());
  const EvaluateOptions options;
  const AthleteLanding check = athlete_landing(on_junior, options);
  EXPECT_FALSE(check.lands);
  EXPECT_EQ(check.athlete, "junior 1.45 m 38 kg, same take-off spin");
  // `saltus simulate --model`'s landing error, from the library's simulate.
  const SimulationResult simulated = simulate_motion(on_junior.motion, on_junior.model, options);
  EXPECT_NEAR(check.landing_error_deg, simulated.landing_root_error_deg, 1e-9);
  EXPECT_GT(check.landing_error_deg, 90.0);
  EXPECT_EQ(check.headline.rfind("Does not land it: the body is ", 0), 0u) << check.headline;
  EXPECT_NE(check.headline.find("(more than 15° off)"), std::string::npos) << check.headline;
  EXPECT_NE(check.flight_words.find("Flies 1¾ front somersaults with 2 twists"), std::string::npos)
      << check.flight_words;
  EXPECT_NE(check.flight_words.find("keyframed: 2 front somersaults with 1½ twists"),
            std::string::npos)
      << check.flight_words;
  // Its landing pose is the free flight's last sample.
  ASSERT_EQ(check.flight.samples.size(), simulated.samples.size());
  EXPECT_TRUE(check.flight.samples.back().segment_rotation[0].isApprox(
      simulated.samples.back().segment_rotation[0]));
  // The joints against the junior's strength, in the CLI's words.
  const DenseCheck strength = evaluate_motion(on_junior.motion, on_junior.model, options).check;
  EXPECT_EQ(check.strength_words, strength_verdict_words(on_junior.model, strength.strength_peaks));
  EXPECT_EQ(check.over_strength, over_strength_lines(on_junior.model, strength.strength_peaks));
  ASSERT_EQ(check.joints.size(), static_cast<std::size_t>(on_junior.model.size() - 1));
  for (int k = 1; k < on_junior.model.size(); ++k) {
    const JointStrengthPeak& peak = strength.strength_peaks[static_cast<std::size_t>(k)];
    const JointStrengthRow& row = check.joints[static_cast<std::size_t>(k - 1)];
    EXPECT_EQ(row.share.has_value(), peak.coordinate >= 0) << k;
    if (row.share) {
      EXPECT_EQ(*row.share, peak.share) << k;
    }
    EXPECT_EQ(row.light, strength_light(row.share)) << k;
  }
}

TEST(AthleteLanding, ARunOnTheAthleteAddsTheWarningsOfSaltusOptimize) {
  const MotionFile on_junior = motion_on_athlete(m7(), saltus::test::junior_athlete());
  // A run whose left hip carries 3.52x its input and whose bounded try lands 171° off.
  OptimizationResult run;
  run.before = evaluate_motion(on_junior.motion, on_junior.model, EvaluateOptions{});
  run.after = run.before;
  const int hip = on_junior.model.joint_index("hip_l");
  run.after.check.joint_peaks[hip].moment_Nm *= 3.52;
  JointLoadPolish polish;
  polish.bounded_alternative = JointLoadPolish::BoundedAlternative{171.0, 0.53, 1.21};
  run.joint_load_polish = polish;
  const AthleteLanding check = athlete_landing(on_junior, EvaluateOptions{}, &run);
  const JointLoadRise rise =
      largest_joint_load_rise(on_junior.model, run.before.check, run.after.check);
  ASSERT_EQ(check.warnings.size(), 2u);
  EXPECT_EQ(check.warnings[0], joint_load_verdict_words(rise));
  EXPECT_EQ(check.warnings[1], human_joints_warning(run, rise));
  EXPECT_NE(check.warnings[1].find("this body does not fly these keyframes"), std::string::npos);
}

}  // namespace
}  // namespace saltus::gui
