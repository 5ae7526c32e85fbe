// The Capture panel's fixes (core/capture_fixes.h): the CMU backflip, whose stated frame time
// makes its flight fall slower than g, gets the library's suggested frame time one click away;
// imported with it, the flight falls at g and no fix is left. A well-timed capture has none.

#include "core/capture_fixes.h"

#include <gtest/gtest.h>

namespace saltus::gui {
namespace {

std::string capture(const std::string& name) {
  return std::string(SALTUS_EXAMPLES_DIR) + "/captures/" + name;
}

TEST(CaptureFixes, TheSuggestedFrameTimeIsOneClickAwayAndFixesTheFlight) {
  CaptureFileOptions used;
  used.import.keyframe_count = 9;  // kept by the fix
  const CaptureFile cmu = import_capture_file(capture("mass-backflip.bvh"), used);
  ASSERT_TRUE(cmu.import.suggested_frame_time);
  const std::vector<CaptureFix> fixes = capture_fixes(cmu, used);
  ASSERT_EQ(fixes.size(), 1u);
  EXPECT_EQ(fixes[0].flag, "--frame-time");
  EXPECT_EQ(fixes[0].label.rfind("Re-import at ", 0), 0u) << fixes[0].label;
  EXPECT_NE(fixes[0].reason.find("--frame-time"), std::string::npos) << fixes[0].reason;
  ASSERT_TRUE(fixes[0].options.import.frame_time);
  EXPECT_EQ(*fixes[0].options.import.frame_time, *cmu.import.suggested_frame_time);
  EXPECT_EQ(fixes[0].options.import.keyframe_count, 9);
  // Imported with it: the flight falls at g (the library's fit), and nothing is left to fix.
  const CaptureFile fixed = import_capture_file(capture("mass-backflip.bvh"), fixes[0].options);
  EXPECT_NEAR(fixed.import.implied_gravity, 9.81, 0.2 * 9.81);
  EXPECT_TRUE(capture_fixes(fixed, fixes[0].options).empty());
}

TEST(CaptureFixes, AWellTimedCaptureHasNone) {
  const CaptureFile deepmimic = import_capture_file(capture("deepmimic-backflip.bvh"));
  EXPECT_FALSE(deepmimic.import.suggested_frame_time);
  EXPECT_TRUE(capture_fixes(deepmimic, {}).empty());
}

}  // namespace
}  // namespace saltus::gui
