// Tests for the `saltus model` use cases (use_cases/athlete_models.h): people outside the human
// range are refused naming the flag, a family of athletes all pass the model reader, a bundled
// model scales to a given height and mass; a motion flown by another athlete keeps its spin
// (dimensional analysis: an athlete scaled uniformly flies exactly the same rotation).

#include "saltus/use_cases/athlete_models.h"

#include <gtest/gtest.h>

#include <random>

#include "saltus/base/input_error.h"
#include "saltus/evaluation/rotation_metrics.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/motion/interpolate.h"
#include "support/cli_runner.h"
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

TEST(AthleteModels, ANameThatIsNotUtf8IsRefusedNamingTheFlag) {
  AthleteSize size;
  size.height_m = 1.6;
  size.mass_kg = 50;
  size.name = "junior\xfe";
  EXPECT_EQ(ath_error_of([&] { new_athlete_model(size); }).file(), "--name");
  const BodyModel bundled = load_model_argument("zatsiorsky-66kg");
  EXPECT_EQ(ath_error_of([&] { scaled_athlete_model(bundled, 1.6, 50, "\xc3"); }).file(), "--name");
  const std::string yeadon = std::string(SALTUS_EXAMPLES_DIR) + "/athletes/yeadon-male1.txt";
  EXPECT_EQ(ath_error_of([&] { yeadon_athlete_model(yeadon, "dempster", 0, "\xff"); }).file(),
            "--name");
  size.name = "jüngste";  // UTF-8: kept
  EXPECT_EQ(new_athlete_model(size).name, "jüngste");
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
  // female1's right wrist is 14.1 cm wide for a 14.6 cm perimeter (5.5 cm on the left): the
  // width is the typing error, the wrist a circle of that perimeter, and the warning says so.
  const YeadonModel female = yeadon_athlete_model(dir + "yeadon-female1.txt", "dempster", 0.0, "");
  EXPECT_EQ(female.model.size(), 13);
  bool wrist = false;
  for (const std::string& w : female.warnings)
    wrist = wrist || (w.find("Lb4p") != std::string::npos && w.find("La4w") != std::string::npos);
  EXPECT_TRUE(wrist);
  EXPECT_EQ(ath_error_of([&] {
              yeadon_athlete_model(dir + "yeadon-male1.txt", "average", 0.0, "");
            }).file(),
            "--densities");
  EXPECT_EQ(ath_error_of([&] {
              yeadon_athlete_model(dir + "yeadon-male1.txt", "dempster", 3000.0, "");
            }).file(),
            "--mass");
  // A mass given is within the documented 10-300 kg, 0 included; the message tells it from the
  // bound (once "300 kg is outside [10, 300]").
  const std::string male1 = dir + "yeadon-male1.txt";
  EXPECT_EQ(
      ath_error_of([&] { yeadon_athlete_model(male1, "dempster", std::optional(0.0), ""); }).file(),
      "--mass");
  const InputError above = ath_error_of(
      [&] { yeadon_athlete_model(male1, "dempster", std::optional(300.0000001), ""); });
  EXPECT_EQ(above.file(), "--mass");
  EXPECT_NE(above.problem().find("300.0000001 kg is outside"), std::string::npos) << above.what();
  // 300 kg itself is within the range; on male1's 1.64 m it is a body mass index no person has.
  const InputError at_edge =
      ath_error_of([&] { yeadon_athlete_model(male1, "dempster", std::optional(300.0), ""); });
  EXPECT_NE(at_edge.problem().find("body mass index"), std::string::npos) << at_edge.what();
}

TEST(AthleteModels, TheSameSpinOnAScaledAthleteFliesTheSameRotation) {
  // Lengths 1.2x and masses 1.5x: every inertia is 1.5 * 1.44 = 2.16 times M1's own, so the same
  // spin needs 2.16 times the angular momentum, and the free flight turns exactly as M1's does.
  const test::TempDir dir;
  const MotionFile own = load_motion_file(test::m1_path());
  const std::string big = dir / "big.model.json";
  save_body_model_file(big, scale_body_model(own.model, 1.2, 1.5, "big"));
  const MotionFile same_spin =
      load_motion_for_athlete(test::m1_path(), big, TakeoffRule::kSameSpin);
  ASSERT_TRUE(same_spin.takeoff_adaptation);
  EXPECT_EQ(same_spin.takeoff_adaptation->rule, "same spin");
  EXPECT_EQ(same_spin.takeoff_adaptation->own_model, own.model.name);
  const Eigen::Vector3d own_momentum = *own.motion.takeoff.angular_momentum;
  EXPECT_LT((same_spin.takeoff_adaptation->angular_momentum - 2.16 * own_momentum).norm(),
            1e-9 * own_momentum.norm());
  EXPECT_EQ(*same_spin.motion.takeoff.angular_momentum,
            same_spin.takeoff_adaptation->angular_momentum);
  const SimulationResult flown = simulate_motion(own.motion, own.model);
  const SimulationResult scaled = simulate_motion(same_spin.motion, same_spin.model);
  ASSERT_EQ(flown.samples.size(), scaled.samples.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < flown.samples.size(); ++i)
    largest = std::max(largest, flown.samples[i].segment_rotation.at(0).angularDistance(
                                    scaled.samples[i].segment_rotation.at(0)));
  EXPECT_LT(largest, 1e-6);
  EXPECT_NEAR(scaled.landing_vs_motion_deg, flown.landing_vs_motion_deg, 1e-4);
  // The same angular momentum on 2.16 times the inertia: about half the somersault, far short.
  const MotionFile kept = load_motion_for_athlete(test::m1_path(), big, TakeoffRule::kKeepMomentum);
  EXPECT_EQ(kept.takeoff_adaptation->rule, "same angular momentum");
  EXPECT_EQ(*kept.motion.takeoff.angular_momentum, own_momentum);
  EXPECT_GT(simulate_motion(kept.motion, kept.model).landing_vs_motion_deg,
            flown.landing_vs_motion_deg + 60.0);
  // Its own model: loaded as it is.
  EXPECT_FALSE(load_motion_for_athlete(test::m1_path(), "", TakeoffRule::kSameSpin)
                   .takeoff_adaptation.has_value());
  EXPECT_EQ(ath_error_of([] { parse_takeoff_rule("spin", "--takeoff"); }).file(), "--takeoff");
}

/// |I⁻¹·L|, rad/s: the spin `motion`'s take-off gives `model` in its pose at t = 0 (the inertia
/// from the segment poses, evaluation/rotation_metrics.h, not the reader's check).
double ath_spin(const MotionFile& file) {
  const SampleRecord start =
      evaluate_trajectory(file.model, motion_trajectory(file.motion, file.model), {0.0})[0];
  return whole_body_inertia_about_com(file.model, start)
      .ldlt()
      .solve(*file.motion.takeoff.angular_momentum)
      .norm();
}

TEST(AthleteModels, ASmallAthletesTakeOffIsCheckedAsItIsFlown) {
  // A 0.6 m, 10 kg child (model new takes 0.5 to 2.8 m): M7's own angular momentum would spin
  // it at over 500 rad/s, but same-spin flies M7's own spin. The plausibility check runs on
  // the take-off flown; it once ran on M7's own L on the small body and refused same-spin.
  const test::TempDir dir;
  const std::string m7 = std::string(SALTUS_EXAMPLES_DIR) +
                         "/motions/M7-double-front-one-and-a-half-twists.motion.json";
  const std::string small = dir / "small.model.json";
  AthleteSize child;
  child.height_m = 0.6;
  child.mass_kg = 10.0;
  child.sex = Sex::kFemale;
  save_body_model_file(small, new_athlete_model(child));
  const MotionFile own = load_motion_file(m7);
  const MotionFile flown = load_motion_for_athlete(m7, small, TakeoffRule::kSameSpin);
  EXPECT_NEAR(ath_spin(flown), ath_spin(own), 1e-6 * ath_spin(own));
  EXPECT_LT(ath_spin(own), 20.0);
  MotionFile unadapted = flown;
  unadapted.motion.takeoff.angular_momentum = own.motion.takeoff.angular_momentum;
  EXPECT_GT(ath_spin(unadapted), 200.0) << "what the check once saw";
  // The same angular momentum on the small body is what it would fly: refused, naming the
  // file, the field and where that momentum comes from.
  const InputError kept =
      ath_error_of([&] { load_motion_for_athlete(m7, small, TakeoffRule::kKeepMomentum); });
  EXPECT_EQ(kept.file(), m7);
  EXPECT_EQ(kept.json_path(), "/takeoff/angular_momentum");
  EXPECT_NE(kept.problem().find("kept from model \"" + own.model.name + "\""), std::string::npos)
      << kept.what();
  EXPECT_NE(kept.problem().find("beyond the plausible 200 rad/s"), std::string::npos)
      << kept.what();
  // Motions in memory are checked alike.
  EXPECT_THROW(adapt_takeoff_to_athlete(own, flown, TakeoffRule::kKeepMomentum), InputError);
}

TEST(AthleteModels, AMotionInMemoryIsCarriedOverAsItsFileIs) {
  // adapt_takeoff_to_athlete is load_motion_for_athlete's step after reading: from motions in
  // memory it gives what the files give, to the last bit.
  const test::TempDir dir;
  const MotionFile own = load_motion_file(test::m1_path());
  const std::string big = dir / "big.model.json";
  save_body_model_file(big, scale_body_model(own.model, 1.1, 1.3, "big"));
  for (const TakeoffRule rule : {TakeoffRule::kSameSpin, TakeoffRule::kKeepMomentum}) {
    const MotionFile from_files = load_motion_for_athlete(test::m1_path(), big, rule);
    const MotionFile from_memory =
        adapt_takeoff_to_athlete(own, load_motion_file(test::m1_path(), big), rule);
    ASSERT_TRUE(from_memory.takeoff_adaptation);
    EXPECT_EQ(from_memory.takeoff_adaptation->rule, from_files.takeoff_adaptation->rule);
    EXPECT_EQ(from_memory.takeoff_adaptation->angular_momentum,
              from_files.takeoff_adaptation->angular_momentum);
    EXPECT_EQ(*from_memory.motion.takeoff.angular_momentum,
              *from_files.motion.takeoff.angular_momentum);
    EXPECT_EQ(from_memory.model.name, "big");
  }
}

}  // namespace
}  // namespace saltus
