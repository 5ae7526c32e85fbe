// Glyph scaling: round full scales, proportional lengths, colours and legend text.

#include <gtest/gtest.h>

#include "core/glyph_scale.h"

#include "saltus/base/text_format.h"

namespace saltus::gui {
namespace {

TEST(NiceCeiling, RoundsUpToOneTwoFive) {
  EXPECT_DOUBLE_EQ(nice_ceiling(37.0), 50.0);
  EXPECT_DOUBLE_EQ(nice_ceiling(50.0), 50.0);
  EXPECT_DOUBLE_EQ(nice_ceiling(101.0), 200.0);
  EXPECT_DOUBLE_EQ(nice_ceiling(0.013), 0.02);
  EXPECT_DOUBLE_EQ(nice_ceiling(1.0), 1.0);
  EXPECT_DOUBLE_EQ(nice_ceiling(5.5), 10.0);
  EXPECT_DOUBLE_EQ(nice_ceiling(0.0), 1.0);
  EXPECT_DOUBLE_EQ(nice_ceiling(-3.0), 1.0);
}

TEST(GlyphScale, LengthIsProportionalAndLegendReadsOff) {
  const GlyphScale s(37.0, 0.8);  // full scale 50 N drawn 0.8 m long
  EXPECT_DOUBLE_EQ(s.full_scale(), 50.0);
  EXPECT_DOUBLE_EQ(s.length(50.0), 0.8);
  EXPECT_DOUBLE_EQ(s.length(25.0), 0.4);
  EXPECT_DOUBLE_EQ(s.length(0.0), 0.0);
  EXPECT_DOUBLE_EQ(s.length(-1.0), 0.0);
  EXPECT_DOUBLE_EQ(s.length(75.0), 1.2);                             // beyond full scale
  EXPECT_DOUBLE_EQ(s.length(1000.0), GlyphScale::kLengthCap * 0.8);  // capped
  EXPECT_DOUBLE_EQ(s.fraction(100.0), 1.0);
  EXPECT_DOUBLE_EQ(s.fraction(10.0), 0.2);
  EXPECT_EQ(s.legend("N"), "0.8 m = 50 N");
  EXPECT_THROW(GlyphScale(1.0, 0.0), std::invalid_argument);
}

TEST(GlyphScale, ZeroLargestMagnitudeStillGivesAUsableScale) {
  const GlyphScale s(0.0, 1.0);
  EXPECT_DOUBLE_EQ(s.full_scale(), 1.0);
  EXPECT_DOUBLE_EQ(s.length(0.0), 0.0);
}

TEST(MagnitudeColour, GoesFromGreenThroughYellowToRed) {
  const Rgb low = magnitude_colour(0.0);
  const Rgb mid = magnitude_colour(0.5);
  const Rgb high = magnitude_colour(1.0);
  EXPECT_GT(low.g, low.r);
  EXPECT_GT(mid.r, 0.9);
  EXPECT_GT(mid.g, 0.7);
  EXPECT_GT(high.r, 0.8);
  EXPECT_LT(high.g, 0.2);
  const Rgb beyond = magnitude_colour(7.0);
  EXPECT_DOUBLE_EQ(beyond.r, high.r);
  EXPECT_EQ(legend_number(0.25), "0.25");
  EXPECT_EQ(legend_number(50), "50");
  // Round full scales of large residuals read as numbers, not "1e+03".
  EXPECT_EQ(legend_number(1000), "1000");
  EXPECT_EQ(legend_number(20000), "20000");
  EXPECT_EQ(GlyphScale(800.0, 1.0).legend("N"), "1 m = 1000 N");
}

}  // namespace
}  // namespace saltus::gui
