#include "core/scene_options.h"

namespace saltus::gui {

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

std::optional<CameraPreset> camera_preset_from_name(const std::string& name) {
  for (CameraPreset p :
       {CameraPreset::kSide, CameraPreset::kFront, CameraPreset::kTop, CameraPreset::kFollow})
    if (camera_preset_name(p) == name) return p;
  return std::nullopt;
}

}  // namespace saltus::gui
