// The What if panel's core (core/what_if_report.h): the sliders' steps stay inside the library's
// ranges and map to its changes, the words say what the library found, and the figure beside the
// athlete is posed between the flight's samples.

#include "core/what_if_report.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/workspace.h"
#include "saltus/base/constants.h"
#include "saltus/base/text_format.h"

namespace saltus::gui {
namespace {

std::string what_if_motion_path(const std::string& name) {
  return std::string(SALTUS_EXAMPLES_DIR) + "/motions/" + name;
}

TEST(WhatIfReport, SliderStepsStayInsideTheLibrarysRanges) {
  const SliderSteps steps = shift_slider_steps(-0.1366, 0.1373);
  EXPECT_EQ(steps.min, -13);
  EXPECT_EQ(steps.max, 13);
  // A range ending on a step keeps it despite rounding (0.05 / 0.01 = 5.000000000000001).
  EXPECT_EQ(shift_slider_steps(-0.05, 0.05).max, 5);
  EXPECT_EQ(shift_slider_steps(-0.05, 0.05).min, -5);
  // No range: the slider stays at 0.
  EXPECT_EQ(shift_slider_steps(0.0, 0.0).min, 0);
  EXPECT_EQ(shift_slider_steps(0.0, 0.0).max, 0);
  const SliderSteps tight = tightness_slider_steps();
  EXPECT_EQ(tight.min, 80);
  EXPECT_EQ(tight.max, 120);
  // Every slider position is a change the library flies.
  for (int tuck : {steps.min, 0, steps.max})
    for (int percent : {tight.min, 100, tight.max}) {
      const WhatIfChange c = change_at(tuck, 0, percent);
      EXPECT_GE(c.tuck_later_s, -0.1366);
      EXPECT_LE(c.tuck_later_s, 0.1373);
      EXPECT_GE(c.tuck_scale, kMinTuckScale);
      EXPECT_LE(c.tuck_scale, kMaxTuckScale);
    }
  const WhatIfChange c = change_at(-3, 5, 110);
  EXPECT_DOUBLE_EQ(c.tuck_later_s, -0.03);
  EXPECT_DOUBLE_EQ(c.open_later_s, 0.05);
  EXPECT_DOUBLE_EQ(c.tuck_scale, 1.1);
  EXPECT_TRUE(change_at(0, 0, 100).unchanged());
}

TEST(WhatIfReport, WordsForTheSlidersAndTheTuck) {
  EXPECT_EQ(shift_text(0.05), "0.05 s later");
  EXPECT_EQ(shift_text(-0.03), "0.03 s earlier");
  EXPECT_EQ(shift_text(0.0), "as keyframed");
  EXPECT_EQ(tightness_text(110), "110 % (tighter)");
  EXPECT_EQ(tightness_text(90), "90 % (looser)");
  EXPECT_EQ(tightness_text(100), "100 % (as keyframed)");
  TuckPhases tuck;
  tuck.found = true;
  tuck.tuck_start_s = 0.02;
  tuck.tucked_s = 0.28;
  tuck.opens = true;
  tuck.open_start_s = 0.84;
  tuck.opened_s = 1.02;
  tuck.peak_bend_deg = 145.2;
  EXPECT_EQ(tuck_text(tuck),
            "Tucks 0.02\u20130.28 s, opens 0.84\u20131.02 s; hips and knees bend up to 145°.");
  tuck.opens = false;
  EXPECT_EQ(tuck_text(tuck),
            "Tucks 0.02\u20130.28 s, lands in the tuck; hips and knees bend up "
            "to 145°.");
  TuckPhases none;
  none.reason = "There is no tuck to change.";
  EXPECT_EQ(tuck_text(none), none.reason);
}

TEST(WhatIfReport, TheReferenceLineCarriesTheLibrarysCounts) {
  Workspace ws;
  ws.open(what_if_motion_path("M7-double-front-one-and-a-half-twists.motion.json"));
  const WhatIf w(ws.document().file().motion, ws.document().file().model);
  const std::string text = reference_text(w);
  EXPECT_NE(text.find(format_number("after %.2f somersaults", std::abs(w.target().somersaults))),
            std::string::npos)
      << text;
  EXPECT_NE(text.find(format_number("and %.2f twists", std::abs(w.target().twists))),
            std::string::npos)
      << text;
  EXPECT_NE(
      text.find(format_number("flown as it is, %.2f", std::abs(w.unchanged_landing().somersaults))),
      std::string::npos)
      << text;
}

TEST(WhatIfReport, TheFigureIsPosedBetweenTheFlightsSamples) {
  // Two samples 0.1 s apart: a segment turning 40° about x and moving 1 m up.
  SampleRecord a, b;
  a.time = 1.0;
  b.time = 1.1;
  a.segment_position = {Eigen::Vector3d(0, 1, 0)};
  b.segment_position = {Eigen::Vector3d(0, 2, 0)};
  a.segment_rotation = {Eigen::Quaterniond::Identity()};
  b.segment_rotation = {
      Eigen::Quaterniond(Eigen::AngleAxisd(40 * kPi / 180, Eigen::Vector3d::UnitX()))};
  a.com = Eigen::Vector3d(0, 1, 0);
  b.com = Eigen::Vector3d(0, 2, 0);
  a.joint_wrench = b.joint_wrench = {Vector6d::Zero()};
  const std::vector<SampleRecord> flight = {a, b};
  const SampleRecord mid = flight_sample_at(flight, 1.025);
  EXPECT_DOUBLE_EQ(mid.time, 1.025);
  EXPECT_NEAR(mid.segment_position[0].y(), 1.25, 1e-12);
  EXPECT_NEAR(mid.com.y(), 1.25, 1e-12);
  // A quarter of the way: 10° about x.
  const Eigen::AngleAxisd turned(mid.segment_rotation[0]);
  EXPECT_NEAR(turned.angle() * 180 / kPi, 10.0, 1e-9);
  EXPECT_NEAR(std::abs(turned.axis().x()), 1.0, 1e-12);
  // Outside the flight: its ends.
  EXPECT_EQ(flight_sample_at(flight, 0.5).time, 1.0);
  EXPECT_EQ(flight_sample_at(flight, 3.0).time, 1.1);
  EXPECT_THROW(flight_sample_at({}, 1.0), std::invalid_argument);
}

TEST(WhatIfReport, MedianOfLatencies) {
  EXPECT_EQ(median_ms({}), 0.0);
  EXPECT_EQ(median_ms({30, 10, 20}), 20.0);
  EXPECT_EQ(median_ms({40, 10, 20, 30}), 25.0);
}

}  // namespace
}  // namespace saltus::gui
