// "Can this athlete land it?" in the app (core/athlete_landing.h) is the library's one verdict
// (use_cases/athlete_verdict.h, tested there colour by colour), not the app's own: M7 on a
// 1.45 m, 38 kg junior with the same take-off spin does not land (red, `saltus simulate
// --model`'s landing error from the library's simulate), with a run the optimised motion's
// verdict; and each light has its own colour and words beside the drawn free flight.

#include "core/athlete_landing.h"

#include <gtest/gtest.h>

#include <set>

#include "core/athletes.h"
#include "saltus/formats/motion_file.h"
#include "saltus/use_cases/athlete_models.h"
#include "support/junior_athlete.h"

namespace saltus::gui {
namespace {

MotionFile m7() {
  return load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                          "/motions/M7-double-front-one-and-a-half-twists.motion.json");
}

TEST(AthleteLanding, IsTheLibrarysVerdictForTheJuniorRed) {
  const MotionFile on_junior = motion_on_athlete(m7(), saltus::test::junior_athlete());
  const EvaluateOptions options;
  const AthleteLanding check = athlete_landing(on_junior, options);
  EXPECT_EQ(check.athlete, "junior 1.45 m 38 kg, same take-off spin");
  const AthleteVerdict expected = athlete_verdict(on_junior, options);
  EXPECT_EQ(check.verdict.light, VerdictLight::kRed);
  EXPECT_EQ(check.verdict.headline, expected.headline);
  EXPECT_EQ(check.verdict.reasons, expected.reasons);
  EXPECT_EQ(check.verdict.headline.rfind("Does not land it: ", 0), 0u) << check.verdict.headline;
  // `saltus simulate --model`'s landing error, from the library's simulate.
  const SimulationResult simulated = simulate_motion(on_junior.motion, on_junior.model, options);
  EXPECT_NEAR(check.verdict.landing_error_deg, simulated.landing_root_error_deg, 1e-9);
  EXPECT_GT(check.verdict.landing_error_deg, 90.0);
  EXPECT_NE(check.verdict.flight_words.find("Flies 1¾ front somersaults with 2 twists"),
            std::string::npos)
      << check.verdict.flight_words;
}

TEST(AthleteLanding, WithARunItIsTheVerdictOnTheOptimisedMotion) {
  const MotionFile own = m7();
  OptimizationResult run;
  run.before = evaluate_motion(own.motion, own.model, EvaluateOptions{});
  run.after = run.before;
  run.optimized_motion = own.motion;
  const AthleteLanding check = athlete_landing(own, EvaluateOptions{}, &run);
  const AthleteVerdict expected = athlete_verdict(own, EvaluateOptions{}, run);
  EXPECT_EQ(check.verdict.headline, expected.headline);
  EXPECT_EQ(check.verdict.light, expected.light);
}

TEST(AthleteLanding, EachLightHasItsOwnColourAndFigureLabel) {
  std::set<std::string> colours, labels;
  for (const VerdictLight light :
       {VerdictLight::kGreen, VerdictLight::kAmber, VerdictLight::kRed}) {
    AthleteVerdict v;
    v.light = light;
    colours.insert(verdict_html_colour(light));
    labels.insert(verdict_figure_label(v));
  }
  EXPECT_EQ(colours.size(), 3u);
  EXPECT_EQ(labels.size(), 3u);
  AthleteVerdict red;
  red.light = VerdictLight::kRed;
  EXPECT_EQ(verdict_figure_label(red), "does not land it");
}

}  // namespace
}  // namespace saltus::gui
