#pragma once
/// @file
/// What the 3D view shows and from where: plain settings shared by the VTK scene, the Qt
/// widgets and batch mode (and stored in the app's settings). Every display option is declared
/// once, in scene_option_table(): the View menu, the Display panel, the settings and the
/// compare window walk that table, so a new option is a field here and a row there.

#include <optional>
#include <string>
#include <vector>

namespace saltus::gui {

struct SceneOptions {
  /// The apparatus that fits the motion: trampoline, or platform and water for a dive.
  bool apparatus = true;
  bool floor_grid = true;
  bool parabola = true;
  bool com_trace = true;
  bool residual_arrows = true;
  bool joint_arrows = false;
  /// Off by default: the keyframe poses clutter the follow camera; View menu to show them.
  bool ghosts = false;
  /// The small picture of the whole flight in a corner (the main view follows the body).
  bool flight_inset = true;
  bool physics_text = true;
  /// A motion imported from a capture: the capture's own motion as a grey figure beside the
  /// athlete, at the same time.
  bool capture_figure = true;
};

/// One display option: where it is stored, what the user reads, which field it switches.
struct SceneOptionInfo {
  const char* key;    ///< settings key (under "view/"), stable across versions
  const char* label;  ///< View menu and Display panel
  const char* tip;    ///< tooltip: what the option draws
  bool SceneOptions::*field;
};

/// Every display option in menu order.
const std::vector<SceneOptionInfo>& scene_option_table();

enum class CameraPreset { kSide, kFront, kTop, kFollow };

/// Every preset in menu order (Side, Front, Top, Follow).
std::vector<CameraPreset> camera_presets();
/// "side", "front", "top", "follow".
std::string camera_preset_name(CameraPreset preset);
/// "Side", "Front", "Top", "Follow": toolbar and menu labels.
std::string camera_preset_label(CameraPreset preset);
/// Inverse of camera_preset_name; nullopt for other names.
std::optional<CameraPreset> camera_preset_from_name(const std::string& name);

}  // namespace saltus::gui
