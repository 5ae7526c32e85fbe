#include "scene/scene_camera.h"

#include <cmath>

namespace saltus::gui::scene {

void SceneCamera::set_athlete(const Eigen::Vector3d& forward, const Eigen::Vector3d& left,
                              double body_height) {
  forward_ = forward.normalized();
  left_ = left.normalized();
  body_height_ = body_height > 0 ? body_height : 1.7;
}

double SceneCamera::distance() const {
  const double half_angle = 0.5 * kViewAngleDeg * 3.14159265358979323846 / 180.0;
  return body_height_ / (kBodyShare * 2.0 * std::tan(half_angle));
}

Eigen::Vector3d SceneCamera::direction() const {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  switch (preset_) {
    case CameraPreset::kSide:
      return -left_;  // from the athlete's right: a somersault turns in the picture's plane
    case CameraPreset::kFront:
      return forward_;
    case CameraPreset::kTop:
      return up;
    case CameraPreset::kFollow:
      break;
  }
  // Three-quarter from the right, in front and a little above: both sides of the body and its
  // depth show.
  return (-left_ + 0.35 * up + 0.8 * forward_).normalized();
}

void SceneCamera::reset(vtkCamera* camera, const Eigen::Vector3d& com) {
  const Eigen::Vector3d up = preset_ == CameraPreset::kTop ? forward_ : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d position = com + distance() * direction();
  camera->SetViewAngle(kViewAngleDeg);
  camera->SetFocalPoint(com.x(), com.y(), com.z());
  camera->SetPosition(position.x(), position.y(), position.z());
  camera->SetViewUp(up.x(), up.y(), up.z());
  last_com_ = com;
}

void SceneCamera::follow(vtkCamera* camera, const Eigen::Vector3d& com) {
  const Eigen::Vector3d shift = com - last_com_;
  double p[3], f[3];
  camera->GetPosition(p);
  camera->GetFocalPoint(f);
  camera->SetFocalPoint(f[0] + shift.x(), f[1] + shift.y(), f[2] + shift.z());
  camera->SetPosition(p[0] + shift.x(), p[1] + shift.y(), p[2] + shift.z());
  last_com_ = com;
}

}  // namespace saltus::gui::scene
