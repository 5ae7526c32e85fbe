// The first size of a window (core/screen_fit.h): the preferred size where the screen has room,
// else the screen's available area less the frame, and maximised; never larger than the screen.

#include "core/screen_fit.h"

#include <gtest/gtest.h>

namespace saltus::gui {
namespace {

TEST(ScreenFit, ThePreferredSizeWhereTheScreenHasRoom) {
  const WindowFit fit = first_window_size(1920, 1050, 1600, 1000);
  EXPECT_EQ(fit.width, 1600);
  EXPECT_EQ(fit.height, 1000);
  EXPECT_FALSE(fit.maximise);
}

TEST(ScreenFit, TheScreenLessItsFrameOnALaptopAndMaximised) {
  for (const auto& [w, h] : {std::pair{1366, 740}, std::pair{1024, 700}, std::pair{1280, 690}}) {
    const WindowFit fit = first_window_size(w, h, 1600, 1000);
    EXPECT_EQ(fit.width, w - kFrameWidth);
    EXPECT_EQ(fit.height, h - kFrameHeight);
    EXPECT_LE(fit.width + kFrameWidth, w);
    EXPECT_LE(fit.height + kFrameHeight, h);
    EXPECT_TRUE(fit.maximise);
  }
  // Only one dimension short: that one shrinks.
  const WindowFit tall = first_window_size(1920, 900, 1500, 950);
  EXPECT_EQ(tall.width, 1500);
  EXPECT_EQ(tall.height, 900 - kFrameHeight);
  EXPECT_TRUE(tall.maximise);
  // No screen known: the preferred size.
  EXPECT_EQ(first_window_size(0, 0, 1600, 1000).width, 1600);
}

}  // namespace
}  // namespace saltus::gui
