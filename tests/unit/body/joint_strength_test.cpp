// An athlete's strength: the published numbers come back at the sources' own conditions (the
// gymnast's table at his own size, peak angle and rest; Anderson's c1·m·h·g), the curves have
// the shapes the sources define (75 % and 50 % of Anderson's velocity curve, the cosine's
// lobe), the athlete's own measurement replaces a peak, and the population rule scales the
// upper body as the legs.

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/body/athlete_model.h"
#include "saltus/body/joint_strength.h"
#include "saltus/body/strength_tables.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

const CoordinateStrength& strength_of(const AthleteStrength& s, const BodyModel& model,
                                      const std::string& joint, int coordinate) {
  return s.joints.at(model.joint_index(joint))[coordinate];
}

BodyModel the_gymnast() {
  AthleteSize size;
  size.height_m = kGymnastHeightM;
  size.mass_kg = kGymnastMassKg;
  BodyModel model = de_leva_model(size);
  model.strength.reference = "elite-gymnast";
  return model;
}

TEST(JointStrength, TheGymnastAtHisOwnSizeHasHisTable) {
  const BodyModel model = the_gymnast();
  const AthleteStrength s = athlete_strength(model);
  // (joint, coordinate, positive direction's row, negative direction's row), as the gymnast's
  // table names them.
  struct Row {
    const char* joint;
    int coordinate;
    const char* table_joint;
    const char* positive;
    const char* negative;
  };
  for (const Row& row :
       {Row{"hip_l", 0, "hip", "flexion", "extension"},
        Row{"knee_r", 0, "knee", "flexion", "extension"},
        Row{"ankle_l", 0, "ankle", "flexion", "extension"},
        Row{"shoulder_r", 0, "shoulder", "flexion", "extension"},
        Row{"shoulder_l", 1, "shoulder", "horizontal_adduction", "horizontal_abduction"},
        Row{"shoulder_l", 2, "shoulder", "internal_rotation", "external_rotation"},
        Row{"elbow_r", 0, "elbow", "flexion", "extension"},
        Row{"elbow_l", 2, "wrist", "pronation", "supination"},
        Row{"lumbar", 0, "lumbar", "extension", "flexion"}}) {
    const CoordinateStrength& c = strength_of(s, model, row.joint, row.coordinate);
    for (const auto& [curve, direction] :
         {std::pair{c.positive, row.positive}, std::pair{c.negative, row.negative}}) {
      ASSERT_TRUE(curve) << row.joint << " " << direction;
      const GymnastRow* table = nullptr;
      for (const GymnastRow& g : gymnast_whole_body())
        if (g.joint == row.table_joint && g.direction == direction) table = &g;
      ASSERT_NE(table, nullptr);
      // At the peak angle (in the coordinate's sense) and at rest: the table's peak.
      const double at_peak = curve->angle_sign * table->angle_at_peak_active_moment_rad;
      EXPECT_NEAR(strength_capacity(*curve, at_peak, 0.0), table->max_isometric_moment_Nm,
                  1e-9 * table->max_isometric_moment_Nm)
          << row.joint << " " << direction;
    }
  }
  // Directions no source covers have no curve.
  EXPECT_FALSE(strength_of(s, model, "hip_l", 1).positive);
  EXPECT_FALSE(strength_of(s, model, "knee_l", 2).negative);
}

TEST(JointStrength, AYoungMansLegsAreAndersonsTimesMassHeightAndG) {
  AthleteSize size;
  size.height_m = 1.80;
  size.mass_kg = 75.0;
  const BodyModel model = de_leva_model(size);
  const AthleteStrength s = athlete_strength(model);
  // Table 3, young men: knee extension c1 = 0.163, c3 = 1.133 rad.
  const CoordinateStrength& knee = strength_of(s, model, "knee_l", 0);
  ASSERT_TRUE(knee.negative);
  EXPECT_NEAR(knee.negative->peak_Nm, 0.163 * 75.0 * 1.80 * 9.81, 1e-6);  // 215.87 N·m
  EXPECT_NEAR(strength_capacity(*knee.negative, 1.133, 0.0), 215.87, 0.01);
  // Its velocity curve: Anderson's (2c4c5 + ω(c5 − 3c4)) / (2c4c5 + ω(2c5 − 4c4)) crosses zero at
  // |2c4c5/(c5 − 3c4)| (c4 = 1.517, c5 = 3.952): 20.02 rad/s.
  EXPECT_NEAR(knee.negative->max_shortening_speed, 2 * 1.517 * 3.952 / (3 * 1.517 - 3.952), 1e-9);
  EXPECT_NEAR(knee.negative->velocity_factor(0.0), 1.0, 1e-12);
  EXPECT_NEAR(knee.negative->velocity_factor(knee.negative->max_shortening_speed), 0.0, 1e-12);
  // A woman of 55-65: Anderson's row for her (hip flexion c1 = 0.091).
  AthleteSize her = size;
  her.sex = Sex::kFemale;
  BodyModel older = de_leva_model(her);
  older.strength.female = true;
  older.strength.age_years = 60;
  const AthleteStrength s2 = athlete_strength(older);
  EXPECT_NEAR(strength_of(s2, older, "hip_r", 0).positive->peak_Nm, 0.091 * 75.0 * 1.80 * 9.81,
              1e-6);
}

TEST(JointStrength, CurvesHaveTheSourcesShapes) {
  BodyModel model = test::bundled_model();
  model.strength.reference = "population";
  const AthleteStrength s = athlete_strength(model);
  const StrengthCurve& hip_extension = *strength_of(s, model, "hip_l", 0).negative;
  // Young men's hip extension, c2 = 0.958, c3 = 0.932: the cosine's lobe ends π/(2 c2) from c3.
  EXPECT_NEAR(hip_extension.angle_factor(0.932), 1.0, 1e-12);
  EXPECT_NEAR(hip_extension.angle_factor(0.932 + 0.5), std::cos(0.958 * 0.5), 1e-12);
  bool extrapolated = false;
  const double edge = 0.932 + M_PI / (2 * 0.958) + 0.01;
  EXPECT_NEAR(strength_capacity(hip_extension, edge, 0.0, &extrapolated),
              kMinimumAngleFactor * hip_extension.peak_Nm, 1e-9);
  EXPECT_TRUE(extrapolated);
  strength_capacity(hip_extension, 0.932, 0.0, &extrapolated);
  EXPECT_FALSE(extrapolated);
  // Lengthening raises the capacity to the plateau 1.1 + 0.2 c6 (c6 = 0.242) and no further.
  const double w = hip_extension.max_shortening_speed;
  EXPECT_NEAR(hip_extension.velocity_factor(-w), 1.1 + 0.2 * 0.242, 1e-12);
  EXPECT_NEAR(hip_extension.velocity_factor(-3 * w), 1.1 + 0.2 * 0.242, 1e-12);
  EXPECT_GT(hip_extension.velocity_factor(-0.5 * w), 1.0);
  // Shortening lowers it monotonically through the half-speed factor.
  EXPECT_NEAR(hip_extension.velocity_factor(0.5 * w), hip_extension.factor_at_half_speed, 1e-12);
  double last = 1.0;
  for (double v = 0.05; v < 1.0; v += 0.05) {
    const double f = hip_extension.velocity_factor(v * w);
    EXPECT_LT(f, last);
    last = f;
  }
}

TEST(JointStrength, TheUpperBodyScalesAsThePopulationsLegs) {
  // At the gymnast's size a young man's shoulder is the gymnast's times the legs' ratio:
  // Anderson's hip and knee peaks (c1 = 0.161, 0.113, 0.163, 0.087) against the gymnast's
  // (175.746, 157.293, 285.619, 98.7579 N·m).
  BodyModel model = the_gymnast();
  model.strength.reference = "population";
  const AthleteStrength s = athlete_strength(model);
  const double legs = (0.161 + 0.113 + 0.163 + 0.087) * kGymnastMassKg * kGymnastHeightM * 9.81;
  const double ratio = legs / (175.746 + 157.293 + 285.619 + 98.7579);
  EXPECT_NEAR(ratio, 0.863, 0.001);
  EXPECT_NEAR(strength_of(s, model, "shoulder_l", 0).positive->peak_Nm, 91.1388 * ratio, 1e-6);
}

TEST(JointStrength, AMeasuredPeakReplacesThePublishedOne) {
  BodyModel model = test::bundled_model();
  model.strength.reference = "population";
  model.strength.measured = {{"hip", "extension", 240.0}, {"knee_l", "adduction", 30.0}};
  const AthleteStrength s = athlete_strength(model);
  for (const char* hip : {"hip_l", "hip_r"}) {
    const StrengthCurve& c = *strength_of(s, model, hip, 0).negative;
    EXPECT_DOUBLE_EQ(c.peak_Nm, 240.0);
    EXPECT_TRUE(c.measured);
    EXPECT_EQ(c.shape, StrengthCurve::AngleShape::kCosine);  // the curve keeps its shape
  }
  // A direction no source covers, measured on one side: that side only, at every angle and speed.
  const auto& adduction = strength_of(s, model, "knee_l", 1).positive;
  ASSERT_TRUE(adduction);
  EXPECT_DOUBLE_EQ(strength_capacity(*adduction, 0.7, 9.0), 30.0);
  EXPECT_FALSE(strength_of(s, model, "knee_r", 1).positive);
  model.strength.measured = {{"hip", "pronation", 10.0}};
  EXPECT_THROW(athlete_strength(model), std::invalid_argument);
  model.strength.measured.clear();
  model.strength.reference = "superhero";
  EXPECT_THROW(athlete_strength(model), std::invalid_argument);
}

TEST(JointStrength, APopulationsCurvesAgreeWithIndependentSingleMaxima) {
  // resources/strength/README.md: Šarabon, Kozinc & Perman 2021, isometric knee extension of
  // adult men, pooled 95 % CI 2.92-3.45 N·m/kg; Kruger, van Wyk & du Toit 1995, plantar flexion
  // at 30°/s of 306 untrained men, 1.02 ± 0.29 N·m/kg.
  AthleteSize size;
  size.height_m = 1.75;
  size.mass_kg = 70.0;
  BodyModel model = de_leva_model(size);
  const AthleteStrength s = athlete_strength(model);
  const double knee = strength_of(s, model, "knee_l", 0).negative->peak_Nm / size.mass_kg;
  EXPECT_GT(knee, 0.95 * 2.92);
  EXPECT_LT(knee, 3.45);
  const double plantar =
      strength_capacity(*strength_of(s, model, "ankle_l", 0).negative, 0.0, 30 * M_PI / 180) /
      size.mass_kg;
  EXPECT_GT(plantar, 1.02 - 0.29);
  EXPECT_LT(plantar, 1.02 + 0.29);
}

TEST(JointStrength, AgeGroupsAreTheNearestInTheTable) {
  EXPECT_EQ(anderson_age_group(12), "18-25");
  EXPECT_EQ(anderson_age_group(39.9), "18-25");
  EXPECT_EQ(anderson_age_group(40), "55-65");
  EXPECT_EQ(anderson_age_group(65), "55-65");
  EXPECT_EQ(anderson_age_group(66), "over-65");
}

}  // namespace
}  // namespace saltus
