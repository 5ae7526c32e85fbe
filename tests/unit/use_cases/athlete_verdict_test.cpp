// The one verdict on "can this athlete land it?" (use_cases/athlete_verdict.h), on motions and
// athletes built here: a tucked back somersault keyframed off its own free flight lands (the
// ground truth: the poses really occur at those times), so its verdict rests on the joints: green
// within the athlete's strength, amber on an athlete whose hips and knees were measured at a
// fraction of a newton-metre; the same keyframes flown with half the take-off spin do not land
// (red, whatever the joints); and a run whose landing rests on a joint paying many times its load
// with no human alternative is red too. Each judged against quantities computed here
// independently: the free flight's landing from simulate_motion, the strength peaks of
// evaluate_motion.

#include "saltus/use_cases/athlete_verdict.h"

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/evaluation/joint_loads.h"
#include "saltus/evaluation/strength_demand.h"
#include "saltus/optim/result_standing.h"
#include "support/ground_truth.h"

namespace saltus {
namespace {

/// The ground-truth tuck (keyframes at the times the poses occur) on `model`.
MotionFile verdict_tuck(const BodyModel& model) {
  MotionFile file;
  file.motion = test::make_ground_truth(9, 0.0).motion;
  file.model = model;
  return file;
}

/// Largest strength share of a motion on a model, from evaluate_motion.
double verdict_largest_share(const MotionFile& file) {
  const DenseCheck check = evaluate_motion(file.motion, file.model, EvaluateOptions{}).check;
  const int k = largest_strength_share(check.strength_peaks);
  return k > 0 ? check.strength_peaks[static_cast<std::size_t>(k)].share : 0.0;
}

TEST(AthleteVerdict, GreenWhenItLandsWithinTheAthletesStrength) {
  const MotionFile file = verdict_tuck(test::bundled_model());
  ASSERT_LT(verdict_largest_share(file), 1.0) << "the built tuck must be within the strength";
  const AthleteVerdict v = athlete_verdict(file, EvaluateOptions{});
  EXPECT_EQ(v.light, VerdictLight::kGreen) << v.headline;
  EXPECT_TRUE(v.lands);
  EXPECT_EQ(v.headline.rfind("Lands it (", 0), 0u) << v.headline;
  EXPECT_NE(v.headline.find("every joint within the athlete's strength"), std::string::npos)
      << v.headline;
  EXPECT_TRUE(v.reasons.empty());
  // The free flight is simulate's, and lands within the tolerance in somersault and twist.
  const SimulationResult simulated = simulate_motion(file.motion, file.model, EvaluateOptions{});
  EXPECT_NEAR(v.landing_error_deg, simulated.landing_root_error_deg, 1e-9);
  EXPECT_LE(std::abs(v.somersault_over_deg), v.tolerance_deg);
  EXPECT_LE(std::abs(v.twist_over_deg), v.tolerance_deg);
  EXPECT_EQ(verdict_light_name(v.light), "green");
  EXPECT_EQ(v.summary, "Lands it within the athlete's strength");
}

TEST(AthleteVerdict, AmberWhenItLandsButAJointIsBeyondTheAthletesStrength) {
  BodyModel weak = test::bundled_model();
  for (const char* joint : {"hip", "knee"})
    for (const char* direction : {"flexion", "extension"})
      weak.strength.measured.push_back({joint, direction, 0.5});
  const MotionFile file = verdict_tuck(weak);
  ASSERT_GT(verdict_largest_share(file), 1.0);
  const AthleteVerdict v = athlete_verdict(file, EvaluateOptions{});
  EXPECT_EQ(v.light, VerdictLight::kAmber) << v.headline;
  EXPECT_TRUE(v.lands);
  // Says it lands, then which joints and by how much, in the words `saltus evaluate` prints.
  const DenseCheck check = evaluate_motion(file.motion, file.model, EvaluateOptions{}).check;
  EXPECT_EQ(v.strength_words, strength_verdict_words(weak, check.strength_peaks));
  EXPECT_EQ(v.headline.rfind("Lands it (", 0), 0u) << v.headline;
  EXPECT_NE(v.headline.find(", but " + v.strength_words), std::string::npos) << v.headline;
  EXPECT_EQ(v.reasons, over_strength_lines(weak, check.strength_peaks));
  EXPECT_FALSE(v.reasons.empty());
  EXPECT_EQ(verdict_light_name(v.light), "amber");
  const int over = static_cast<int>(v.reasons.size());
  EXPECT_EQ(v.summary, "Lands it, but " + std::to_string(over) +
                           (over == 1 ? " joint" : " joints") + " beyond the athlete's strength");
}

TEST(AthleteVerdict, RedWhenItDoesNotLandWhateverTheJoints) {
  MotionFile file = verdict_tuck(test::bundled_model());
  // Half the spin the keyframes were flown with: it turns about half as far.
  file.motion.takeoff.angular_momentum = Eigen::Vector3d(-15, 0, 0);
  const AthleteVerdict v = athlete_verdict(file, EvaluateOptions{});
  EXPECT_EQ(v.light, VerdictLight::kRed) << v.headline;
  EXPECT_FALSE(v.lands);
  EXPECT_EQ(v.headline.rfind("Does not land it: you land ", 0), 0u) << v.headline;
  EXPECT_NE(v.headline.find("short"), std::string::npos) << v.headline;
  EXPECT_NE(v.headline.find("(more than 15° off)"), std::string::npos) << v.headline;
  const SimulationResult simulated = simulate_motion(file.motion, file.model, EvaluateOptions{});
  EXPECT_GT(simulated.landing_root_error_deg, v.tolerance_deg);
  EXPECT_LT(v.somersault_over_deg, -90.0);
  EXPECT_NEAR(v.landing_error_deg, simulated.landing_root_error_deg, 1e-9);
  EXPECT_EQ(verdict_light_name(v.light), "red");
  EXPECT_EQ(v.summary, "Does not land it");
}

TEST(AthleteVerdict, ARunThatLandsOnlyBecauseAJointPaysIsRedOneWhoseJointPaysIsAmber) {
  const MotionFile file = verdict_tuck(test::bundled_model());
  OptimizationResult run;
  run.before = evaluate_motion(file.motion, file.model, EvaluateOptions{});
  run.after = run.before;
  run.optimized_motion = file.motion;
  const int hip = file.model.joint_index("hip_l");
  run.after.check.joint_peaks[static_cast<std::size_t>(hip)].moment_Nm *= 3.52;
  const JointLoadRise rise = largest_joint_load_rise(file.model, run.before.check, run.after.check);
  ASSERT_GT(rise.ratio(), kJointLoadRiseLimit);

  const AthleteVerdict pays = athlete_verdict(file, EvaluateOptions{}, run);
  EXPECT_EQ(pays.light, VerdictLight::kAmber) << pays.headline;
  EXPECT_TRUE(pays.lands);
  ASSERT_EQ(pays.reasons.size(), 1u);
  EXPECT_EQ(pays.reasons[0], joint_load_verdict_words(rise));

  // The bounded try that kept the joints human lands 171° off.
  JointLoadPolish polish;
  polish.bounded_alternative = JointLoadPolish::BoundedAlternative{171.0, 0.53, 1.21};
  run.joint_load_polish = polish;
  const AthleteVerdict human = athlete_verdict(file, EvaluateOptions{}, run);
  EXPECT_EQ(human.light, VerdictLight::kRed) << human.headline;
  EXPECT_EQ(human.headline.rfind("Does not land it with human joints", 0), 0u) << human.headline;
  ASSERT_EQ(human.reasons.size(), 2u);
  EXPECT_EQ(human.reasons[1], human_joints_warning(run, rise));
}

}  // namespace
}  // namespace saltus
