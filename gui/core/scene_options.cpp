#include "core/scene_options.h"

namespace saltus::gui {

const std::vector<SceneOptionInfo>& scene_option_table() {
  // Keys: "trampoline" became "apparatus" when dives got a platform and water; the ghosts'
  // key changed when they became off by default (older sessions stored "on" under the old key).
  static const std::vector<SceneOptionInfo> kTable = {
      {"apparatus", "Apparatus",
       "The trampoline for a flight that lands where it took off; a platform at the take-off "
       "height and the water for a dive",
       &SceneOptions::apparatus},
      {"floor_grid", "Floor grid", "A 1 m grid on the floor", &SceneOptions::floor_grid},
      {"parabola", "CoM parabola",
       "The ballistic path of the centre of mass: where it must go in a flight, from its take-off "
       "state under gravity",
       &SceneOptions::parabola},
      {"com_trace", "CoM path", "The path this motion's centre of mass takes",
       &SceneOptions::com_trace},
      {"residual_arrows", "Residual arrows",
       "The residual force and moment at the centre of mass: what would have to act on the body "
       "for this motion; zero in a valid flight",
       &SceneOptions::residual_arrows},
      {"joint_arrows", "Joint force arrows", "The force each joint transmits",
       &SceneOptions::joint_arrows},
      {"keyframe_ghosts", "Keyframe poses", "Thin pale figures at the keyframe poses",
       &SceneOptions::ghosts},
      {"flight_inset", "Whole-flight inset",
       "A small side view of the whole flight while the main view follows the body",
       &SceneOptions::flight_inset},
      {"physics_text", "Numbers in the view", "Time, residual and rotation numbers",
       &SceneOptions::physics_text},
      {"capture_figure", "Motion capture beside",
       "For a motion imported from a capture: the capture itself as a grey figure beside the "
       "athlete, at the same moment",
       &SceneOptions::capture_figure},
  };
  return kTable;
}

std::vector<CameraPreset> camera_presets() {
  return {CameraPreset::kSide, CameraPreset::kFront, CameraPreset::kTop, CameraPreset::kFollow};
}

std::string camera_preset_name(CameraPreset preset) {
  switch (preset) {
    case CameraPreset::kSide:
      return "side";
    case CameraPreset::kFront:
      return "front";
    case CameraPreset::kTop:
      return "top";
    case CameraPreset::kFollow:
      return "follow";
  }
  return "side";
}

std::string camera_preset_label(CameraPreset preset) {
  std::string name = camera_preset_name(preset);
  name[0] = static_cast<char>(name[0] - 'a' + 'A');
  return name;
}

std::optional<CameraPreset> camera_preset_from_name(const std::string& name) {
  for (CameraPreset p : camera_presets())
    if (camera_preset_name(p) == name) return p;
  return std::nullopt;
}

}  // namespace saltus::gui
