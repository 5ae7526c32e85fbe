// Tests for Yeadon's model of a person (body/yeadon_model.h) on the real measurements of
// examples/athletes: single-density segments weigh their density times the volume of their
// solids in closed form, the given mass scales every density, the model passes the model reader,
// and bad geometry or typing errors are named by key.

#include "saltus/body/yeadon_model.h"

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/base/input_error.h"
#include "saltus/body/mass_properties.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/yeadon_measurements_file.h"

namespace saltus {
namespace {

YeadonInput ym_male() {
  const std::string path = std::string(SALTUS_EXAMPLES_DIR) + "/athletes/yeadon-male1.txt";
  YeadonInput in;
  in.file = path;
  in.measured = load_yeadon_measurements(path).measured;
  in.name = "male1";
  return in;
}

const Segment& ym_segment(const BodyModel& model, const std::string& name) {
  return model.segments.at(static_cast<std::size_t>(model.segment_index(name)));
}

/// Volume of the frustum between circles of perimeters p0 and p1, h apart.
double ym_frustum(double p0, double p1, double h) {
  const double a = p0 / (2 * M_PI), b = p1 / (2 * M_PI);
  return M_PI * h / 3 * (a * a + a * b + b * b);
}

TEST(YeadonModel, SingleDensitySegmentsWeighTheirDensityTimesTheirVolume) {
  const YeadonInput in = ym_male();
  const YeadonModel made = yeadon_model(in);
  EXPECT_EQ(made.solids, 40);
  ASSERT_EQ(made.model.size(), 13);
  const auto m = [&](const std::string& key) { return in.measured.at(key); };
  // Left upper arm: two frustums of circles (Dempster's upper-arm density 1.07 kg/L).
  const double arm = ym_frustum(m("La0p"), m("La1p"), m("La2L") / 2) +
                     ym_frustum(m("La1p"), m("La2p"), m("La2L") / 2);
  EXPECT_NEAR(ym_segment(made.model, "upper_arm_l").mass, 1070 * arm, 1e-9);
  // Right lower leg: knee to calf to ankle (1.09 kg/L).
  const double shank = ym_frustum(m("Lk3p"), m("Lk4p"), m("Lk4L") - m("Lk3L")) +
                       ym_frustum(m("Lk4p"), m("Lk5p"), m("Lk5L") - m("Lk4L"));
  EXPECT_NEAR(ym_segment(made.model, "shank_r").mass, 1090 * shank, 1e-9);
  // Abdomen: one stadium solid, umbilicus to lowest rib (1.01 kg/L); its volume in closed form
  // ∫ (4 r t + π r²) over the linear interpolation.
  const auto stadium = [&](const std::string& level) {
    const double p = m(level + "p"), w = m(level + "w");
    return std::make_pair((M_PI * w - p) / (2 * M_PI - 4), (p - 2 * w) / (2 * M_PI - 4));
  };
  const auto [t0, r0] = stadium("Ls1");
  const auto [t1, r1] = stadium("Ls2");
  const double dt = t1 - t0, dr = r1 - r0;
  const double area = 4 * (r0 * t0 + (r0 * dt + t0 * dr) / 2 + dr * dt / 3) +
                      M_PI * (r0 * r0 + r0 * dr + dr * dr / 3);
  EXPECT_NEAR(ym_segment(made.model, "abdomen").mass, 1010 * area * (m("Ls2L") - m("Ls1L")), 1e-9);
  // A person: mass, standing height, the reader accepts the model.
  EXPECT_GT(made.model.total_mass(), 50.0);
  EXPECT_LT(made.model.total_mass(), 110.0);
  const StandingBody standing = standing_body(made.model);
  EXPECT_GT(standing.height(), 1.5);
  EXPECT_LT(standing.height(), 2.0);
  EXPECT_NO_THROW(parse_body_model(body_model_to_json(made.model), "male1"));
  // Density × volume for the whole body lies between the lightest and heaviest density.
  EXPECT_GT(made.model.total_mass(), 920 * made.volume);
  EXPECT_LT(made.model.total_mass(), 1160 * made.volume);
}

TEST(YeadonModel, AGivenMassScalesEveryDensity) {
  YeadonInput in = ym_male();
  const YeadonModel plain = yeadon_model(in);
  in.total_mass = 70.0;
  const YeadonModel scaled = yeadon_model(in);
  EXPECT_NEAR(scaled.model.total_mass(), 70.0, 1e-9);
  EXPECT_NEAR(scaled.density_scale, 70.0 / plain.model.total_mass(), 1e-12);
  for (int i = 0; i < plain.model.size(); ++i) {
    const Segment& a = plain.model.segments[static_cast<std::size_t>(i)];
    const Segment& b = scaled.model.segments[static_cast<std::size_t>(i)];
    EXPECT_NEAR(b.mass, scaled.density_scale * a.mass, 1e-12);
    EXPECT_LT((b.com - a.com).norm(), 1e-15);
    EXPECT_LT((b.inertia - scaled.density_scale * a.inertia).norm(), 1e-12);
  }
  in.total_mass = 0.0;
  in.densities = YeadonDensities::kChandler;  // lighter trunk densities
  EXPECT_LT(yeadon_model(in).model.total_mass(), plain.model.total_mass());
}

TEST(YeadonModel, TypingErrorsAndImpossibleGeometryAreNamedByKey) {
  YeadonInput in = ym_male();
  // male1's own left/right difference: wrist to base of thumb 3.0 cm left, 1.5 cm right.
  const YeadonModel made = yeadon_model(in);
  bool named = false;
  for (const std::string& w : made.warnings)
    named = named || (w.find("La5L") != std::string::npos && w.find("Lb5L") != std::string::npos);
  EXPECT_TRUE(named);

  // A width more than half its perimeter fits no convex shape. When it differs from the other
  // side's like a typing error, the width is the wrong one: a circle of the given perimeter
  // (as the `yeadon` package makes), with a warning naming both widths...
  YeadonInput wide = in;
  wide.measured["Lb4w"] = wide.measured["Lb4p"] * 0.9;
  const YeadonModel repaired = yeadon_model(wide);
  bool both = false;
  for (const std::string& w : repaired.warnings)
    both = both || (w.find("Lb4p") != std::string::npos && w.find("La4w") != std::string::npos);
  EXPECT_TRUE(both);
  // ... the right forearm's wrist end round, so not wider than the measured one.
  EXPECT_LT(repaired.model.segments[made.model.segment_index("forearm_r")].mass,
            made.model.segments[made.model.segment_index("forearm_r")].mass * 1.5);
  // When both sides agree on it, nothing says which number is wrong: refused.
  wide.measured["La4w"] = wide.measured["La4p"] * 0.9;
  try {
    yeadon_model(wide);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.json_path(), "La4p");
    EXPECT_NE(e.problem().find("La4w"), std::string::npos) << e.what();
  }
  YeadonInput backwards = in;
  backwards.measured["Lj3L"] = backwards.measured["Lj1L"] * 0.5;  // knee above the crotch
  try {
    yeadon_model(backwards);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.json_path(), "Lj3L");
  }
}

TEST(YeadonModel, ASegmentWithoutMassIsNamedWithTheFile) {
  // Perimeters and widths of 1e-300 m (the file reader refuses them below 1 mm; a YeadonInput
  // made in code is not read from a file): the left arm's solids have no volume. Once this was
  // "combine: the pieces have no mass", naming neither the file nor the segment.
  YeadonInput thin = ym_male();
  for (auto& [key, value] : thin.measured)
    if (key.rfind("La", 0) == 0 && (key.back() == 'p' || key.back() == 'w')) value = 1e-300;
  try {
    yeadon_model(thin);
    FAIL() << "a massless arm was made";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), thin.file);
    EXPECT_NE(e.problem().find("upper_arm_l segment"), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find("no mass"), std::string::npos) << e.what();
  }
  // One massless solid among others only adds nothing: the hand's fingers.
  YeadonInput fingers = ym_male();
  const double whole = yeadon_model(fingers).model.total_mass();
  fingers.measured["La7p"] = fingers.measured["La7w"] = 1e-300;
  const YeadonModel made = yeadon_model(fingers);
  EXPECT_LT(made.model.total_mass(), whole);
  EXPECT_GT(made.model.total_mass(), 0.99 * whole);
}

}  // namespace
}  // namespace saltus
