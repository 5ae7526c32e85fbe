#pragma once
/// @file
/// The 3D view: a BodyScene in a VtkImageWidget. The mouse rotates, pans and zooms the camera;
/// a left click without dragging on a body segment reports that segment. Moving pictures
/// (playback, a turning camera) are drawn fast; once the picture has kept still for a moment it
/// is drawn again anti-aliased, as are pictures taken for export. Included only inside gui/app.

#include <QTimer>

#include "app/vtk_image_widget.h"
#include "core/click_tracker.h"
#include "scene/body_scene.h"

namespace saltus::gui {

class SceneWidget : public VtkImageWidget {
  Q_OBJECT

 public:
  explicit SceneWidget(QWidget* parent = nullptr);

  BodyScene& scene() { return scene_; }
  /// Renders the current picture anti-aliased now (exports, screenshots, tests).
  void render_refined();
  /// How long the picture must keep still before it is refined, ms.
  static constexpr int kRefineDelayMs = 300;

 signals:
  /// A left click (press and release without dragging) on a body segment: its index in the
  /// model; -1 for a click on anything else.
  void segment_clicked(int segment);

 protected:
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void rendered() override;

 private:
  BodyScene scene_;
  ClickTracker click_;
  QTimer refine_;
  bool refining_ = false;
};

}  // namespace saltus::gui
