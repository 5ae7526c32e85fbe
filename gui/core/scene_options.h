#pragma once
/// @file
/// What the 3D view shows and from where: plain settings shared by the VTK scene, the Qt
/// widgets and batch mode (and stored in the app's settings).

#include <optional>
#include <string>

namespace saltus::gui {

struct SceneOptions {
  bool trampoline = true;
  bool floor_grid = true;
  bool parabola = true;
  bool com_trace = true;
  bool residual_arrows = true;
  bool joint_arrows = false;
  /// Off by default: the keyframe poses clutter the follow camera; View menu to show them.
  bool ghosts = false;
  bool physics_text = true;
};

enum class CameraPreset { kSide, kFront, kTop, kFollow };

/// "side", "front", "top", "follow".
std::string camera_preset_name(CameraPreset preset);
/// Inverse of camera_preset_name; nullopt for other names.
std::optional<CameraPreset> camera_preset_from_name(const std::string& name);

}  // namespace saltus::gui
