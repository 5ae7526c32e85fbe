#include "app/chart_widget.h"

#include <QMouseEvent>
#include <QPalette>
#include <cmath>

namespace saltus::gui {

ChartWidget::ChartWidget(QWidget* parent) : VtkImageWidget(parent), cursor_time_(std::nan("")) {
  view_.set_render_window(render_window(), interactor());
  setMinimumSize(240, 160);
  // A click gives it the focus, so that the playback keys act after clicking a plot.
  setFocusPolicy(Qt::ClickFocus);
  setToolTip(tr("Click or drag to move the time cursor"));
  cursor_ = new QWidget(this);
  cursor_->setAttribute(Qt::WA_TransparentForMouseEvents);
  cursor_->setAutoFillBackground(true);
  QPalette palette = cursor_->palette();
  palette.setColor(QPalette::Window, QColor(20, 20, 20));
  cursor_->setPalette(palette);
  cursor_->hide();
}

void ChartWidget::set_chart(const ChartSpec& spec) {
  view_.set_chart(spec);
  request_render();
  emit chart_changed();
}

void ChartWidget::set_cursor(double t) {
  cursor_time_ = t;
  place_cursor();
}

void ChartWidget::place_cursor() {
  const ChartView::PlotArea a = view_.plot_area();
  if (!std::isfinite(cursor_time_) || !(a.right > a.left) || !(a.x_max > a.x_min) ||
      cursor_time_ < a.x_min || cursor_time_ > a.x_max) {
    cursor_->hide();
    return;
  }
  // Render-window pixels (from the bottom) to widget coordinates (from the top).
  const double ratio = devicePixelRatioF();
  const double u = (cursor_time_ - a.x_min) / (a.x_max - a.x_min);
  const int x = static_cast<int>(std::lround((a.left + u * (a.right - a.left)) / ratio));
  const int top = static_cast<int>(std::lround(height() - a.top / ratio));
  const int bottom = static_cast<int>(std::lround(height() - a.bottom / ratio));
  const QRect geometry(x - 1, top, 2, std::max(1, bottom - top));
  if (cursor_->geometry() != geometry) cursor_->setGeometry(geometry);
  cursor_->show();
}

void ChartWidget::rendered() {
  // The plot area is known once the chart has been laid out by a render.
  place_cursor();
}

bool ChartWidget::seek_at(const QPoint& position) {
  // Chart coordinates are render-window pixels from the bottom-left.
  const double ratio = devicePixelRatioF();
  const int x = static_cast<int>(position.x() * ratio);
  const int y = static_cast<int>((height() - position.y()) * ratio);
  const std::optional<double> t = view_.x_at_pixel(x, y);
  if (!t) return false;
  emit seek_requested(*t);
  return true;
}

void ChartWidget::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton && seek_at(event->pos())) {
    event->accept();
    return;
  }
  VtkImageWidget::mousePressEvent(event);
}

void ChartWidget::mouseMoveEvent(QMouseEvent* event) {
  if ((event->buttons() & Qt::LeftButton) && seek_at(event->pos())) {
    event->accept();
    return;
  }
  VtkImageWidget::mouseMoveEvent(event);
}

}  // namespace saltus::gui
