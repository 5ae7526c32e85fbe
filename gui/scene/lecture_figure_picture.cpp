#include "scene/lecture_figure_picture.h"

#include <vtkBillboardTextActor3D.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include "scene/body_layer.h"
#include "scene/vtk_text.h"
#include "scene/vtk_util.h"

namespace saltus::gui {

namespace {

constexpr int kTitlePixels = 64;     ///< above the poses
constexpr int kCaptionPixels = 150;  ///< below them: four lines of caption
constexpr int kBarPixels = 220;      ///< right of them: the colour bar and its title
constexpr double kMargin = 1.06;     ///< around the bodies
constexpr double kTimeRow = 0.22;    ///< the times' row below the lowest body point, m
const Rgb kPathGrey{0.45, 0.47, 0.50};

}  // namespace

void write_lecture_figure_png(const LectureFigure& figure, const std::string& path, int width,
                              int height) {
  const Stroboscope& s = figure.strobe;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->SetMultiSamples(0);

  // The words and the colour bar on the whole picture; the bodies in a viewport between them.
  vtkNew<vtkRenderer> page;
  page->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkRenderer> bodies;
  bodies->SetBackground(1.0, 1.0, 1.0);
  bodies->SetUseFXAA(true);
  const double left = 0.0, right = 1.0 - double(kBarPixels) / width;
  const double bottom = double(kCaptionPixels) / height, top = 1.0 - double(kTitlePixels) / height;
  bodies->SetViewport(left, bottom, right, top);
  window->AddRenderer(page);
  window->AddRenderer(bodies);

  const double span = figure.spin_high - figure.spin_low;
  std::vector<std::unique_ptr<scene::BodyLayer>> layers;
  for (const StroboscopePose& pose : s.poses) {
    layers.push_back(std::make_unique<scene::BodyLayer>(bodies));
    const double fraction = span > 0.0 ? (pose.spin_rev_per_s - figure.spin_low) / span : 0.5;
    layers.back()->build(figure.model, spin_colour(fraction));
    layers.back()->pose(pose.sample);
  }
  vtkSmartPointer<vtkActor> path_line =
      scene::actor_for(scene::mapper_for(scene::polyline(s.com_path)));
  scene::set_colour(path_line, kPathGrey);
  path_line->GetProperty()->SetLineWidth(3.0F);
  path_line->GetProperty()->SetLighting(false);
  bodies->AddActor(path_line);

  // The bodies' extent across the picture (along `right`) and up, from their bounding box.
  double b[6];
  bodies->ComputeVisiblePropBounds(b);
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  double x_min = std::numeric_limits<double>::max(), x_max = -x_min;
  double y_min = x_min, y_max = -x_min;
  double depth = 0.0;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner(b[i & 1 ? 1 : 0], b[i & 2 ? 3 : 2], b[i & 4 ? 5 : 4]);
    x_min = std::min(x_min, corner.dot(s.right));
    x_max = std::max(x_max, corner.dot(s.right));
    y_min = std::min(y_min, corner.dot(up));
    y_max = std::max(y_max, corner.dot(up));
    depth += corner.dot(s.view_direction) / 8.0;
  }
  // Each pose's time in a row under the lowest point, below its centre of mass.
  const double row = y_min - kTimeRow;
  for (const StroboscopePose& pose : s.poses) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", pose.time);
    vtkNew<vtkBillboardTextActor3D> label;
    label->SetInput(text);
    apply_font(label->GetTextProperty(), 17, 0.15, 0.15, 0.18);
    label->GetTextProperty()->SetJustificationToCentered();
    label->GetTextProperty()->SetVerticalJustificationToCentered();
    const Eigen::Vector3d at =
        pose.sample.com.dot(s.right) * s.right + row * up + depth * s.view_direction;
    label->SetPosition(at.x(), at.y(), at.z());
    bodies->AddActor(label);
  }
  y_min = row - 0.12;

  const double aspect = (right - left) * width / ((top - bottom) * height);
  const Eigen::Vector3d centre =
      0.5 * (x_min + x_max) * s.right + 0.5 * (y_min + y_max) * up + depth * s.view_direction;
  const double reach = std::max(x_max - x_min, y_max - y_min);
  const Eigen::Vector3d eye = centre - 10.0 * reach * s.view_direction;
  vtkCamera* camera = bodies->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetParallelScale(kMargin *
                           std::max(0.5 * (y_max - y_min), 0.5 * (x_max - x_min) / aspect));
  camera->SetFocalPoint(centre.x(), centre.y(), centre.z());
  camera->SetPosition(eye.x(), eye.y(), eye.z());
  camera->SetViewUp(0.0, 1.0, 0.0);
  bodies->ResetCameraClippingRange();

  vtkNew<vtkTextActor> title;
  title->SetInput(figure.title.c_str());
  apply_font(title->GetTextProperty(), 26, 0.08, 0.08, 0.10, true);
  title->GetTextProperty()->SetVerticalJustificationToTop();
  title->SetDisplayPosition(24, height - 18);
  page->AddActor2D(title);

  vtkNew<vtkTextActor> caption;
  caption->SetInput(figure.caption.c_str());
  apply_font(caption->GetTextProperty(), 17, 0.12, 0.12, 0.14);
  caption->GetTextProperty()->SetVerticalJustificationToTop();
  caption->GetTextProperty()->SetLineSpacing(1.15);
  caption->SetDisplayPosition(24, kCaptionPixels - 12);
  page->AddActor2D(caption);

  vtkNew<vtkLookupTable> colours;
  constexpr int kColours = 256;
  colours->SetNumberOfTableValues(kColours);
  colours->SetRange(figure.spin_low, figure.spin_high);
  for (int i = 0; i < kColours; ++i) {
    const Rgb c = spin_colour(double(i) / (kColours - 1));
    colours->SetTableValue(i, c.r, c.g, c.b, 1.0);
  }
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(colours);
  bar->SetTitle(figure.colour_bar_title.c_str());
  // A label every step of the range (whole steps: core/lecture_figure.h).
  bar->SetNumberOfLabels(static_cast<int>(std::lround(span / figure.spin_step)) + 1);
  bar->SetLabelFormat("%.2f");
  bar->UnconstrainedFontSizeOn();
  bar->SetBarRatio(0.3);
  bar->SetTextPositionToSucceedScalarBar();
  apply_font(bar->GetTitleTextProperty(), 18, 0.08, 0.08, 0.10, true);
  apply_font(bar->GetLabelTextProperty(), 17, 0.08, 0.08, 0.10);
  bar->GetTitleTextProperty()->SetJustificationToLeft();
  bar->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
  bar->GetPositionCoordinate()->SetValue(width - kBarPixels + 10, kCaptionPixels + 10);
  bar->GetPosition2Coordinate()->SetCoordinateSystemToDisplay();
  bar->GetPosition2Coordinate()->SetValue(kBarPixels - 20,
                                          height - kTitlePixels - kCaptionPixels - 20);
  page->AddActor2D(bar);

  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0 || !std::filesystem::exists(path))
    throw std::runtime_error(path + ": cannot write the figure");
}

}  // namespace saltus::gui
