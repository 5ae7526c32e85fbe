#pragma once
/// @file
/// A VTK chart (vtkChartXY in a vtkContextView) in a VtkImageWidget, with the time cursor on top.
/// Clicking or dragging in the plot area asks to seek to that time. Included only inside gui/app.

#include "app/vtk_image_widget.h"
#include "scene/chart_view.h"

namespace saltus::gui {

class ChartWidget : public VtkImageWidget {
  Q_OBJECT

 public:
  explicit ChartWidget(QWidget* parent = nullptr);

  ChartView& view() { return view_; }
  /// Shows a new chart (drawn at the next repaint, or when its tab is shown).
  void set_chart(const ChartSpec& spec);
  /// Moves the time cursor (NaN hides it). The cursor is a thin Qt widget over the chart's
  /// picture, so moving it during playback costs no chart render, only the repaint of two
  /// slivers of the picture.
  void set_cursor(double t);

 signals:
  /// The user clicked (or dragged) at time t in the plot area.
  void seek_requested(double t);
  /// set_chart showed a new chart (its legend strip follows).
  void chart_changed();

 protected:
  void rendered() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;

 private:
  bool seek_at(const QPoint& position);
  void place_cursor();

  ChartView view_;
  QWidget* cursor_ = nullptr;
  double cursor_time_;
};

}  // namespace saltus::gui
