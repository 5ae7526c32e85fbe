// What a segment is drawn as (body/drawn_parts.h): its parts in their colours, or one capsule
// from its origin along y, never thinner than kMinDrawnRadius.

#include "saltus/body/drawn_parts.h"

#include <gtest/gtest.h>

namespace saltus {
namespace {

TEST(DrawnParts, ASegmentWithoutPartsIsOneCapsuleAlongItsAxis) {
  Segment thigh;
  thigh.name = "thigh_l";
  thigh.shape.length = -0.4;
  thigh.shape.radius = 0.0;
  const std::vector<DrawnPart> parts = drawn_parts(thigh);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].shape.type, "capsule");
  EXPECT_TRUE(parts[0].shape.center.isApprox(Eigen::Vector3d(0, -0.2, 0)));
  EXPECT_DOUBLE_EQ(parts[0].shape.length, -0.4);
  EXPECT_DOUBLE_EQ(parts[0].shape.radius, kMinDrawnRadius);
  EXPECT_EQ(hex_colour(parts[0].colour), hex_colour(segment_colour(thigh)));
}

TEST(DrawnParts, PartsReplaceTheSingleShapeAndKeepTheirColours) {
  Segment thorax;
  thorax.name = "thorax";
  thorax.shape.length = 0.6;
  thorax.shape.radius = 0.12;
  ShapePart chest;
  chest.name = "chest";
  chest.radii = Eigen::Vector3d(0.15, 0.2, 0.1);
  ShapePart head;
  head.name = "head";
  head.center = Eigen::Vector3d(0, 0.5, 0);
  head.radii = Eigen::Vector3d(0.08, 0.11, 0.09);
  thorax.shape.parts = {chest, head};
  const std::vector<DrawnPart> parts = drawn_parts(thorax);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].shape.name, "chest");
  EXPECT_EQ(parts[1].shape.name, "head");
  EXPECT_TRUE(parts[1].shape.center.isApprox(head.center));
  EXPECT_EQ(hex_colour(parts[0].colour), hex_colour(segment_colour(thorax)));
  EXPECT_EQ(hex_colour(parts[1].colour), hex_colour(part_colour(thorax, head)));
  EXPECT_NE(hex_colour(parts[0].colour), hex_colour(parts[1].colour)) << "the head is skin";
}

}  // namespace
}  // namespace saltus
