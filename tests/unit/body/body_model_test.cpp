// Tests for the BodyModel queries and mass scaling (body/body_model.h); reading and writing model
// files is tested in unit/formats/model_file_test.cpp.

#include "saltus/body/body_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "support/test_motions.h"

namespace saltus {
namespace {

/// A three-segment chain with masses 1, 2 and 4 kg: every sum of a subset is distinct.
BodyModel chain() {
  BodyModel model;
  model.name = "chain";
  const char* names[] = {"base", "middle", "tip"};
  const char* joints[] = {"root", "waist", "wrist"};
  for (int i = 0; i < 3; ++i) {
    Segment s;
    s.name = names[i];
    s.joint = joints[i];
    s.parent = i - 1;
    s.mass = std::ldexp(1.0, i);
    s.inertia = Eigen::Vector3d(0.1, 0.2, 0.3).asDiagonal() * s.mass;
    model.segments.push_back(s);
  }
  return model;
}

TEST(BodyModelQueries, TotalMassAndIndicesByName) {
  const BodyModel model = chain();
  EXPECT_EQ(model.size(), 3);
  EXPECT_EQ(model.total_mass(), 7.0);
  // Segments and joints have their own names: each lookup finds only its own kind.
  EXPECT_EQ(model.segment_index("tip"), 2);
  EXPECT_EQ(model.joint_index("wrist"), 2);
  EXPECT_EQ(model.joint_index("waist"), 1);
  EXPECT_EQ(model.segment_index("wrist"), -1);
  EXPECT_EQ(model.joint_index("tip"), -1);
  EXPECT_EQ(model.segment_index(""), -1);
  EXPECT_EQ(BodyModel().total_mass(), 0.0);
}

TEST(BodyModelScale, ScalingEverySegmentScalesTheTotalAndKeepsTheCentresOfMass) {
  const BodyModel model = chain();
  const BodyModel scaled = scale_segment_mass(model, "", 3.0);
  EXPECT_DOUBLE_EQ(scaled.total_mass(), 21.0);
  const BodyModel middle = scale_segment_mass(model, "middle", 0.5);
  EXPECT_DOUBLE_EQ(middle.total_mass(), 6.0);  // 1 + 2·0.5 + 4
  EXPECT_EQ(middle.segments[1].inertia, model.segments[1].inertia * 0.5);
  EXPECT_EQ(middle.segments[2].inertia, model.segments[2].inertia);
}

TEST(BodyModelScale, ScalesOneSegmentOrAll) {
  const BodyModel model = test::bundled_model();
  const int thigh = model.segment_index("thigh_l");
  const BodyModel one = scale_segment_mass(model, "thigh_l", 1.5);
  EXPECT_DOUBLE_EQ(one.segments[thigh].mass, 15.0);
  EXPECT_TRUE(one.segments[thigh].inertia.isApprox(1.5 * model.segments[thigh].inertia));
  EXPECT_EQ(one.segments[thigh].com, model.segments[thigh].com);
  EXPECT_NEAR(one.total_mass(), 70.5, 1e-12);
  for (int i = 0; i < model.size(); ++i) {
    if (i == thigh) continue;
    EXPECT_EQ(one.segments[i].mass, model.segments[i].mass);
    EXPECT_EQ(one.segments[i].inertia, model.segments[i].inertia);
  }

  const BodyModel all = scale_segment_mass(model, "", 0.9);
  EXPECT_NEAR(all.total_mass(), 0.9 * 65.5, 1e-12);
  for (int i = 0; i < model.size(); ++i)
    EXPECT_TRUE(all.segments[i].inertia.isApprox(0.9 * model.segments[i].inertia));
  // The input is untouched.
  EXPECT_DOUBLE_EQ(model.total_mass(), 65.5);
}

TEST(BodyModelScale, RejectsUnknownSegmentsAndNonPositiveFactors) {
  const BodyModel model = test::bundled_model();
  EXPECT_THROW(scale_segment_mass(model, "tail", 1.1), std::invalid_argument);
  EXPECT_THROW(scale_segment_mass(model, "thigh_l", 0.0), std::invalid_argument);
  EXPECT_THROW(scale_segment_mass(model, "", -1.0), std::invalid_argument);
  EXPECT_THROW(scale_segment_mass(model, "", std::nan("")), std::invalid_argument);
  try {
    scale_segment_mass(model, "tail", 1.1);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("tail"), std::string::npos);
  }
}

}  // namespace
}  // namespace saltus
