#include "app/vtk_image_widget.h"

#include <QVTKInteractor.h>
#include <QVTKInteractorAdapter.h>
#include <vtkCommand.h>
#include <vtkRenderWindow.h>

#include <QMouseEvent>
#include <QPaintEvent>
#include <QPainter>
#include <QWheelEvent>
#include <cmath>

namespace saltus::gui {

namespace {
/// VTK's text sizes are in points at this many dots per inch on a standard-density screen
/// (QVTKOpenGLNativeWidget's default), scaled with the device pixel ratio.
constexpr double kUnscaledDpi = 72.0;
}  // namespace

VtkImageWidget::VtkImageWidget(QWidget* parent) : QWidget(parent) {
  // The picture covers the widget: no background to clear first.
  setAttribute(Qt::WA_OpaquePaintEvent);
  setMouseTracking(true);  // hover (chart tooltips) reaches VTK without a button down
  window_ = vtkSmartPointer<vtkRenderWindow>::New();
  window_->SetOffScreenRendering(1);
  // Software OpenGL: no multisampling, which would cost most of the frame rate.
  window_->SetMultiSamples(0);
  interactor_ = vtkSmartPointer<QVTKInteractor>::New();
  interactor_->SetRenderWindow(window_);
  interactor_->Initialize();
  adapter_ = new QVTKInteractorAdapter(this);
  end_observer_ = window_->AddObserver(vtkCommand::EndEvent, this, &VtkImageWidget::read_picture);
}

VtkImageWidget::~VtkImageWidget() {
  window_->RemoveObserver(end_observer_);
}

vtkRenderWindow* VtkImageWidget::render_window() const {
  return window_;
}

vtkRenderWindowInteractor* VtkImageWidget::interactor() const {
  return interactor_;
}

QSize VtkImageWidget::device_size() const {
  const double ratio = devicePixelRatioF();
  return {static_cast<int>(std::lround(width() * ratio)),
          static_cast<int>(std::lround(height() * ratio))};
}

void VtkImageWidget::request_render() {
  pending_ = true;
  update();
}

void VtkImageWidget::render_now() {
  if (!isVisible()) {
    pending_ = true;
    return;
  }
  render();
}

QImage VtkImageWidget::picture() {
  if (pending_ || image_.size() != device_size()) render();
  return image_;
}

void VtkImageWidget::render() {
  pending_ = false;
  const QSize size = device_size();
  if (size.isEmpty()) return;
  const int* current = window_->GetSize();
  if (current[0] != size.width() || current[1] != size.height()) {
    window_->SetSize(size.width(), size.height());
    interactor_->SetSize(size.width(), size.height());
  }
  const double ratio = devicePixelRatioF();
  window_->SetDPI(static_cast<int>(std::lround(kUnscaledDpi * ratio)));
  adapter_->SetDevicePixelRatio(static_cast<float>(ratio));
  window_->Render();  // read_picture() follows (EndEvent)
}

void VtkImageWidget::read_picture() {
  const int* size = window_->GetSize();
  const int w = size[0];
  const int h = size[1];
  if (w <= 0 || h <= 0) return;
  window_->GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, pixels_);
  if (image_.size() != QSize(w, h) || image_.format() != QImage::Format_RGB32)
    image_ = QImage(w, h, QImage::Format_RGB32);
  const unsigned char* rows = pixels_->GetPointer(0);
  for (int y = 0; y < h; ++y) {
    // OpenGL's rows go up from the bottom, QImage's down from the top.
    const unsigned char* in = rows + static_cast<std::size_t>(h - 1 - y) * w * 4;
    auto* out = reinterpret_cast<QRgb*>(image_.scanLine(y));
    for (int x = 0; x < w; ++x, in += 4)
      out[x] = qRgb(in[0], in[1], in[2]);
  }
  ++render_count_;
  shown_ = false;
  rendered();
  // A render inside paintEvent is painted by that same event.
  if (!painting_) update();
}

void VtkImageWidget::paintEvent(QPaintEvent* event) {
  painting_ = true;
  if (pending_ || image_.size() != device_size()) render();
  painting_ = false;
  QPainter painter(this);
  if (image_.isNull()) {
    painter.fillRect(event->rect(), palette().window());
    return;
  }
  // Only the exposed part: a moving plot cursor repaints a sliver, not the whole chart.
  const double ratio = devicePixelRatioF();
  const QRect r = event->rect();
  painter.drawImage(r, image_,
                    QRectF(r.x() * ratio, r.y() * ratio, r.width() * ratio, r.height() * ratio));
  if (!shown_) {
    shown_ = true;
    emit frame_shown();
  }
}

void VtkImageWidget::forward(QEvent* event) {
  adapter_->ProcessEvent(event, interactor_);
}

void VtkImageWidget::mousePressEvent(QMouseEvent* event) {
  forward(event);
}

void VtkImageWidget::mouseMoveEvent(QMouseEvent* event) {
  forward(event);
}

void VtkImageWidget::mouseReleaseEvent(QMouseEvent* event) {
  forward(event);
}

void VtkImageWidget::mouseDoubleClickEvent(QMouseEvent* event) {
  forward(event);
}

void VtkImageWidget::wheelEvent(QWheelEvent* event) {
  forward(event);
  event->accept();
}

void VtkImageWidget::enterEvent(QEvent* event) {
  forward(event);
}

void VtkImageWidget::leaveEvent(QEvent* event) {
  forward(event);
}

}  // namespace saltus::gui
