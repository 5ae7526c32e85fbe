#include "scene/standing_figures.h"

#include <vtkBillboardTextActor3D.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>

#include <algorithm>

#include "saltus/body/mass_properties.h"
#include "scene/body_layer.h"
#include "scene/vtk_text.h"
#include "scene/vtk_util.h"

namespace saltus::gui {

namespace {

/// Each figure's place is at least this many tallest heights wide, so that its label (about
/// fifteen characters a line) fits over it; a pose wider than that (lying) gets its own width.
constexpr double kPlacePerHeight = 0.7;
/// Room between two poses' extents, tallest heights.
constexpr double kGapPerHeight = 0.12;
/// Room above the tallest head for the labels, share of its height.
constexpr double kLabelRoom = 0.3;
/// The camera: from the front, a little from the right and above, so the face and the body's
/// depth show. A parallel projection: heights compare as they are, whichever figure is nearer.
const Eigen::Vector3d kCameraDirection = Eigen::Vector3d(0.35, 0.1, 1.0).normalized();
constexpr double kMargin = 1.04;  ///< around the figures and labels
const Rgb kGrey{0.66, 0.68, 0.70};

}  // namespace

struct StandingFigures::Impl {
  vtkNew<vtkRenderer> renderer;
  std::vector<std::unique_ptr<scene::BodyLayer>> bodies;
  std::vector<vtkSmartPointer<vtkBillboardTextActor3D>> labels;
  vtkSmartPointer<vtkActor> floor;
  vtkNew<vtkCallbackCommand> on_render;
  std::vector<double> heights;
  /// What the camera frames: x from, x to, the bottom (below the floor at y = 0: the feet in
  /// front of it show, seen from a little above) and the top (m).
  double x_min = -0.5, x_max = 0.5, bottom = -0.1, top = 2.0;

  Impl() {
    renderer->GradientBackgroundOn();
    renderer->SetBackground(0.10, 0.12, 0.16);
    renderer->SetBackground2(0.30, 0.36, 0.46);
    renderer->SetUseFXAA(true);  // a still picture: worth the anti-aliasing pass
    // Before each render: the framing for the window's shape.
    on_render->SetClientData(this);
    on_render->SetCallback(
        [](vtkObject*, unsigned long, void* self, void*) { static_cast<Impl*>(self)->frame(); });
    renderer->AddObserver(vtkCommand::StartEvent, on_render);
  }

  /// The body layers stay (each keeps actors in the renderer) and are built again.
  void clear() {
    for (auto& body : bodies)
      body->clear();
    for (auto& label : labels)
      renderer->RemoveActor(label);
    labels.clear();
    if (floor) renderer->RemoveActor(floor);
    floor = nullptr;
    heights.clear();
  }

  /// The camera for the window's aspect: every figure and label in view, as large as fits.
  void frame() {
    const int* size = renderer->GetSize();
    const double aspect = size[0] > 0 && size[1] > 0 ? double(size[0]) / size[1] : 1.0;
    const double half_height = 0.5 * (top - bottom);
    const double half_width = 0.5 * (x_max - x_min);
    const Eigen::Vector3d centre(0.5 * (x_min + x_max), 0.5 * (top + bottom), 0.0);
    const Eigen::Vector3d position = centre + 10.0 * top * kCameraDirection;
    vtkCamera* c = renderer->GetActiveCamera();
    c->ParallelProjectionOn();
    c->SetParallelScale(kMargin * std::max(half_height, half_width / aspect));
    c->SetFocalPoint(centre.x(), centre.y(), centre.z());
    c->SetPosition(position.x(), position.y(), position.z());
    c->SetViewUp(0, 1, 0);
    renderer->ResetCameraClippingRange();
  }
};

StandingFigures::StandingFigures() : impl_(std::make_unique<Impl>()) {}

StandingFigures::~StandingFigures() = default;

void StandingFigures::attach(vtkRenderWindow* window) {
  window->AddRenderer(impl_->renderer);
}

void StandingFigures::set_figures(const std::vector<Figure>& figures) {
  Impl& m = *impl_;
  m.clear();
  double tallest = 0.0;
  std::vector<StandingBody> standing;
  for (const Figure& f : figures) {
    standing.push_back(standing_body(f.model));
    tallest = std::max(tallest, standing.back().height());
  }
  if (!(tallest > 0.0)) tallest = 1.7;
  // Each figure's horizontal extent about its centre: standing, a quarter of its height either
  // side; posed, its joints' (and a margin for the shapes); at least its label's place.
  std::vector<std::pair<double, double>> extents;
  for (std::size_t i = 0; i < figures.size(); ++i) {
    double lo = -0.25 * tallest, hi = 0.25 * tallest;
    if (const auto& pose = figures[i].pose) {
      double mean = 0.0, min_x = std::numeric_limits<double>::infinity(), max_x = -min_x;
      for (const Eigen::Vector3d& p : pose->segment_position) {
        mean += p.x();
        min_x = std::min(min_x, p.x());
        max_x = std::max(max_x, p.x());
      }
      mean /= static_cast<double>(std::max<std::size_t>(1, pose->segment_position.size()));
      lo = min_x - mean - 0.2 * tallest;
      hi = max_x - mean + 0.2 * tallest;
    }
    extents.emplace_back(std::min(lo, -0.5 * kPlacePerHeight * tallest),
                         std::max(hi, 0.5 * kPlacePerHeight * tallest));
  }
  std::vector<double> centres;
  double cursor = 0.0;
  for (const auto& [lo, hi] : extents) {
    if (!centres.empty()) cursor += kGapPerHeight * tallest;
    centres.push_back(cursor - lo);
    cursor = centres.back() + hi;
  }
  for (std::size_t i = 0; i < figures.size(); ++i) {
    const Figure& f = figures[i];
    const StandingBody& s = standing[i];
    // The standing pose: every joint at identity, the soles on the floor, side by side. A
    // flight's pose: centred on its place, then onto the floor by its lowest point.
    const Eigen::Vector3d offset(centres[i], -s.lowest_y, 0.0);
    SampleRecord pose;
    if (f.pose) {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (const Eigen::Vector3d& p : f.pose->segment_position)
        centre += p;
      centre /= static_cast<double>(std::max<std::size_t>(1, f.pose->segment_position.size()));
      pose.segment_rotation = f.pose->segment_rotation;
      for (const Eigen::Vector3d& p : f.pose->segment_position)
        pose.segment_position.push_back(p +
                                        Eigen::Vector3d(offset.x() - centre.x(), 0.0, -centre.z()));
    } else {
      for (const Eigen::Vector3d& origin : standing_origins(f.model)) {
        pose.segment_position.push_back(origin + offset);
        pose.segment_rotation.push_back(Eigen::Quaterniond::Identity());
      }
    }
    if (m.bodies.size() <= i) m.bodies.push_back(std::make_unique<scene::BodyLayer>(m.renderer));
    scene::BodyLayer& body = *m.bodies[i];
    body.build(f.model, f.grey ? std::optional<Rgb>(kGrey) : std::nullopt);
    body.pose(pose);
    if (f.pose) {
      // Onto the floor by its lowest point, shapes included (a head that lands first).
      const double lowest = body.lowest_y();
      for (Eigen::Vector3d& p : pose.segment_position)
        p.y() -= lowest;
      body.pose(pose);
    }
    m.heights.push_back(s.height());

    auto label = vtkSmartPointer<vtkBillboardTextActor3D>::New();
    label->SetInput(f.label.c_str());
    vtkTextProperty* p = label->GetTextProperty();
    apply_font(p, 15, 0.94, 0.95, 0.92, true);
    p->SetJustificationToCentered();
    p->SetVerticalJustificationToBottom();
    label->SetPosition(offset.x(), s.height() + 0.06 * tallest, 0.0);
    label->PickableOff();
    m.renderer->AddActor(label);
    m.labels.push_back(label);
  }
  const double reach = 0.25 * tallest;
  m.x_min = 0.0;
  m.x_max = figures.empty() ? 0.0 : cursor;
  m.top = (1.0 + kLabelRoom) * tallest;
  m.bottom = -0.08 * tallest;
  // A floor under them, so that heights compare against one ground.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(m.x_min - reach, 0.0, -reach);
  plane->SetPoint1(m.x_max + reach, 0.0, -reach);
  plane->SetPoint2(m.x_min - reach, 0.0, reach);
  m.floor = scene::actor_for(scene::mapper_for(plane->GetOutputPort()));
  scene::set_colour(m.floor, Rgb{0.22, 0.25, 0.30});
  m.floor->GetProperty()->SetLighting(false);
  m.floor->PickableOff();
  m.renderer->AddActor(m.floor);
}

std::vector<double> StandingFigures::drawn_heights() const {
  return impl_->heights;
}

}  // namespace saltus::gui
