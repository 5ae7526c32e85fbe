#include "scene/environment_layer.h"

#include <vtkCellArray.h>
#include <vtkCubeSource.h>
#include <vtkPlaneSource.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include <cmath>
#include <utility>

#include "scene/vtk_util.h"

namespace saltus::gui::scene {

namespace {

// The apparatus's size comes from the library (evaluation/apparatus.h): the clearances are
// measured against the same bed, frame and platform.
constexpr double kWaterSize = 24.0;  ///< m, side of the water (or floor) drawn
constexpr int kGridCells = 24;       ///< 1 m squares on the floor or the water

const Rgb kFrameColour{0.16, 0.33, 0.72};
const Rgb kBedColour{0.08, 0.08, 0.10};
const Rgb kConcreteColour{0.70, 0.70, 0.68};
const Rgb kPlatformTopColour{0.62, 0.50, 0.40};  ///< the non-slip surface
const Rgb kWaterColour{0.12, 0.42, 0.64};
const Rgb kGridColour{0.55, 0.58, 0.65};
/// The grid's lines as if 55 % opaque over what is behind them: the view's background below the
/// trampoline (the middle of its gradient), or the water.
constexpr double kGridOpacity = 0.55;
const Rgb kBehindFloorGrid{0.18, 0.21, 0.28};

vtkSmartPointer<vtkActor> box(const Eigen::Vector3d& centre, const Eigen::Vector3d& size,
                              const Rgb& colour, const Eigen::Affine3d& pose) {
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(centre.x(), centre.y(), centre.z());
  cube->SetXLength(size.x());
  cube->SetYLength(size.y());
  cube->SetZLength(size.z());
  auto actor = actor_for(mapper_for(cube->GetOutputPort()));
  set_colour(actor, colour);
  set_matrix(actor, pose);
  // Some light of its own: the camera's light grazes a platform seen from the side, which would
  // otherwise turn it into a black band.
  actor->GetProperty()->SetAmbient(0.35);
  actor->GetProperty()->SetDiffuse(0.7);
  actor->PickableOff();
  return actor;
}

vtkSmartPointer<vtkActor> plane(const Eigen::Vector3d& centre, double size, const Rgb& colour) {
  vtkNew<vtkPlaneSource> source;
  const double h = 0.5 * size;
  source->SetOrigin(centre.x() - h, centre.y(), centre.z() - h);
  source->SetPoint1(centre.x() + h, centre.y(), centre.z() - h);
  source->SetPoint2(centre.x() - h, centre.y(), centre.z() + h);
  auto actor = actor_for(mapper_for(source->GetOutputPort()));
  set_colour(actor, colour);
  actor->PickableOff();
  return actor;
}

/// A square grid of `cells` × `cells` on the horizontal plane through `centre`: one line per grid
/// line (not a wireframe of quads, which draws every inner edge twice), opaque and unlit in
/// `colour`, the grid's colour already mixed with what lies behind it. A translucent grid would
/// make VTK add its order-independent translucency passes over the whole view, which with
/// software OpenGL cost a third of each frame during playback (docs/performance.md).
vtkSmartPointer<vtkActor> grid(const Eigen::Vector3d& centre, double size, int cells,
                               const Rgb& colour) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  const double h = 0.5 * size;
  for (int i = 0; i <= cells; ++i) {
    const double u = -h + size * i / cells;
    for (const auto& [a, b] : {std::pair{Eigen::Vector3d(u, 0, -h), Eigen::Vector3d(u, 0, h)},
                               std::pair{Eigen::Vector3d(-h, 0, u), Eigen::Vector3d(h, 0, u)}}) {
      const Eigen::Vector3d from = centre + a, to = centre + b;
      const vtkIdType ends[2] = {points->InsertNextPoint(from.data()),
                                 points->InsertNextPoint(to.data())};
      lines->InsertNextCell(2, ends);
    }
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetLines(lines);
  auto actor = actor_for(mapper_for(data));
  set_colour(actor, colour);
  actor->GetProperty()->SetLighting(false);
  actor->PickableOff();
  return actor;
}

/// `front` over `behind` at `opacity`: the colour a translucent line would have had.
Rgb over(const Rgb& front, const Rgb& behind, double opacity) {
  return {opacity * front.r + (1 - opacity) * behind.r,
          opacity * front.g + (1 - opacity) * behind.g,
          opacity * front.b + (1 - opacity) * behind.b};
}

}  // namespace

EnvironmentLayer::EnvironmentLayer(vtkRenderer* renderer) : renderer_(renderer) {}

void EnvironmentLayer::clear() {
  for (auto* list : {&apparatus_, &grid_})
    for (auto& a : *list) {
      renderer_->RemoveActor(a);
      for (vtkRenderer* r : also_in_)
        r->RemoveActor(a);
    }
  apparatus_.clear();
  grid_.clear();
}

void EnvironmentLayer::show_in(vtkRenderer* other) {
  also_in_.push_back(other);
  for (auto* list : {&apparatus_, &grid_})
    for (auto& a : *list)
      other->AddActor(a);
}

void EnvironmentLayer::add(const vtkSmartPointer<vtkActor>& actor, bool apparatus) {
  (apparatus ? apparatus_ : grid_).push_back(actor);
  renderer_->AddActor(actor);
  for (vtkRenderer* r : also_in_)
    r->AddActor(actor);
}

void EnvironmentLayer::build(const Apparatus& a, const Eigen::AlignedBox3d& flight) {
  clear();
  const Eigen::Affine3d pose = world_from_apparatus(a);
  frame_ = flight;
  if (a.kind == ApparatusKind::kTrampoline) {
    // Frame with pads (blue) and the bed (dark webbing), the bed's top where the feet leave.
    add(box({0, kFrameTop - 0.5 * kFrameThickness, 0}, {kFrameWidth, kFrameThickness, kFrameLength},
            kFrameColour, pose),
        true);
    add(box({0, -0.5 * kBedThickness, 0}, {kBedWidth, kBedThickness, kBedLength}, kBedColour, pose),
        true);
    add(grid(a.takeoff_point - Eigen::Vector3d(0, 0.08, 0), kWaterSize / 2, kGridCells / 2,
             over(kGridColour, kBehindFloorGrid, kGridOpacity)),
        false);
    for (double x : {-kFrameWidth / 2, kFrameWidth / 2})
      for (double z : {-kFrameLength / 2, kFrameLength / 2})
        frame_.extend(pose * Eigen::Vector3d(x, 0, z));
  } else {
    // The slab: its top where the feet leave, its front edge just ahead of the take-off point,
    // reaching back away from the direction of travel; a column under its back down to the
    // water; the water where the flight ends.
    const double drop = a.takeoff_height - a.landing_height;
    const double back = kPlatformEdgeAhead - kPlatformLength;
    add(box({0, -0.5 * kPlatformThickness, 0.5 * (kPlatformEdgeAhead + back)},
            {kPlatformWidth, kPlatformThickness, kPlatformLength}, kConcreteColour, pose),
        true);
    add(box({0, 0.005, 0.5 * (kPlatformEdgeAhead + back)},
            {kPlatformWidth - 0.1, 0.01, kPlatformLength - 0.1}, kPlatformTopColour, pose),
        true);
    add(box({0, -0.5 * drop, back + kPillarSide}, {kPillarSide, drop, kPillarSide}, kConcreteColour,
            pose),
        true);
    const Eigen::Vector3d water_centre(a.takeoff_point.x(), a.landing_height, a.takeoff_point.z());
    auto water = plane(water_centre, kWaterSize, kWaterColour);
    water->GetProperty()->SetAmbient(0.35);
    water->GetProperty()->SetSpecular(0.4);
    water->GetProperty()->SetSpecularPower(40.0);
    add(water, true);
    add(grid(water_centre + Eigen::Vector3d(0, 0.003, 0), kWaterSize, kGridCells,
             over(lighter(kWaterColour, 0.35), kWaterColour, kGridOpacity)),
        false);
    for (double x : {-kPlatformWidth / 2, kPlatformWidth / 2})
      for (double z : {back * 0.4, kPlatformEdgeAhead})
        frame_.extend(pose * Eigen::Vector3d(x, 0, z));
    frame_.extend(Eigen::Vector3d(flight.center().x(), a.landing_height, flight.center().z()));
  }
}

void EnvironmentLayer::set_visible(bool apparatus, bool grid) {
  for (auto& actor : apparatus_)
    actor->SetVisibility(apparatus);
  for (auto& actor : grid_)
    actor->SetVisibility(grid);
}

}  // namespace saltus::gui::scene
