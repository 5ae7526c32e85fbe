// Tests for rigid-mass composition and the standing whole body (body/mass_properties.h), against
// brute-force sums over point clouds and closed forms.

#include "saltus/body/mass_properties.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "support/test_motions.h"

namespace saltus {
namespace {

struct MassPoint {
  double mass;
  Eigen::Vector3d position;
};

/// Mass, CoM and inertia about the CoM of point masses, summed directly.
RigidMass mp_point_sums(const std::vector<MassPoint>& points) {
  RigidMass out;
  for (const MassPoint& p : points) {
    out.mass += p.mass;
    out.com += p.mass * p.position;
  }
  out.com /= out.mass;
  for (const MassPoint& p : points) {
    const Eigen::Vector3d d = p.position - out.com;
    out.inertia += p.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  return out;
}

TEST(MassProperties, ComposedPiecesEqualTheBruteForceSumOverTheirPoints) {
  std::mt19937 random(25);
  std::uniform_real_distribution<double> mass(0.1, 3.0);
  std::uniform_real_distribution<double> coordinate(-0.5, 0.5);
  std::vector<MassPoint> all;
  RigidMass composed;
  for (int piece = 0; piece < 4; ++piece) {
    // Each piece a cloud of its own, off centre.
    const Eigen::Vector3d offset(piece * 0.3, -piece * 0.2, 0.1 * piece * piece);
    std::vector<MassPoint> points;
    for (int i = 0; i < 50; ++i)
      points.push_back(
          {mass(random),
           offset + Eigen::Vector3d(coordinate(random), coordinate(random), coordinate(random))});
    all.insert(all.end(), points.begin(), points.end());
    const RigidMass own = mp_point_sums(points);
    composed = piece == 0 ? own : combine(composed, own);
  }
  const RigidMass direct = mp_point_sums(all);
  EXPECT_NEAR(composed.mass, direct.mass, 1e-12);
  EXPECT_LT((composed.com - direct.com).norm(), 1e-13);
  EXPECT_LT((composed.inertia - direct.inertia).cwiseAbs().maxCoeff(),
            1e-12 * direct.inertia.norm());
}

TEST(MassProperties, TwoSlenderRodsEndToEndAreOneRodOfTwiceTheLength) {
  // A uniform rod of mass m and length L: I = m L² / 12 about its middle across the rod.
  const double m = 2.0;
  const double L = 0.5;
  const double across = std::sqrt(L * L / 12.0);
  const RigidMass lower =
      rigid_mass_from_radii(m, Eigen::Vector3d(0, -L / 2, 0), Eigen::Vector3d(across, 0, across));
  const RigidMass upper =
      rigid_mass_from_radii(m, Eigen::Vector3d(0, L / 2, 0), Eigen::Vector3d(across, 0, across));
  const RigidMass rod = combine(lower, upper);
  EXPECT_DOUBLE_EQ(rod.mass, 2 * m);
  EXPECT_NEAR(rod.com.norm(), 0.0, 1e-15);
  const double expected = 2 * m * (2 * L) * (2 * L) / 12.0;
  EXPECT_NEAR(rod.inertia(0, 0), expected, 1e-14);
  EXPECT_NEAR(rod.inertia(2, 2), expected, 1e-14);
  EXPECT_NEAR(rod.inertia(1, 1), 0.0, 1e-15);
}

TEST(MassProperties, TheBundledModelStandsItsDocumentedHeightAndMass) {
  // Its source text states that the upright identity pose stands 1.700 m tall, 65.5 kg.
  const BodyModel model = test::bundled_model();
  const StandingBody standing = standing_body(model);
  EXPECT_NEAR(standing.height(), 1.700, 5e-4);
  EXPECT_NEAR(standing.body.mass, 65.5, 1e-12);
  // Left and right mirror each other: the CoM is on the mid-line, the products about x vanish.
  EXPECT_NEAR(standing.body.com.x(), 0.0, 1e-12);
  EXPECT_NEAR(standing.body.inertia(0, 1), 0.0, 1e-12);
  // Standing, the twist axis has by far the smallest moment.
  EXPECT_LT(standing.principal_moments(0), 0.2 * standing.principal_moments(1));
  EXPECT_NEAR(standing.principal_moments(0), standing.body.inertia(1, 1), 0.02);
}

TEST(MassProperties, TheSummaryNamesSegmentsForPeopleAndItsPercentagesSumTo100) {
  const ModelSummary summary = summarize_model(test::bundled_model());
  ASSERT_EQ(summary.segments.size(), 13u);
  double percent = 0.0;
  for (const SegmentSummary& s : summary.segments)
    percent += s.mass_percent;
  EXPECT_NEAR(percent, 100.0, 1e-9);
  EXPECT_EQ(summary.segments[7].name, "thigh_l");
  EXPECT_EQ(summary.segments[7].label, "left thigh");
  EXPECT_NEAR(summary.segments[7].length, 0.4123, 1e-12);
  // Principal moments of the thigh [0.2, 0.041, 0.19], ascending.
  EXPECT_NEAR(summary.segments[7].principal_moments(0), 0.041, 1e-12);
  EXPECT_NEAR(summary.segments[7].principal_moments(2), 0.2, 1e-12);
}

}  // namespace
}  // namespace saltus
