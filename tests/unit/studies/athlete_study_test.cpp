// One athlete's row of the athletes study (studies/athlete_study.h), checked by dimensional
// analysis: the same motion on a body with every mass and inertia doubled (lengths kept) needs
// exactly twice the root force and joint loads (the same % of body weight), flies with twice
// the angular momentum and lands the same way. The optimisation is cut to a few iterations: what
// is checked is the row, not the solver.

#include "saltus/studies/athlete_study.h"

#include <gtest/gtest.h>

#include "saltus/base/constants.h"
#include "saltus/body/athlete_model.h"
#include "saltus/body/mass_properties.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

OptimizeOptions few_iterations() {
  OptimizeOptions options;
  options.nlp.samples = 41;
  options.solver.max_iterations = 3;
  use_paper_protocol(options);
  return options;
}

TEST(AthleteStudy, TwiceTheMassIsTwiceTheForcesAndTheSameFlight) {
  MotionFile light;
  light.model = test::bundled_model();
  light.motion = test::tuck_motion(light.model);
  MotionFile heavy = light;
  heavy.model = scale_body_model(light.model, 1.0, 2.0, "heavy");
  if (heavy.motion.takeoff.angular_momentum)
    heavy.motion.takeoff.angular_momentum = 2.0 * *light.motion.takeoff.angular_momentum;

  const AthleteOutcome a = run_athlete_case(light, few_iterations());
  const AthleteOutcome b = run_athlete_case(heavy, few_iterations());
  EXPECT_EQ(a.athlete, light.model.name);
  EXPECT_EQ(b.athlete, "heavy");
  EXPECT_EQ(a.takeoff, "own model");
  EXPECT_NEAR(b.mass_kg, 2.0 * a.mass_kg, 1e-9);
  EXPECT_NEAR(a.height_m, standing_body(light.model).height(), 1e-12);
  EXPECT_NEAR(b.height_m, a.height_m, 1e-12);
  EXPECT_LT((b.takeoff_angular_momentum - 2.0 * a.takeoff_angular_momentum).norm(),
            1e-9 * a.takeoff_angular_momentum.norm());
  EXPECT_GT(a.avg_root_force_before_N, 1.0);
  EXPECT_NEAR(b.avg_root_force_before_N, 2.0 * a.avg_root_force_before_N,
              1e-9 * a.avg_root_force_before_N);
  // The free flight of the motion as given is the same flight.
  EXPECT_NEAR(b.landing_error_before_deg, a.landing_error_before_deg, 1e-6);
  EXPECT_NEAR(b.somersaults_before, a.somersaults_before, 1e-9);
  EXPECT_NEAR(b.twists_before, a.twists_before, 1e-9);
  // A tucked back somersault: about one backward turn, no twist.
  EXPECT_LT(a.somersaults_before, -0.5);
  EXPECT_NEAR(a.twists_before, 0.0, 0.05);
  // The optimiser stopped early but moved: the after figures are the optimised motion's.
  EXPECT_LE(a.iterations, 3);
  EXPECT_LT(a.avg_root_force_after_N, a.avg_root_force_before_N);
  EXPECT_GE(a.max_root_force_after_N, a.avg_root_force_after_N);
  EXPECT_FALSE(a.peak_moment_joint.empty());
  EXPECT_FALSE(a.peak_force_joint.empty());
  EXPECT_GT(a.peak_moment_Nm, 0.0);
  EXPECT_NEAR(a.peak_force_pct_bw, 100.0 * a.peak_force_N / (a.mass_kg * kStandardGravity), 1e-9);
}

}  // namespace
}  // namespace saltus
