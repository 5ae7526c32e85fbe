#include "scene/chart_view.h"

#include <vtkAxis.h>
#include <vtkBrush.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextMouseEvent.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "scene/vtk_text.h"

namespace saltus::gui {

namespace {

/// The most labels on a chart's y axes and on its time axis (linear_ticks).
constexpr std::size_t kMaxYLabels = 5;
constexpr std::size_t kMaxXLabels = 8;

vtkSmartPointer<vtkTable> make_table(const std::string& x_name, const std::string& y_name,
                                     const std::vector<double>& x, const std::vector<double>& y) {
  auto table = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkDoubleArray> xs, ys;
  xs->SetName(x_name.c_str());
  ys->SetName(y_name.c_str());
  table->AddColumn(xs);
  table->AddColumn(ys);
  const std::size_t n = std::min(x.size(), y.size());
  table->SetNumberOfRows(static_cast<vtkIdType>(n));
  for (std::size_t i = 0; i < n; ++i) {
    table->SetValue(static_cast<vtkIdType>(i), 0, x[i]);
    table->SetValue(static_cast<vtkIdType>(i), 1, y[i]);
  }
  return table;
}

}  // namespace

struct ChartView::Impl {
  vtkNew<vtkContextView> view;
  vtkNew<vtkChartXY> chart;
  ChartSpec spec;
  AxisRange left, right;
  bool uses_right = false;
  int font_points = 12;
  bool legend_drawn = true;
  /// Tables must outlive their plots' use; the plots hold references, this keeps them alive too.
  std::vector<vtkSmartPointer<vtkTable>> tables;

  Impl() {
    view->GetScene()->AddItem(chart);
    view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
    // Clicking seeks (the widget handles it), so the chart's own mouse actions are off and
    // the axes stay where set_chart puts them. Hover tooltips remain.
    for (int action : {vtkChart::PAN, vtkChart::ZOOM, vtkChart::ZOOM_AXIS, vtkChart::SELECT,
                       vtkChart::SELECT_POLYGON, vtkChart::CLICK_AND_DRAG})
      chart->SetActionToButton(action, vtkContextMouseEvent::NO_BUTTON);
    chart->SetZoomWithMouseWheel(false);
    chart->SetShowLegend(true);
    // Inside the plot, top right, on a pale box: short entries ("before", "after") cost a
    // corner of the plot, not a column beside it (ChartSpec::legend_beside asks for the column).
    chart->GetLegend()->SetInline(true);
    chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
    chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
    chart->GetLegend()->GetBrush()->SetColor(255, 255, 255, 200);
    chart->GetLegend()->GetPen()->SetColor(190, 190, 190, 255);
    // Which axes show is decided per chart (a right axis in other units has no plots).
    chart->SetAutoAxes(false);
    apply_fonts();
  }

  void apply_fonts() {
    apply_font(chart->GetTitleProperties(), font_points + 1, 0.1, 0.1, 0.1, true);
    for (int a : {vtkAxis::LEFT, vtkAxis::BOTTOM, vtkAxis::RIGHT}) {
      apply_font(chart->GetAxis(a)->GetTitleProperties(), font_points, 0.1, 0.1, 0.1);
      apply_font(chart->GetAxis(a)->GetLabelProperties(), font_points - 2, 0.2, 0.2, 0.2);
    }
    apply_font(chart->GetLegend()->GetLabelProperties(), font_points - 2, 0.1, 0.1, 0.1);
    chart->GetLegend()->SetLabelSize(font_points - 2);
  }

  /// Labelled ticks of our own on every numeric axis: a log axis a label a decade (log_ticks),
  /// placed at the exponents it works in; a linear one on 1-2-5 steps with at least two labels
  /// (linear_ticks: VTK's own left a short plot's axis with a single label).
  static void set_ticks(vtkAxis* axis, const AxisRange& range, bool log, std::size_t most) {
    const std::vector<double> ticks = log ? log_ticks(range) : linear_ticks(range, most);
    if (ticks.empty()) {
      axis->SetCustomTickPositions(nullptr, nullptr);
      return;
    }
    vtkNew<vtkDoubleArray> positions;
    vtkNew<vtkStringArray> labels;
    for (double t : ticks) {
      positions->InsertNextValue(log ? std::log10(t) : t);
      labels->InsertNextValue(tick_label(t));
    }
    axis->SetCustomTickPositions(positions, labels);
  }

  void rebuild() {
    chart->ClearPlots();
    tables.clear();
    chart->SetTitle(spec.title);
    vtkAxis* bottom = chart->GetAxis(vtkAxis::BOTTOM);
    vtkAxis* left_axis = chart->GetAxis(vtkAxis::LEFT);
    vtkAxis* right_axis = chart->GetAxis(vtkAxis::RIGHT);
    bottom->SetTitle(spec.x_title);
    left_axis->SetTitle(spec.y_title);
    right_axis->SetTitle(spec.y2_title);

    uses_right = false;
    for (const LineSpec& line : spec.lines)
      uses_right = uses_right || line.right_axis;
    left = spec.log_y ? log_y_range(spec) : y_range(spec, false);
    right = y_range(spec, true);
    const bool linked_right = !uses_right && spec.y2_per_y > 0;
    if (linked_right) right = {left.min * spec.y2_per_y, left.max * spec.y2_per_y};
    AxisRange x = x_range(spec);
    const bool bars = !spec.x_labels.empty();
    if (bars) x = {-0.5, static_cast<double>(spec.x_labels.size()) - 0.5};

    bool any_legend = false;
    for (const LineSpec& line : spec.lines) {
      auto table =
          make_table(spec.x_title.empty() ? "x" : spec.x_title, line.label, line.x, line.y);
      tables.push_back(table);
      // Point series are lines with markers, so keyframes before/after read as connected rows.
      const int type = line.kind == LineKind::kBars ? vtkChart::BAR : vtkChart::LINE;
      vtkPlot* plot = chart->AddPlot(type);
      plot->SetInputData(table, 0, 1);
      plot->SetColor(line.colour.r, line.colour.g, line.colour.b);
      plot->SetWidth(static_cast<float>(line.width));
      plot->SetLabel(line.label);
      plot->SetLegendVisibility(!line.label.empty());
      any_legend = any_legend || !line.label.empty();
      if (line.dashed) plot->GetPen()->SetLineType(vtkPen::DASH_LINE);
      if (auto* points = vtkPlotPoints::SafeDownCast(plot)) {
        // Lines carry no markers (hundreds of samples); point series (keyframes) do.
        points->SetMarkerStyle(line.kind == LineKind::kPoints ? vtkPlotPoints::CIRCLE
                                                              : vtkPlotPoints::NONE);
        if (line.kind == LineKind::kPoints) points->SetMarkerSize(bars ? 16.0f : 10.0f);
        // On a categorical axis a point series is one value per category, not a row.
        if (bars && line.kind == LineKind::kPoints) plot->GetPen()->SetLineType(vtkPen::NO_PEN);
      }
      if (line.right_axis) chart->SetPlotCorner(plot, 1);
    }

    for (const MarkerSpec& marker : spec.markers) {
      auto table = make_table("x", marker.label.empty() ? "marker" : marker.label,
                              {marker.x, marker.x}, {left.min, left.max});
      tables.push_back(table);
      vtkPlot* plot = chart->AddPlot(vtkChart::LINE);
      plot->SetInputData(table, 0, 1);
      plot->SetColor(marker.colour.r, marker.colour.g, marker.colour.b);
      plot->SetWidth(1.0f);
      if (marker.dashed) plot->GetPen()->SetLineType(vtkPen::DOT_LINE);
      plot->SetLabel(marker.label);
      plot->SetLegendVisibility(!marker.label.empty());
      any_legend = any_legend || !marker.label.empty();
      plot->SetSelectable(false);
    }
    chart->SetShowLegend(spec.legend && any_legend && legend_drawn);
    chart->GetLegend()->SetInline(!spec.legend_beside);

    for (vtkAxis* axis : {bottom, left_axis, right_axis})
      axis->SetBehavior(vtkAxis::FIXED);
    bottom->SetRange(x.min, x.max);
    left_axis->SetLogScale(spec.log_y);
    right_axis->SetLogScale(spec.log_y && linked_right);
    // Unscaled: in data units whether or not the axis is logarithmic.
    left_axis->SetUnscaledRange(left.min, left.max);
    right_axis->SetUnscaledRange(right.min, right.max);
    bottom->SetVisible(true);
    left_axis->SetVisible(true);
    right_axis->SetVisible(uses_right || linked_right);
    // One grid, the left axis's: a second one at the right axis's own ticks only crowds it.
    right_axis->SetGridVisible(false);
    chart->GetAxis(vtkAxis::TOP)->SetVisible(false);
    if (bars) {
      vtkNew<vtkDoubleArray> positions;
      vtkNew<vtkStringArray> labels;
      for (std::size_t i = 0; i < spec.x_labels.size(); ++i) {
        positions->InsertNextValue(static_cast<double>(i));
        labels->InsertNextValue(spec.x_labels[i]);
      }
      bottom->SetCustomTickPositions(positions, labels);
    } else {
      set_ticks(bottom, x, false, kMaxXLabels);
    }
    set_ticks(left_axis, left, spec.log_y, kMaxYLabels);
    set_ticks(right_axis, right, spec.log_y && linked_right, kMaxYLabels);
    chart->Update();
  }
};

ChartView::ChartView() : impl_(std::make_unique<Impl>()) {}
ChartView::~ChartView() = default;

void ChartView::set_render_window(vtkRenderWindow* window, vtkRenderWindowInteractor* interactor) {
  impl_->view->SetRenderWindow(window);
  if (interactor) impl_->view->SetInteractor(interactor);
}

void ChartView::set_chart(const ChartSpec& spec) {
  impl_->spec = spec;
  impl_->rebuild();
}

const ChartSpec& ChartView::chart() const {
  return impl_->spec;
}

ChartView::PlotArea ChartView::plot_area() const {
  vtkAxis* bottom = impl_->chart->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* left = impl_->chart->GetAxis(vtkAxis::LEFT);
  PlotArea area;
  area.left = bottom->GetPoint1()[0];
  area.right = bottom->GetPoint2()[0];
  area.bottom = std::min(left->GetPoint1()[1], left->GetPoint2()[1]);
  area.top = std::max(left->GetPoint1()[1], left->GetPoint2()[1]);
  area.x_min = bottom->GetMinimum();
  area.x_max = bottom->GetMaximum();
  return area;
}

std::optional<double> ChartView::x_at_pixel(int x, int y) const {
  const PlotArea a = plot_area();
  if (!(a.right > a.left) || x < a.left || x > a.right || y < a.bottom || y > a.top)
    return std::nullopt;
  const double u = (x - a.left) / static_cast<double>(a.right - a.left);
  return a.x_min + u * (a.x_max - a.x_min);
}

void ChartView::set_legend_drawn(bool drawn) {
  impl_->legend_drawn = drawn;
  impl_->rebuild();
}

bool ChartView::legend_drawn() const {
  return impl_->legend_drawn;
}

void ChartView::set_font_size(int points) {
  impl_->font_points = points;
  impl_->apply_fonts();
}

namespace {

/// The chart rendered offscreen, as an RGB image that outlives the window.
vtkSmartPointer<vtkImageData> render_chart(const ChartSpec& spec, int width, int height,
                                           int font_points) {
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  ChartView view;
  view.set_font_size(font_points);
  view.set_render_window(window, nullptr);
  view.set_chart(spec);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

void write_png(vtkImageData* image, const std::string& path) {
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
  if (writer->GetErrorCode() != 0 || !std::filesystem::exists(path))
    throw std::runtime_error(path + ": cannot write the figure");
}

}  // namespace

void write_chart_png(const ChartSpec& spec, const std::string& path, int width, int height,
                     int font_points) {
  write_png(render_chart(spec, width, height, font_points), path);
}

void write_chart_grid_png(const std::vector<ChartSpec>& charts, int columns,
                          const std::string& path, int panel_width, int panel_height,
                          int font_points) {
  if (charts.empty()) throw std::runtime_error(path + ": no charts to write");
  columns = std::max(1, columns);
  const std::size_t per_row = static_cast<std::size_t>(columns);
  const std::size_t rows = (charts.size() + per_row - 1) / per_row;
  const int total_width = panel_width * columns;
  const int total_height = panel_height * static_cast<int>(rows);
  vtkNew<vtkImageData> figure;
  figure->SetDimensions(total_width, total_height, 1);
  figure->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(figure->GetScalarPointer());
  std::fill(out, out + static_cast<std::size_t>(total_width) * total_height * 3, 255);
  for (std::size_t i = 0; i < charts.size(); ++i) {
    const vtkSmartPointer<vtkImageData> panel =
        render_chart(charts[i], panel_width, panel_height, font_points);
    int dims[3];
    panel->GetDimensions(dims);
    const int components = panel->GetNumberOfScalarComponents();
    if (panel->GetScalarType() != VTK_UNSIGNED_CHAR || components < 3 || dims[0] != panel_width ||
        dims[1] != panel_height)
      throw std::runtime_error(path + ": unexpected chart image format");
    const auto* in = static_cast<const unsigned char*>(panel->GetScalarPointer());
    // VTK images grow upwards: the first row of panels sits at the top of the figure.
    const int x0 = static_cast<int>(i % per_row) * panel_width;
    const int y0 = (static_cast<int>(rows - 1 - i / per_row)) * panel_height;
    for (int y = 0; y < panel_height; ++y)
      for (int x = 0; x < panel_width; ++x) {
        const unsigned char* src =
            in + (static_cast<std::size_t>(y) * panel_width + x) * components;
        unsigned char* dst = out + (static_cast<std::size_t>(y0 + y) * total_width + (x0 + x)) * 3;
        dst[0] = src[0];
        dst[1] = src[1];
        dst[2] = src[2];
      }
  }
  write_png(figure, path);
}

}  // namespace saltus::gui
