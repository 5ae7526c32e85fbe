// Sizes of the root wrench and shares of body weight, checked against an independent path: a body
// held still in any pose needs exactly its weight at the root (statics), so |F| must equal
// body_weight() there and be 100 % of it.

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/evaluation/residual_measures.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(ResidualMeasures, AStillBodyNeedsItsWeightAtTheRoot) {
  const BodyModel model = test::bundled_model();
  BodyState<double> still(model.size());
  still.root_position = Eigen::Vector3d(0.1, 1.2, -0.4);
  still.joints[0].q =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, 0.3, -2).normalized()));
  still.joints[model.joint_index("knee_l")].q =
      Eigen::Quaterniond(Eigen::AngleAxisd(1.2, Eigen::Vector3d::UnitX()));
  const std::vector<SampleRecord> samples = evaluate_states(model, {0.0, 0.5}, {still, still});
  const std::vector<double> force = root_force_magnitudes(samples);
  ASSERT_EQ(force.size(), 2u);
  // m·g from the model's masses and the dynamics' gravity, computed here by hand.
  double mass = 0.0;
  for (const Segment& s : model.segments)
    mass += s.mass;
  EXPECT_NEAR(body_weight(model), mass * 9.81, 1e-9);
  EXPECT_NEAR(force[0], body_weight(model), 1e-9);
  EXPECT_NEAR(percent_of_body_weight(force[1], model), 100.0, 1e-9);
  // The moment about the root origin is the lever of the CoM: |(c − root) × W|, not zero.
  const Eigen::Vector3d lever = samples[0].com - still.root_position;
  EXPECT_NEAR(root_moment_magnitudes(samples)[0],
              lever.cross(Eigen::Vector3d(0, body_weight(model), 0)).norm(), 1e-9);
}

TEST(ResidualMeasures, MagnitudesAreTheNormsOfTheForceAndMomentHalves) {
  Vector6d w;
  w << 3, -4, 12, 0, 0, -2;
  EXPECT_DOUBLE_EQ(force_magnitude(w), 13.0);
  EXPECT_DOUBLE_EQ(moment_magnitude(w), 2.0);
  BodyModel massless;
  EXPECT_EQ(percent_of_body_weight(10.0, massless), 0.0);
}

}  // namespace
}  // namespace saltus
