#include "app/scene_widget.h"

#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkRenderWindowInteractor.h>

#include <QApplication>
#include <QMouseEvent>

namespace saltus::gui {

SceneWidget::SceneWidget(QWidget* parent)
    : VtkImageWidget(parent), click_(QApplication::startDragDistance()) {
  scene_.attach(render_window());
  // Trackball (not VTK's default joystick) so the view only moves while the mouse drags.
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor()->SetInteractorStyle(style);
  setMinimumSize(320, 240);
  refine_.setSingleShot(true);
  refine_.setInterval(kRefineDelayMs);
  connect(&refine_, &QTimer::timeout, this, &SceneWidget::render_refined);
}

void SceneWidget::render_refined() {
  refine_.stop();
  if (!isVisible()) return;
  refining_ = true;
  scene_.set_antialiasing(true);
  render_now();
  scene_.set_antialiasing(false);
  refining_ = false;
}

void SceneWidget::rendered() {
  // A fast picture: refine it once nothing has changed for a moment.
  if (!refining_) refine_.start();
}

void SceneWidget::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton) click_.press(event->x(), event->y());
  VtkImageWidget::mousePressEvent(event);
}

void SceneWidget::mouseMoveEvent(QMouseEvent* event) {
  click_.move(event->x(), event->y());
  VtkImageWidget::mouseMoveEvent(event);
}

void SceneWidget::mouseReleaseEvent(QMouseEvent* event) {
  // The camera's rotation ends first (it re-renders an unchanged view after a click).
  VtkImageWidget::mouseReleaseEvent(event);
  if (event->button() != Qt::LeftButton || !click_.release(event->x(), event->y())) return;
  // Where VTK saw the release: render-window pixels from the bottom-left.
  const int* at = interactor()->GetEventPosition();
  emit segment_clicked(scene_.segment_at(at[0], at[1]));
}

}  // namespace saltus::gui
