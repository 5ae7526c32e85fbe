// Camera preset names (batch flag --camera and stored settings) round-trip.

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "core/scene_options.h"

namespace saltus::gui {
namespace {

TEST(SceneOptions, CameraPresetNamesRoundTrip) {
  for (CameraPreset p :
       {CameraPreset::kSide, CameraPreset::kFront, CameraPreset::kTop, CameraPreset::kFollow})
    EXPECT_EQ(camera_preset_from_name(camera_preset_name(p)), p);
  EXPECT_EQ(camera_preset_name(CameraPreset::kFollow), "follow");
  EXPECT_EQ(camera_preset_label(CameraPreset::kSide), "Side");
  EXPECT_EQ(camera_presets().size(), 4u);
  EXPECT_FALSE(camera_preset_from_name("diagonal").has_value());
}

TEST(SceneOptions, EveryOptionIsDeclaredOnceWithADistinctKeyAndField) {
  const auto& table = scene_option_table();
  std::set<std::string> keys, labels;
  std::vector<bool SceneOptions::*> fields;
  for (const SceneOptionInfo& info : table) {
    keys.insert(info.key);
    labels.insert(info.label);
    for (auto field : fields)
      EXPECT_NE(field, info.field) << info.key;  // member pointers compare only for equality
    fields.push_back(info.field);
    EXPECT_FALSE(std::string(info.tip).empty()) << info.key;
  }
  EXPECT_EQ(keys.size(), table.size());
  EXPECT_EQ(labels.size(), table.size());
  EXPECT_EQ(fields.size(), table.size());
  // Every bool of SceneOptions is in the table: switching each one through the table changes
  // a distinct field and nothing else.
  EXPECT_EQ(sizeof(SceneOptions), table.size() * sizeof(bool));
  for (const SceneOptionInfo& info : table) {
    SceneOptions o;
    o.*info.field = !(o.*info.field);
    int differing = 0;
    for (const SceneOptionInfo& other : table)
      differing += (o.*other.field) != (SceneOptions{}.*other.field);
    EXPECT_EQ(differing, 1) << info.key;
  }
}

TEST(SceneOptions, KeyframeGhostsAreOffByDefault) {
  // They clutter the follow camera; the View menu turns them on.
  EXPECT_FALSE(SceneOptions{}.ghosts);
  EXPECT_TRUE(SceneOptions{}.residual_arrows);
}

}  // namespace
}  // namespace saltus::gui
