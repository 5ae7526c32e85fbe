// The drawing colours (body/drawing_colours.h): sides by name, skin on the head, neck and hands,
// the nose's own, written as #rrggbb; the hex values are worked out by hand from the app's RGB
// fractions (gui/scene/body_layer.cpp's palette).

#include "saltus/body/drawing_colours.h"

#include <gtest/gtest.h>

#include "support/test_motions.h"

namespace saltus {
namespace {

Segment named_segment(const std::string& name) {
  Segment s;
  s.name = name;
  return s;
}

ShapePart named_part(const std::string& name) {
  ShapePart p;
  p.name = name;
  return p;
}

TEST(DrawingColours, SidesFollowTheSegmentName) {
  // 0.25, 0.47, 0.88 -> 64, 120, 224; 0.93, 0.45, 0.18 -> 237, 115, 46; 0.86, 0.82, 0.74 ->
  // 219, 209, 189.
  EXPECT_EQ(hex_colour(segment_colour(named_segment("thigh_l"))), "#4078e0");
  EXPECT_EQ(hex_colour(segment_colour(named_segment("forearm_r"))), "#ed732e");
  EXPECT_EQ(hex_colour(segment_colour(named_segment("pelvis"))), "#dbd1bd");
  EXPECT_EQ(hex_colour(segment_colour(named_segment("_l"))), "#dbd1bd") << "no name before it";
}

TEST(DrawingColours, SkinAndNoseWhereTheyShow) {
  const Segment forearm = named_segment("forearm_l");
  EXPECT_EQ(hex_colour(part_colour(forearm, named_part("hand"))), "#f2c7a3");  // 242 199 163
  EXPECT_EQ(hex_colour(part_colour(forearm, named_part("forearm"))), "#4078e0");
  const Segment thorax = named_segment("thorax");
  EXPECT_EQ(hex_colour(part_colour(thorax, named_part("head"))), "#f2c7a3");
  EXPECT_EQ(hex_colour(part_colour(thorax, named_part("neck"))), "#f2c7a3");
  EXPECT_EQ(hex_colour(part_colour(thorax, named_part("nose"))), "#d18570");  // 209 133 112
  EXPECT_EQ(hex_colour(part_colour(thorax, named_part("chest"))), "#dbd1bd");
}

TEST(DrawingColours, HexClampsAndRounds) {
  EXPECT_EQ(hex_colour({0.0, 1.0, 0.5}), "#00ff80");
  EXPECT_EQ(hex_colour({-1.0, 2.0, 0.0}), "#00ff00");
}

TEST(DrawingColours, EveryPartOfTheBundledModelHasAColour) {
  const BodyModel model = test::bundled_model();
  int skin = 0;
  for (const Segment& s : model.segments)
    for (const ShapePart& p : s.shape.parts)
      if (hex_colour(part_colour(s, p)) == "#f2c7a3") ++skin;
  EXPECT_EQ(skin, 4) << "neck, head and two hands";
}

}  // namespace
}  // namespace saltus
