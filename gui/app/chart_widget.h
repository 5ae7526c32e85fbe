#pragma once
/// @file
/// A VTK chart (vtkChartXY in a vtkContextView) in a Qt widget, with the time cursor on top.
/// Clicking or dragging in the plot area asks to seek to that time. Included only inside gui/app.

#include <QVTKOpenGLNativeWidget.h>

#include "scene/chart_view.h"

namespace saltus::gui {

class ChartWidget : public QVTKOpenGLNativeWidget {
  Q_OBJECT

 public:
  explicit ChartWidget(QWidget* parent = nullptr);

  ChartView& view() { return view_; }
  void set_chart(const ChartSpec& spec);
  /// Moves the time cursor (NaN hides it). The cursor is a thin Qt widget over the chart, so
  /// moving it during playback costs no chart redraw.
  void set_cursor(double t);
  void render_now();

 signals:
  /// The user clicked (or dragged) at time t in the plot area.
  void seek_requested(double t);

 protected:
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void paintGL() override;
  void showEvent(QShowEvent* event) override;

 private:
  bool seek_at(const QPoint& position);
  void place_cursor();

  ChartView view_;
  QWidget* cursor_ = nullptr;
  double cursor_time_;
  bool stale_ = false;  ///< changed while hidden: render when shown
};

}  // namespace saltus::gui
