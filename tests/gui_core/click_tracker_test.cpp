// Click or drag in the 3D view: only a press and release without moving picks a segment; a
// drag (camera rotation) never does, even when it ends where it started.

#include <gtest/gtest.h>

#include "core/click_tracker.h"

namespace saltus::gui {
namespace {

TEST(ClickTracker, PressAndReleaseInPlaceIsAClick) {
  ClickTracker c(4);
  c.press(100, 50);
  EXPECT_TRUE(c.pressed());
  EXPECT_TRUE(c.release(100, 50));
  EXPECT_FALSE(c.pressed());
}

TEST(ClickTracker, SmallJitterBelowTheToleranceIsStillAClick) {
  ClickTracker c(4);
  c.press(100, 50);
  c.move(101, 51);  // Manhattan 2
  c.move(102, 49);  // Manhattan 3
  EXPECT_TRUE(c.release(101, 52));
}

TEST(ClickTracker, MovingAsFarAsTheToleranceIsADrag) {
  ClickTracker c(4);
  c.press(100, 50);
  c.move(102, 52);  // Manhattan 4: a drag, as Qt starts a drag at startDragDistance
  EXPECT_FALSE(c.release(102, 52));
  // Only in the release: a drag too.
  c.press(100, 50);
  EXPECT_FALSE(c.release(130, 50));
}

TEST(ClickTracker, ADragThatComesBackIsNoClick) {
  // Rotating the camera and returning the mouse to where it started must not pick.
  ClickTracker c(4);
  c.press(100, 50);
  c.move(160, 90);
  c.move(100, 50);
  EXPECT_FALSE(c.release(100, 50));
}

TEST(ClickTracker, ReleaseWithoutPressOrAfterCancelIsNoClick) {
  ClickTracker c(4);
  EXPECT_FALSE(c.release(10, 10));
  c.press(10, 10);
  c.cancel();
  EXPECT_FALSE(c.pressed());
  EXPECT_FALSE(c.release(10, 10));
  // Moves without a press change nothing.
  c.move(500, 500);
  c.press(20, 20);
  EXPECT_TRUE(c.release(20, 21));
}

TEST(ClickTracker, ANewPressStartsAFreshGesture) {
  ClickTracker c(4);
  c.press(0, 0);
  c.move(50, 0);      // a drag ...
  c.press(200, 200);  // ... forgotten by the next press (its release was lost)
  EXPECT_TRUE(c.release(201, 200));
}

TEST(ClickTracker, ToleranceIsAtLeastOnePixel) {
  ClickTracker c(0);
  EXPECT_EQ(c.tolerance(), 1);
  c.press(5, 5);
  EXPECT_TRUE(c.release(5, 5));
  c.press(5, 5);
  EXPECT_FALSE(c.release(6, 5));
}

}  // namespace
}  // namespace saltus::gui
