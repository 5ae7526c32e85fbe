// The lecture figure's words and colours: the title names the motion and the stage, the caption
// says how many poses, how far apart in time, from which side and whether to scale, and the
// colour bar's range holds every pose's spin rate.

#include <gtest/gtest.h>

#include <cmath>

#include "core/lecture_figure.h"
#include "gui_core/test_motion.h"

namespace saltus::gui {
namespace {

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(LectureFigure, NamesTheMotionAndStageAndRangesEveryPosesSpin) {
  Document document;
  document.load(test::gui_test_motion_path());
  const LectureFigure f = lecture_figure(document, Stage::kAfter, 8);  // no run: before
  EXPECT_TRUE(has(f.title, document.file().motion.name)) << f.title;
  EXPECT_TRUE(has(f.title, "before optimisation")) << f.title;
  ASSERT_EQ(f.strobe.poses.size(), 8u);
  EXPECT_TRUE(has(f.caption, "8 poses")) << f.caption;
  EXPECT_TRUE(has(f.caption, "rev/s")) << f.caption;
  EXPECT_TRUE(has(f.colour_bar_title, "spin rate")) << f.colour_bar_title;
  EXPECT_TRUE(has(f.colour_bar_title, "rev/s")) << f.colour_bar_title;
  for (const StroboscopePose& p : f.strobe.poses) {
    EXPECT_GE(p.spin_rev_per_s, f.spin_low);
    EXPECT_LE(p.spin_rev_per_s, f.spin_high);
  }
  EXPECT_GE(f.spin_high - f.spin_low, 0.2 - 1e-12);
  // The range is whole steps, at most 6 of them.
  const double parts = (f.spin_high - f.spin_low) / f.spin_step;
  EXPECT_NEAR(parts, std::round(parts), 1e-9);
  EXPECT_LE(parts, 6.0 + 1e-9);
}

TEST(LectureFigure, SaysWhetherThePosesAreSpreadOrToScale) {
  Stroboscope strobe;
  strobe.poses.resize(3);
  strobe.poses[1].time = 0.5;
  strobe.poses[2].time = 1.0;
  strobe.poses[1].spin_rev_per_s = 1.23;
  strobe.travel_m = 0.12;
  strobe.spread_m = 0.9;
  const LectureFigure spread = lecture_figure_of(strobe, BodyModel{}, "M", "stage");
  EXPECT_EQ(spread.title, "M — stage");
  EXPECT_TRUE(has(spread.caption, "Not to scale horizontally")) << spread.caption;
  EXPECT_TRUE(has(spread.caption, "0.90 m")) << spread.caption;
  EXPECT_TRUE(has(spread.caption, "travels 0.12 m")) << spread.caption;
  EXPECT_TRUE(has(spread.caption, "0.500 s apart")) << spread.caption;
  EXPECT_TRUE(has(spread.caption, "athlete's right")) << spread.caption;
  EXPECT_DOUBLE_EQ(spread.spin_low, 0.0);
  // 0 to 1.23 rev/s: labels every 0.5 (at 0.1 or 0.2 there would be more than 6 parts).
  EXPECT_DOUBLE_EQ(spread.spin_step, 0.5);
  EXPECT_DOUBLE_EQ(spread.spin_high, 1.5);
  strobe.spread_m = 0.0;
  strobe.travel_m = 7.5;
  strobe.along_velocity = true;
  const LectureFigure to_scale = lecture_figure_of(strobe, BodyModel{}, "M", "stage");
  EXPECT_TRUE(has(to_scale.caption, "To scale: the flight travels 7.50 m")) << to_scale.caption;
  EXPECT_TRUE(has(to_scale.caption, "somersault axis")) << to_scale.caption;
}

TEST(LectureFigure, SpinColoursRunFromBlueToRedAndClamp) {
  const Rgb slow = spin_colour(0.0), fast = spin_colour(1.0);
  EXPECT_GT(slow.b, slow.r);
  EXPECT_GT(fast.r, fast.b);
  EXPECT_DOUBLE_EQ(spin_colour(-1.0).b, slow.b);
  EXPECT_DOUBLE_EQ(spin_colour(2.0).r, fast.r);
  // Neighbouring tenths differ visibly: the poses' colours tell their rates apart.
  for (int i = 0; i < 10; ++i) {
    const Rgb a = spin_colour(i / 10.0), b = spin_colour((i + 1) / 10.0);
    EXPECT_GT(std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b), 0.05) << i;
  }
}

}  // namespace
}  // namespace saltus::gui
