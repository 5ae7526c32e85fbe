#pragma once
/// @file
/// The 3D view: a BodyScene in a VtkImageWidget. The mouse rotates, pans and zooms the camera;
/// a left click without dragging on a body segment reports that segment. Included only inside
/// gui/app.

#include "app/vtk_image_widget.h"
#include "core/click_tracker.h"
#include "scene/body_scene.h"

namespace saltus::gui {

class SceneWidget : public VtkImageWidget {
  Q_OBJECT

 public:
  explicit SceneWidget(QWidget* parent = nullptr);

  BodyScene& scene() { return scene_; }

 signals:
  /// A left click (press and release without dragging) on a body segment: its index in the
  /// model; -1 for a click on anything else.
  void segment_clicked(int segment);

 protected:
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;

 private:
  BodyScene scene_;
  ClickTracker click_;
};

}  // namespace saltus::gui
