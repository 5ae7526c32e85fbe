// Timeline maths: time <-> frame, stepping, speed, loop, playback, keyframe ticks and the flags
// of the closest pass to the apparatus and a dive's entry.

#include <gtest/gtest.h>

#include <stdexcept>

#include "core/timeline.h"

namespace saltus::gui {
namespace {

Timeline make(double duration = 2.0, int frames = 201) {
  Timeline t;
  t.set_range(duration, frames);
  return t;
}

TEST(Timeline, RejectsBadRanges) {
  Timeline t;
  EXPECT_THROW(t.set_range(0.0, 10), std::invalid_argument);
  EXPECT_THROW(t.set_range(-1.0, 10), std::invalid_argument);
  EXPECT_THROW(t.set_range(1.0, 1), std::invalid_argument);
}

TEST(Timeline, MapsTimesAndFrames) {
  const Timeline t = make(2.0, 201);
  EXPECT_DOUBLE_EQ(t.frame_interval(), 0.01);
  EXPECT_EQ(t.frame_at(0.0), 0);
  EXPECT_EQ(t.frame_at(0.014), 1);
  EXPECT_EQ(t.frame_at(0.016), 2);
  EXPECT_EQ(t.frame_at(5.0), 200);
  EXPECT_EQ(t.frame_at(-1.0), 0);
  EXPECT_DOUBLE_EQ(t.time_of_frame(200), 2.0);
  EXPECT_DOUBLE_EQ(t.time_of_frame(1000), 2.0);
  EXPECT_DOUBLE_EQ(t.time_of_frame(50), 0.5);
}

TEST(Timeline, SeekClampsToTheFlight) {
  Timeline t = make();
  t.seek(3.0);
  EXPECT_DOUBLE_EQ(t.time(), 2.0);
  t.seek(-0.5);
  EXPECT_DOUBLE_EQ(t.time(), 0.0);
  t.seek(0.7);
  EXPECT_EQ(t.frame(), 70);
}

TEST(Timeline, StepsToTheNeighbouringFrame) {
  Timeline t = make(2.0, 201);
  t.seek(0.505);  // between frames 50 and 51
  t.step(1);
  EXPECT_NEAR(t.time(), 0.51, 1e-12);
  t.seek(0.505);
  t.step(-1);
  EXPECT_NEAR(t.time(), 0.50, 1e-12);
  t.step(-1);
  EXPECT_NEAR(t.time(), 0.49, 1e-12);
  t.step(10);
  EXPECT_NEAR(t.time(), 0.59, 1e-12);
}

TEST(Timeline, StepClampsWithoutLoopAndWrapsWithLoop) {
  Timeline t = make(1.0, 11);
  t.set_loop(false);
  t.seek(1.0);
  t.step(1);
  EXPECT_DOUBLE_EQ(t.time(), 1.0);
  t.seek(0.0);
  t.step(-1);
  EXPECT_DOUBLE_EQ(t.time(), 0.0);
  t.set_loop(true);
  t.step(-1);
  EXPECT_DOUBLE_EQ(t.time(), 1.0);
  t.step(1);
  EXPECT_DOUBLE_EQ(t.time(), 0.0);
}

TEST(Timeline, StepPausesPlayback) {
  Timeline t = make();
  t.play();
  t.step(1);
  EXPECT_FALSE(t.playing());
}

TEST(Timeline, SpeedIsClamped) {
  Timeline t = make();
  t.set_speed(0.01);
  EXPECT_DOUBLE_EQ(t.speed(), Timeline::kMinSpeed);
  t.set_speed(5.0);
  EXPECT_DOUBLE_EQ(t.speed(), Timeline::kMaxSpeed);
  t.set_speed(0.5);
  EXPECT_DOUBLE_EQ(t.speed(), 0.5);
}

TEST(Timeline, AdvancesWithSpeedOnlyWhilePlaying) {
  Timeline t = make(2.0, 201);
  EXPECT_FALSE(t.advance(0.1));
  EXPECT_DOUBLE_EQ(t.time(), 0.0);
  t.set_speed(0.5);
  t.play();
  EXPECT_TRUE(t.advance(0.2));
  EXPECT_DOUBLE_EQ(t.time(), 0.1);
}

TEST(Timeline, LoopWrapsAndNoLoopStopsAtTheEnd) {
  Timeline t = make(2.0, 201);
  t.set_loop(true);
  t.seek(1.9);
  t.play();
  t.advance(0.3);
  EXPECT_NEAR(t.time(), 0.2, 1e-12);
  EXPECT_TRUE(t.playing());

  t.set_loop(false);
  t.seek(1.9);
  t.advance(0.3);
  EXPECT_DOUBLE_EQ(t.time(), 2.0);
  EXPECT_FALSE(t.playing());
  // Play again from the end restarts from the beginning.
  t.play();
  EXPECT_DOUBLE_EQ(t.time(), 0.0);
  EXPECT_TRUE(t.playing());
}

TEST(Timeline, KeepsTimeWhenTheRangeChanges) {
  Timeline t = make(2.0, 201);
  t.seek(1.5);
  t.play();
  t.set_range(1.0, 101);
  EXPECT_DOUBLE_EQ(t.time(), 1.0);
  EXPECT_FALSE(t.playing());
}

TEST(KeyframeTicks, PlacesGivenAndOptimisedTimesAlongTheSlider) {
  const auto ticks = keyframe_ticks({0.0, 0.5, 2.0}, {0.0, 0.6, 2.0}, 2.0);
  ASSERT_EQ(ticks.size(), 6u);
  EXPECT_EQ(ticks[1].kind, TickKind::kGiven);
  EXPECT_DOUBLE_EQ(ticks[1].fraction, 0.25);
  EXPECT_EQ(ticks[4].kind, TickKind::kOptimised);
  EXPECT_EQ(ticks[4].keyframe, 1);
  EXPECT_DOUBLE_EQ(ticks[4].fraction, 0.3);
  EXPECT_DOUBLE_EQ(ticks[5].fraction, 1.0);
  EXPECT_EQ(keyframe_ticks({0.0, 1.0}, {}, 1.0).size(), 2u);
}

TEST(ApparatusFlags, FlagTheClosestPassAndTheEntryInTimeOrder) {
  ApparatusClearance c;
  c.kind = ApparatusKind::kPlatform;
  c.min_distance_m = -0.52;
  c.time_s = 1.2;
  c.point = "left toes";
  c.edge_m = 0.52;
  c.vertical_m = 1.29;
  c.collision = true;
  DiveEntry e;
  e.time_s = 1.5;
  e.first_contact = "right hand";
  e.angle_to_vertical_deg = 13.7;
  e.head_first = true;
  e.vertical = false;
  const std::vector<TimelineFlag> flags = apparatus_flags(c, e, 1.5);
  ASSERT_EQ(flags.size(), 2u);
  EXPECT_EQ(flags[0].kind, FlagKind::kCollision);
  EXPECT_DOUBLE_EQ(flags[0].fraction, 0.8);
  EXPECT_EQ(flags[0].text,
            "Closest to the platform at 1.200 s: inside its space by 0.52 m (left toes, 0.52 m "
            "behind its edge, 1.29 m below its top): the body would strike the platform");
  EXPECT_EQ(flags[1].kind, FlagKind::kEntryOffLine);
  EXPECT_DOUBLE_EQ(flags[1].fraction, 1.0);
  EXPECT_EQ(flags[1].text,
            "Entry at 1.500 s: right hand first, body 13.7° from vertical, head first: not "
            "vertical (within 10°)");
  // A trampoline: one flag, clear of the frame.
  c.kind = ApparatusKind::kTrampoline;
  c.min_distance_m = 0.68;
  c.edge_m = 0.68;
  c.collision = false;
  c.time_s = 3.0;
  const std::vector<TimelineFlag> one = apparatus_flags(c, std::nullopt, 2.0);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].kind, FlagKind::kClearance);
  EXPECT_DOUBLE_EQ(one[0].fraction, 1.0);  // clamped to the slider
  EXPECT_EQ(one[0].text,
            "Closest to the trampoline frame at 3.000 s: clear by 0.68 m (left toes, 0.68 m "
            "inside the bed's edge)");
}

TEST(Timeline, SpeedChoicesSpanTheAllowedRange) {
  const auto choices = speed_choices();
  EXPECT_DOUBLE_EQ(choices.front(), Timeline::kMinSpeed);
  EXPECT_DOUBLE_EQ(choices.back(), Timeline::kMaxSpeed);
  EXPECT_NE(std::find(choices.begin(), choices.end(), 1.0), choices.end());
  EXPECT_EQ(format_time(0.5, 2.04), "0.500 s / 2.040 s");
}

}  // namespace
}  // namespace saltus::gui
