#pragma once
/// @file
/// The 3D view's camera (private to gui/scene): every preset looks at the athlete from a side
/// named after the athlete's own take-off axes (Side: from the right; Front: from where the
/// face looks; Top; Follow: three-quarter, from the right, in front and a little above), keeps
/// the standing body at about 60 % of the view's height, and follows the centre of mass: each
/// new time moves the camera with the body, keeping whatever turn, zoom or pan the user gave it,
/// so zooming always closes in on the body.

#include <vtkCamera.h>

#include <Eigen/Core>

#include "core/scene_options.h"

namespace saltus::gui::scene {

class SceneCamera {
 public:
  /// Share of the view's height the standing body fills.
  static constexpr double kBodyShare = 0.6;
  static constexpr double kViewAngleDeg = 30.0;

  /// The athlete's horizontal facing direction and left at take-off (unit vectors), and the
  /// standing body's height (m).
  void set_athlete(const Eigen::Vector3d& forward, const Eigen::Vector3d& left, double body_height);
  void set_preset(CameraPreset preset) { preset_ = preset; }
  CameraPreset preset() const { return preset_; }
  /// Camera distance that makes the standing body kBodyShare of the view's height, m.
  double distance() const;
  /// The unit vector from the body towards the camera for the preset.
  Eigen::Vector3d direction() const;

  /// Places the camera for the preset, looking at `com`.
  void reset(vtkCamera* camera, const Eigen::Vector3d& com);
  /// Moves the camera with the body from the last CoM to `com`, keeping its offset.
  void follow(vtkCamera* camera, const Eigen::Vector3d& com);

 private:
  CameraPreset preset_ = CameraPreset::kFollow;
  Eigen::Vector3d forward_ = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d left_ = Eigen::Vector3d::UnitX();
  double body_height_ = 1.7;
  Eigen::Vector3d last_com_ = Eigen::Vector3d(0, 1, 0);
};

}  // namespace saltus::gui::scene
