#include "app/scene_widget.h"

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

namespace saltus::gui {

SceneWidget::SceneWidget(QWidget* parent) : QVTKOpenGLNativeWidget(parent) {
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  // Software OpenGL under Xvfb: no multisampling, which would cost most of the frame rate.
  window->SetMultiSamples(0);
  setRenderWindow(window);
  scene_.attach(window);
  // Trackball (not VTK's default joystick) so the view only moves while the mouse drags.
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor()->SetInteractorStyle(style);
  setMinimumSize(320, 240);
}

void SceneWidget::render_now() {
  renderWindow()->Render();
}

}  // namespace saltus::gui
