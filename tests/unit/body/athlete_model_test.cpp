// Tests for athletes' models from de Leva's table and for scaling (body/athlete_model.h): masses
// sum to the body mass, the lengths keep de Leva's ratios and stand the given height, the
// composed segments equal brute-force point sums, the whole-body CoM sits where people's does,
// the bundled model's lengths come out at its 1.70 m, and scaling obeys dimensional analysis.

#include "saltus/body/athlete_model.h"

#include <gtest/gtest.h>

#include <random>

#include "saltus/body/mass_properties.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

using P = DeLevaPart;

AthleteSize am_size(double h, double m, Sex sex) {
  AthleteSize s;
  s.height_m = h;
  s.mass_kg = m;
  s.sex = sex;
  return s;
}

const Segment& am_segment(const BodyModel& model, const std::string& name) {
  return model.segments.at(static_cast<std::size_t>(model.segment_index(name)));
}

/// Six point masses m/6 at ±a x, ±b y, ±c z around `com` with the inertia diag(I) about it.
void am_add_points(std::vector<std::pair<double, Eigen::Vector3d>>& points, double m,
                   const Eigen::Vector3d& com, const Eigen::Vector3d& I) {
  const double a = std::sqrt(1.5 * (I.y() + I.z() - I.x()) / m);
  const double b = std::sqrt(1.5 * (I.x() + I.z() - I.y()) / m);
  const double c = std::sqrt(1.5 * (I.x() + I.y() - I.z()) / m);
  for (const double s : {1.0, -1.0}) {
    points.push_back({m / 6, com + Eigen::Vector3d(s * a, 0, 0)});
    points.push_back({m / 6, com + Eigen::Vector3d(0, s * b, 0)});
    points.push_back({m / 6, com + Eigen::Vector3d(0, 0, s * c)});
  }
}

TEST(AthleteModel, MassesSumToTheBodyMassAndTheBodyStandsItsHeight) {
  std::mt19937 random(1996);
  std::uniform_real_distribution<double> height(1.2, 2.0);
  std::uniform_real_distribution<double> bmi(15.0, 30.0);
  for (int i = 0; i < 40; ++i) {
    const double h = height(random);
    const double m = bmi(random) * h * h;
    const Sex sex = i % 2 ? Sex::kMale : Sex::kFemale;
    const BodyModel model = de_leva_model(am_size(h, m, sex));
    ASSERT_EQ(model.size(), 13);
    EXPECT_NEAR(model.total_mass(), m, 1e-12 * m);
    const StandingBody standing = standing_body(model);
    EXPECT_NEAR(standing.height(), h, 1e-12);
    // People's whole-body CoM standing is at 55-57 % of stature from the soles; de Leva's table
    // with the arms hanging puts it at 57.4 % (male) and 55.4 % (female), see docs/method.md.
    const double fraction = standing.com_height() / h;
    EXPECT_GT(fraction, 0.55) << sex_name(sex);
    EXPECT_LT(fraction, 0.58) << sex_name(sex);
    EXPECT_NEAR(standing.body.com.x(), 0.0, 1e-12);
  }
}

TEST(AthleteModel, SegmentLengthsKeepDeLevasRatios) {
  for (const Sex sex : {Sex::kMale, Sex::kFemale}) {
    const BodyModel model = de_leva_model(am_size(1.45, 38.0, sex));
    const auto mm = [sex](P part) { return de_leva_row(sex, part).length_mm; };
    const double thigh = am_segment(model, "shank_l").joint_position.norm();
    const double shank = am_segment(model, "foot_l").joint_position.norm();
    const double upper_arm = am_segment(model, "forearm_r").joint_position.norm();
    const double middle_trunk = am_segment(model, "thorax").joint_position.norm();
    const double lower_trunk = std::abs(am_segment(model, "thigh_l").joint_position.y());
    EXPECT_NEAR(thigh / upper_arm, mm(P::kThigh) / mm(P::kUpperArm), 1e-12);
    EXPECT_NEAR(shank / thigh, mm(P::kShank) / mm(P::kThigh), 1e-12);
    EXPECT_NEAR(middle_trunk / lower_trunk, mm(P::kMiddleTrunk) / mm(P::kLowerTrunk), 1e-12);
    EXPECT_NEAR(thigh, mm(P::kThigh) / 1000 * 1.45 / de_leva_stature(sex), 1e-12);
    // Shoulders at de Leva's mid-shoulder height above the hips.
    const double shoulder =
        am_segment(model, "upper_arm_l").joint_position.y() + middle_trunk + lower_trunk;
    EXPECT_NEAR(shoulder, mm(P::kTrunkMids) / 1000 * 1.45 / de_leva_stature(sex), 1e-12);
  }
}

TEST(AthleteModel, AtTheBundledModelsSizeTheLengthsAreTheBundledModels) {
  // The bundled model's lengths were made by hand from de Leva's male table at 1.70 m.
  const BodyModel made = de_leva_model(am_size(1.70, 65.5, Sex::kMale));
  const BodyModel bundled = test::bundled_model();
  ASSERT_EQ(made.size(), bundled.size());
  for (int i = 0; i < made.size(); ++i) {
    const Segment& a = made.segments[static_cast<std::size_t>(i)];
    const Segment& b = bundled.segments[static_cast<std::size_t>(i)];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.joint, b.joint);
    EXPECT_EQ(a.parent, b.parent);
    EXPECT_LT((a.joint_position - b.joint_position).norm(), 6e-4) << a.name;
    EXPECT_NEAR(a.shape.length, b.shape.length, 6e-4) << a.name;
    // CoMs on the same axis, at the same de Leva fractions (the bundled thorax's and forearm's
    // are composed the same way, but to the mass of its own table).
    EXPECT_LT((a.com - b.com).norm(), 0.012) << a.name;
  }
}

TEST(AthleteModel, ComposedSegmentsEqualBruteForcePointSums) {
  for (const Sex sex : {Sex::kMale, Sex::kFemale}) {
    const double h = 1.85, m = 85.0;
    const BodyModel model = de_leva_model(am_size(h, m, sex));
    const double k = h / de_leva_stature(sex);
    double sum = 0.0;
    for (const DeLevaRow& r : de_leva_rows(sex))
      if (r.part != P::kTrunk && r.part != P::kTrunkMids)
        sum += (r.part >= P::kUpperArm ? 2 : 1) * r.mass_percent / 100;
    const auto piece = [&](P part, double com_y,
                           std::vector<std::pair<double, Eigen::Vector3d>>& points) {
      const DeLevaRow& r = de_leva_row(sex, part);
      const double length = r.length_mm / 1000 * k;
      const double mass = r.mass_percent / 100 / sum * m;
      const Eigen::Vector3d radii =
          Eigen::Vector3d(r.r_transverse, r.r_longitudinal, r.r_sagittal) / 100 * length;
      am_add_points(points, mass, Eigen::Vector3d(0, com_y, 0), mass * radii.cwiseProduct(radii));
    };
    const auto length = [&](P part) { return de_leva_row(sex, part).length_mm / 1000 * k; };
    const auto com = [&](P part) {
      return de_leva_row(sex, part).com_percent / 100 * length(part);
    };

    std::vector<std::pair<double, Eigen::Vector3d>> thorax, forearm;
    const double top = am_segment(model, "thorax").shape.length;  // the vertex
    piece(P::kUpperTrunk, length(P::kUpperTrunk) - com(P::kUpperTrunk), thorax);
    piece(P::kHead, top - com(P::kHead), thorax);
    piece(P::kForearm, -com(P::kForearm), forearm);
    piece(P::kHand, -(length(P::kForearm) + com(P::kHand)), forearm);
    for (const auto& [name, points] : {std::make_pair(std::string("thorax"), thorax),
                                       std::make_pair(std::string("forearm_l"), forearm)}) {
      double mass = 0;
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (const auto& p : points) {
        mass += p.first;
        c += p.first * p.second;
      }
      c /= mass;
      Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
      for (const auto& p : points) {
        const Eigen::Vector3d d = p.second - c;
        I += p.first * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
      }
      const Segment& s = am_segment(model, name);
      EXPECT_NEAR(s.mass, mass, 1e-12) << name;
      EXPECT_LT((s.com - c).norm(), 1e-12) << name;
      EXPECT_LT((s.inertia - I).cwiseAbs().maxCoeff(), 1e-12) << name;
    }
  }
}

TEST(AthleteModel, ScalingFollowsDimensionalAnalysis) {
  const BodyModel small = de_leva_model(am_size(1.45, 38.0, Sex::kFemale));
  const double k = 1.85 / 1.45;
  const double mu = 85.0 / 38.0;
  const BodyModel scaled = scale_body_model(small, k, mu, "scaled");
  // de Leva's model is proportional: scaling the 1.45 m one gives the 1.85 m one, physics alike.
  AthleteSize tall = am_size(1.85, 85.0, Sex::kFemale);
  const BodyModel direct = de_leva_model(tall);
  for (int i = 0; i < small.size(); ++i) {
    const Segment& a = scaled.segments[static_cast<std::size_t>(i)];
    const Segment& b = direct.segments[static_cast<std::size_t>(i)];
    EXPECT_NEAR(a.mass, b.mass, 1e-12 * b.mass);
    EXPECT_LT((a.com - b.com).norm(), 1e-13);
    EXPECT_LT((a.joint_position - b.joint_position).norm(), 1e-13);
    EXPECT_LT((a.inertia - b.inertia).norm(), 1e-13);
  }
  // Whole body: mass ∝ m, height ∝ L, inertia ∝ m·L².
  const StandingBody s0 = standing_body(small);
  const StandingBody s1 = standing_body(scaled);
  EXPECT_NEAR(s1.body.mass, mu * s0.body.mass, 1e-12);
  EXPECT_NEAR(s1.height(), k * s0.height(), 1e-12);
  EXPECT_LT((s1.body.inertia - mu * k * k * s0.body.inertia).norm(), 1e-12);
  EXPECT_EQ(scaled.name, "scaled");
  EXPECT_THROW(scale_body_model(small, 0.0, 1.0, "x"), std::invalid_argument);
  EXPECT_THROW(de_leva_model(am_size(-1.0, 50.0, Sex::kMale)), std::invalid_argument);
}

}  // namespace
}  // namespace saltus
