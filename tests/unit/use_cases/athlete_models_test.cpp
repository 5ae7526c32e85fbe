// Tests for the `saltus model` use cases (use_cases/athlete_models.h): people outside the human
// range are refused naming the flag, a family of athletes all pass the model reader, a bundled
// model scales to a given height and mass.

#include "saltus/use_cases/athlete_models.h"

#include <gtest/gtest.h>

#include <random>

#include "saltus/base/input_error.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// The InputError `call` throws (or a failure).
template <typename Call>
InputError ath_error_of(Call call) {
  try {
    call();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", "", "");
}

TEST(AthleteModels, RefusesPeopleOutsideTheHumanRangeNamingTheFlag) {
  const InputError tall = ath_error_of([] { check_person_size(14.5, 38, "--height", "--mass"); });
  EXPECT_EQ(tall.file(), "--height");
  EXPECT_NE(tall.problem().find("metres"), std::string::npos) << tall.what();
  const InputError heavy = ath_error_of([] { check_person_size(1.8, 800, "--height", "--mass"); });
  EXPECT_EQ(heavy.file(), "--mass");
  const InputError bmi = ath_error_of([] { check_person_size(1.45, 180, "--height", "--mass"); });
  EXPECT_EQ(bmi.file(), "--mass");
  EXPECT_NE(bmi.problem().find("body mass index"), std::string::npos) << bmi.what();
  EXPECT_NO_THROW(check_person_size(1.45, 38, "--height", "--mass"));
  EXPECT_EQ(ath_error_of([] { parse_sex("f", "--sex"); }).file(), "--sex");
  EXPECT_EQ(parse_sex("female", "--sex"), Sex::kFemale);
}

TEST(AthleteModels, AFamilyOfAthletesAllPassTheModelReader) {
  std::mt19937 random(25);
  std::uniform_real_distribution<double> height(1.2, 2.0);
  std::uniform_real_distribution<double> mass(25.0, 120.0);
  int made = 0;
  for (int i = 0; i < 60; ++i) {
    AthleteSize size;
    size.height_m = height(random);
    size.mass_kg = mass(random);
    size.sex = i % 2 ? Sex::kFemale : Sex::kMale;
    const double bmi = size.mass_kg / (size.height_m * size.height_m);
    if (bmi < 8 || bmi > 80) continue;
    const BodyModel model = new_athlete_model(size);  // throws if the reader refuses it
    EXPECT_NEAR(model.total_mass(), size.mass_kg, 1e-9);
    ++made;
  }
  EXPECT_GE(made, 50);
}

TEST(AthleteModels, ABundledModelScalesToTheGivenHeightAndMass) {
  const BodyModel bundled = load_model_argument("zatsiorsky-66kg");
  EXPECT_EQ(bundled.name, "zatsiorsky-66kg");
  const BodyModel scaled = scaled_athlete_model(bundled, 1.85, 85.0, "");
  EXPECT_EQ(scaled.name, "zatsiorsky-66kg-1.85m-85.0kg");
  EXPECT_NEAR(scaled.total_mass(), 85.0, 1e-9);
  EXPECT_NEAR(standing_body(scaled).height(), 1.85, 1e-12);
  const double k = 1.85 / standing_body(bundled).height();
  EXPECT_NEAR(standing_body(scaled).body.inertia(0, 0),
              85.0 / 65.5 * k * k * standing_body(bundled).body.inertia(0, 0), 1e-9);
  EXPECT_EQ(ath_error_of([] { load_model_argument("no-such-model"); }).file(), "no-such-model");
  EXPECT_EQ(ath_error_of([&] { scaled_athlete_model(bundled, 1.85, 0.5, ""); }).file(), "--mass");
}

TEST(AthleteModels, YeadonModelsOfTheRealMeasurementFiles) {
  const std::string dir = std::string(SALTUS_EXAMPLES_DIR) + "/athletes/";
  const YeadonModel male = yeadon_athlete_model(dir + "yeadon-male1.txt", "dempster", 0.0, "");
  EXPECT_EQ(male.model.name, "yeadon-male1");
  EXPECT_EQ(male.model.size(), 13);
  const YeadonModel heavier = yeadon_athlete_model(dir + "yeadon-male1.txt", "clauser", 80.0, "m");
  EXPECT_NEAR(heavier.model.total_mass(), 80.0, 1e-9);
  // female1's right wrist is 14.1 cm wide for a 14.6 cm perimeter (5.5 cm on the left).
  const InputError female =
      ath_error_of([&] { yeadon_athlete_model(dir + "yeadon-female1.txt", "dempster", 0.0, ""); });
  EXPECT_NE(female.file().find("yeadon-female1.txt"), std::string::npos);
  EXPECT_EQ(female.json_path(), "Lb4p");
  EXPECT_NE(female.problem().find("La4w"), std::string::npos) << female.what();
  EXPECT_EQ(ath_error_of([&] {
              yeadon_athlete_model(dir + "yeadon-male1.txt", "average", 0.0, "");
            }).file(),
            "--densities");
  EXPECT_EQ(ath_error_of([&] {
              yeadon_athlete_model(dir + "yeadon-male1.txt", "dempster", 3000.0, "");
            }).file(),
            "--mass");
}

}  // namespace
}  // namespace saltus
