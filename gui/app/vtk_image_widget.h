#pragma once
/// @file
/// A VTK render window drawn offscreen and shown as a picture in a plain QWidget; the mouse goes
/// on to the window's VTK interactor (camera, chart tooltips). The base of the 3D view and the
/// charts. Included only inside gui/app.
///
/// Why not QVTKOpenGLNativeWidget: it is a QOpenGLWidget, and one QOpenGLWidget in a window
/// makes Qt composite the whole window with OpenGL and swap all of it to the screen whenever
/// anything in it changes (the time label, the slider, a plot cursor). With Mesa's software
/// OpenGL that took 25 ms a frame at 1600×1000 during playback, more than rendering the 3D scene
/// (18 ms). Here the window stays a raster window: a new picture costs VTK's render, a read-back
/// (under a millisecond in software OpenGL, a small copy on a GPU) and the repaint of this
/// widget's rectangle. QVTKOpenGLStereoWidget (a native child window) was tried for the 3D view:
/// window screenshots (QWidget::grab) show an empty rectangle where it is, it renders only once
/// exposed on a screen, and as long as any QOpenGLWidget (a chart) remained, the composition did
/// too (9 frames per second).

#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <QImage>
#include <QWidget>

class QVTKInteractor;
class QVTKInteractorAdapter;
class vtkRenderWindow;
class vtkRenderWindowInteractor;

namespace saltus::gui {

class VtkImageWidget : public QWidget {
  Q_OBJECT

 public:
  explicit VtkImageWidget(QWidget* parent = nullptr);
  ~VtkImageWidget() override;

  vtkRenderWindow* render_window() const;
  vtkRenderWindowInteractor* interactor() const;

  /// Asks for a new picture after a change. It is rendered when the widget is next painted, so
  /// that several changes before that (or while hidden in another tab) cost one render.
  void request_render();
  /// Renders now if the widget is shown (else once it is) and repaints.
  void render_now();
  /// The current picture in device pixels, rendered first if a render is pending.
  QImage picture();
  /// Renders so far, by this widget or by the interactor (e.g. while the camera rotates).
  int render_count() const { return render_count_; }

 signals:
  /// A picture not painted before has been painted (it reaches the screen with this repaint).
  void frame_shown();

 protected:
  /// Called after every render with the new picture in place, e.g. to place overlay widgets.
  virtual void rendered() {}
  /// Passes a mouse or wheel event on to the VTK interactor.
  void forward(QEvent* event);

  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void enterEvent(QEvent* event) override;
  void leaveEvent(QEvent* event) override;

 private:
  /// Renders at the widget's size in device pixels (nothing while it has no size).
  void render();
  /// After each render of the window (EndEvent): copies the picture out of it.
  void read_picture();
  QSize device_size() const;

  vtkSmartPointer<vtkRenderWindow> window_;
  vtkSmartPointer<QVTKInteractor> interactor_;
  QVTKInteractorAdapter* adapter_ = nullptr;
  vtkNew<vtkUnsignedCharArray> pixels_;
  unsigned long end_observer_ = 0;
  QImage image_;
  bool pending_ = true;  ///< the picture is out of date
  bool painting_ = false;
  bool shown_ = false;  ///< image_ has been painted
  int render_count_ = 0;
};

}  // namespace saltus::gui
