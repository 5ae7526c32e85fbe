#pragma once
/// @file
/// The 3D view: a QVTKOpenGLNativeWidget showing a BodyScene (mouse: rotate, pan, zoom the
/// camera). Included only inside gui/app.

#include <QVTKOpenGLNativeWidget.h>

#include "scene/body_scene.h"

namespace saltus::gui {

class SceneWidget : public QVTKOpenGLNativeWidget {
  Q_OBJECT

 public:
  explicit SceneWidget(QWidget* parent = nullptr);

  BodyScene& scene() { return scene_; }
  /// Renders the scene now (after any change to it).
  void render_now();

 private:
  BodyScene scene_;
};

}  // namespace saltus::gui
