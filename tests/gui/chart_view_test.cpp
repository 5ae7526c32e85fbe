// Where an exported chart puts its legend: in the top right corner of the plot by default, and
// in a column beside the plot when the chart asks for it (ChartSpec::legend_beside), as the
// twist figure does, whose tilt curves can end in any corner of the plot.

#include <gtest/gtest.h>

#include <vtkNew.h>
#include <vtkRenderWindow.h>

#include "core/twist_report.h"
#include "scene/chart_view.h"

namespace saltus::gui {
namespace {

/// The plot area of `spec` rendered offscreen at width × height pixels.
ChartView::PlotArea rendered_plot_area(const ChartSpec& spec, int width, int height) {
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  ChartView view;
  view.set_render_window(window, nullptr);
  view.set_chart(spec);
  window->Render();
  return view.plot_area();
}

/// A twist analysis as the library makes one: the actual flight, the take-off only and two arms
/// made symmetric, the last of them rising to the top right corner.
TwistSources tilts_to_the_corner() {
  TwistSources s;
  s.reference_time_s = 0.9;
  s.total_tilt_deg = 9.0;
  s.shares = {{"take-off", 0.0, 0.0}, {"left arm", 5.0, 55.0}, {"right arm", 4.0, 45.0}};
  s.times = {0.0, 0.9, 1.9};
  s.flight_names = {"actual", "take-off only", "without left arm", "without right arm"};
  s.tilt_deg = {{0, 9, 4}, {0, 0, 0}, {0, 4, 2}, {0, 5, 12}};
  return s;
}

TEST(ChartLegend, TheTwistFigureKeepsItsLegendBesideThePlot) {
  const ChartSpec twist = twist_chart(tilts_to_the_corner());
  ASSERT_TRUE(twist.legend_beside);
  ChartSpec inside = twist;
  inside.legend_beside = false;
  const int width = 1200, height = 600;
  const ChartView::PlotArea beside_area = rendered_plot_area(twist, width, height);
  const ChartView::PlotArea inside_area = rendered_plot_area(inside, width, height);
  // Inside, the plot reaches nearly to the right edge and the legend's box lies on it; beside,
  // the plot ends where a column wide enough for "right arm made symmetric" begins.
  EXPECT_GT(inside_area.right, width - 60) << inside_area.right;
  EXPECT_LT(beside_area.right, width - 150) << beside_area.right;
  EXPECT_GT(beside_area.right - beside_area.left, 0.5 * width)
      << "the plot keeps most of the width";
}

}  // namespace
}  // namespace saltus::gui
