// Camera preset names (batch flag --camera and stored settings) round-trip.

#include <gtest/gtest.h>

#include "core/scene_options.h"

namespace saltus::gui {
namespace {

TEST(SceneOptions, CameraPresetNamesRoundTrip) {
  for (CameraPreset p :
       {CameraPreset::kSide, CameraPreset::kFront, CameraPreset::kTop, CameraPreset::kFollow})
    EXPECT_EQ(camera_preset_from_name(camera_preset_name(p)), p);
  EXPECT_EQ(camera_preset_name(CameraPreset::kFollow), "follow");
  EXPECT_FALSE(camera_preset_from_name("diagonal").has_value());
}

TEST(SceneOptions, KeyframeGhostsAreOffByDefault) {
  // They clutter the follow camera; the View menu turns them on.
  EXPECT_FALSE(SceneOptions{}.ghosts);
  EXPECT_TRUE(SceneOptions{}.residual_arrows);
}

}  // namespace
}  // namespace saltus::gui
