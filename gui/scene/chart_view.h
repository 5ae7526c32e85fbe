#pragma once
/// @file
/// Draws a ChartSpec with VTK's charts (vtkChartXY in a vtkContextView): lines with legend,
/// fixed axes with titles and units, vertical keyframe markers and a time cursor. The same class
/// draws into the app's Qt widget and into offscreen windows for exported PNG figures.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/chart_spec.h"

class vtkRenderWindow;
class vtkRenderWindowInteractor;

namespace saltus::gui {

class ChartView {
 public:
  ChartView();
  ~ChartView();
  ChartView(const ChartView&) = delete;
  ChartView& operator=(const ChartView&) = delete;

  /// Draws into `window` (the Qt widget's, or an offscreen one). `interactor` may be null.
  void set_render_window(vtkRenderWindow* window, vtkRenderWindowInteractor* interactor);

  /// Replaces what the chart shows. Axes are fixed to the data, so a cursor drawn over the
  /// chart (see plot_area) stays valid until the next set_chart.
  void set_chart(const ChartSpec& spec);
  const ChartSpec& chart() const;

  /// The rectangle between the axes after the last render, render-window pixels from the
  /// bottom-left; empty (right <= left) before the first render.
  struct PlotArea {
    float left = 0, right = 0, bottom = 0, top = 0;
    double x_min = 0, x_max = 1;  ///< data x at left and right
  };
  PlotArea plot_area() const;

  /// Data x under a pixel of the render window (x from the left, y from the bottom); nullopt
  /// outside the plot area.
  std::optional<double> x_at_pixel(int x, int y) const;

  /// Text size in points for titles (labels are 2 points smaller).
  void set_font_size(int points);
  /// Whether the chart draws its legend inside the plot (default true, as exported figures
  /// do). The app's charts pass false and show the legend in a row above the chart instead
  /// (LegendStrip), where it covers no curve and no keyframe line.
  void set_legend_drawn(bool drawn);
  bool legend_drawn() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Renders a chart offscreen at width × height pixels into a PNG file (needs an X display, e.g.
/// under xvfb-run). Throws std::runtime_error if the file cannot be written.
void write_chart_png(const ChartSpec& spec, const std::string& path, int width, int height,
                     int font_points = 14);

/// Renders charts offscreen, each panel_width × panel_height pixels, in a grid of `columns`
/// per row (row by row, top first) into one PNG file. Throws std::runtime_error if the file
/// cannot be written or `charts` is empty.
void write_chart_grid_png(const std::vector<ChartSpec>& charts, int columns,
                          const std::string& path, int panel_width, int panel_height,
                          int font_points = 14);

}  // namespace saltus::gui
