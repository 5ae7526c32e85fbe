#include "scene/body_layer.h"

#include <vtkAppendPolyData.h>
#include <vtkCapsuleSource.h>
#include <vtkDataArray.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "saltus/body/drawing_colours.h"
#include "scene/vtk_util.h"

namespace saltus::gui::scene {

namespace {

/// Pale cyan: no other part of the scene has it (sides blue and orange, arrows green to red).
const Rgb kOutlineColour{0.45, 0.95, 1.0};
/// The picked segment's rim: this share of its thickness, at least kOutlineMinWidth.
constexpr double kOutlineWidthFactor = 0.3;
constexpr double kOutlineMinWidth = 0.015;  ///< m
/// Brightness added to the picked segment (its ambient light).
constexpr double kHighlightAmbient = 0.45;
constexpr double kGhostRadiusFactor = 0.35;  ///< keyframe poses drawn as thin figures
constexpr int kRoundResolution = 18;         ///< around a capsule or an ellipsoid
constexpr int kLengthResolution = 10;        ///< along them

/// The library's drawing colours (body/drawing_colours.h), which the flight page draws too.
Rgb rgb(const DrawingColour& c) {
  return Rgb{c.r, c.g, c.b};
}

vtkSmartPointer<vtkPolyData> placed(vtkAlgorithmOutput* source, vtkTransform* transform) {
  vtkNew<vtkTransformPolyDataFilter> filter;
  filter->SetTransform(transform);
  filter->SetInputConnection(source);
  filter->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(filter->GetOutput());
  return out;
}

vtkSmartPointer<vtkPolyData> placed_data(vtkPolyData* data, const Eigen::Affine3d& t) {
  vtkNew<vtkMatrix4x4> m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      m->SetElement(r, c, t.matrix()(r, c));
  vtkNew<vtkTransform> transform;
  transform->SetMatrix(m);
  vtkNew<vtkTransformPolyDataFilter> filter;
  filter->SetTransform(transform);
  filter->SetInputData(data);
  filter->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(filter->GetOutput());
  return out;
}

/// A capsule along y, centred at `centre`, cylinder `length` (sign ignored), `radius`.
vtkSmartPointer<vtkPolyData> capsule(const Eigen::Vector3d& centre, double length, double radius,
                                     int resolution) {
  vtkNew<vtkCapsuleSource> source;
  source->SetRadius(radius);
  source->SetCylinderLength(std::abs(length));
  source->SetThetaResolution(resolution);
  source->SetPhiResolution(std::max(6, resolution / 2));
  vtkNew<vtkTransform> t;
  t->Translate(centre.x(), centre.y(), centre.z());
  return placed(source->GetOutputPort(), t);
}

vtkSmartPointer<vtkPolyData> ellipsoid(const Eigen::Vector3d& centre,
                                       const Eigen::Vector3d& radii) {
  vtkNew<vtkSphereSource> source;
  source->SetRadius(1.0);
  source->SetThetaResolution(kRoundResolution);
  source->SetPhiResolution(kLengthResolution);
  vtkNew<vtkTransform> t;
  t->Translate(centre.x(), centre.y(), centre.z());
  t->Scale(radii.x(), radii.y(), radii.z());
  return placed(source->GetOutputPort(), t);
}

void paint(vtkPolyData* data, const Rgb& c) {
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("colour");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(data->GetNumberOfPoints());
  const unsigned char rgb[3] = {static_cast<unsigned char>(std::lround(255 * c.r)),
                                static_cast<unsigned char>(std::lround(255 * c.g)),
                                static_cast<unsigned char>(std::lround(255 * c.b))};
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    colours->SetTypedTuple(i, rgb);
  data->GetPointData()->SetScalars(colours);
}

/// The segment's drawing in its own coordinates, coloured per point (all `uniform` if given).
vtkSmartPointer<vtkPolyData> segment_mesh(const Segment& s, const std::optional<Rgb>& uniform) {
  vtkNew<vtkAppendPolyData> all;
  if (s.shape.parts.empty()) {
    auto mesh = capsule(Eigen::Vector3d(0, 0.5 * s.shape.length, 0), s.shape.length,
                        std::max(s.shape.radius, 0.01), kRoundResolution);
    paint(mesh, uniform ? *uniform : rgb(segment_colour(s)));
    all->AddInputData(mesh);
  }
  for (const ShapePart& part : s.shape.parts) {
    auto mesh = part.type == "capsule"
                    ? capsule(part.center, part.length, part.radius, kRoundResolution)
                    : ellipsoid(part.center, part.radii);
    paint(mesh, uniform ? *uniform : rgb(part_colour(s, part)));
    all->AddInputData(mesh);
  }
  all->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(all->GetOutput());
  return out;
}

/// The mesh with every point moved `width` along its normal: a uniformly thicker copy.
vtkSmartPointer<vtkPolyData> inflated(vtkPolyData* mesh, double width) {
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(mesh);
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  if (!normals) return out;
  vtkPoints* points = out->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
    double p[3], n[3];
    points->GetPoint(i, p);
    normals->GetTuple(i, n);
    points->SetPoint(i, p[0] + width * n[0], p[1] + width * n[1], p[2] + width * n[2]);
  }
  return out;
}

/// The thickness of a segment's drawing (its largest radius), for the rim's width.
double thickness(const Segment& s) {
  double r = s.shape.radius;
  for (const ShapePart& p : s.shape.parts)
    r = std::max(r, p.type == "capsule" ? p.radius : p.radii.minCoeff());
  return r;
}

Eigen::Affine3d world_from_segment(const SampleRecord& s, std::size_t i) {
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.translate(s.segment_position[i]);
  t.rotate(s.segment_rotation[i]);
  return t;
}

}  // namespace

BodyLayer::BodyLayer(vtkRenderer* renderer) : renderer_(renderer) {
  picker_->PickFromListOn();
  outline_->GetProperty()->FrontfaceCullingOn();
  outline_->GetProperty()->SetLighting(false);
  set_colour(outline_, kOutlineColour);
  outline_->PickableOff();
  outline_->SetVisibility(false);
  renderer_->AddActor(outline_);
}

void BodyLayer::clear() {
  for (auto& a : segments_) {
    renderer_->RemoveActor(a);
    for (vtkRenderer* r : also_in_)
      r->RemoveActor(a);
  }
  segments_.clear();
  outlines_.clear();
  picker_->InitializePickList();
  if (ghosts_) renderer_->RemoveActor(ghosts_);
  ghosts_ = nullptr;
  outline_->SetVisibility(false);
}

void BodyLayer::show_in(vtkRenderer* other) {
  also_in_.push_back(other);
  for (auto& a : segments_)
    other->AddActor(a);
}

void BodyLayer::build(const BodyModel& model, const std::optional<Rgb>& uniform) {
  clear();
  std::vector<Eigen::Vector3d> origin(model.segments.size(), Eigen::Vector3d::Zero());
  double top = -std::numeric_limits<double>::infinity();
  double bottom = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < model.segments.size(); ++i) {
    const Segment& s = model.segments[i];
    if (s.parent >= 0) origin[i] = origin[static_cast<std::size_t>(s.parent)] + s.joint_position;
    vtkSmartPointer<vtkPolyData> mesh = segment_mesh(s, uniform);
    double b[6];
    mesh->GetBounds(b);
    top = std::max(top, origin[i].y() + b[3]);
    bottom = std::min(bottom, origin[i].y() + b[2]);
    auto mapper = mapper_for(mesh);
    mapper->SetColorModeToDirectScalars();
    mapper->ScalarVisibilityOn();
    auto actor = actor_for(mapper);
    vtkProperty* p = actor->GetProperty();
    // Smooth shading: normals interpolated per pixel, a soft highlight.
    p->SetInterpolationToPhong();
    p->SetDiffuse(0.85);
    p->SetSpecular(0.25);
    p->SetSpecularPower(25.0);
    renderer_->AddActor(actor);
    for (vtkRenderer* r : also_in_)
      r->AddActor(actor);
    if (uniform) {
      p->SetSpecular(0.1);
      actor->PickableOff();
    } else {
      picker_->AddPickList(actor);
    }
    segments_.push_back(actor);
    outlines_.push_back(
        inflated(mesh, std::max(kOutlineWidthFactor * thickness(s), kOutlineMinWidth)));
  }
  if (top > bottom) standing_height_ = top - bottom;
  apply_highlight();
}

void BodyLayer::set_visible(bool visible) {
  for (auto& a : segments_)
    a->SetVisibility(visible);
  outline_->SetVisibility(visible && highlight_ >= 0);
}

void BodyLayer::pose(const SampleRecord& s, const Eigen::Vector3d& offset) {
  const Eigen::Translation3d moved(offset);
  for (std::size_t i = 0; i < segments_.size() && i < s.segment_position.size(); ++i)
    set_matrix(segments_[i], moved * world_from_segment(s, i));
  if (highlight_ >= 0 && static_cast<std::size_t>(highlight_) < s.segment_position.size())
    set_matrix(outline_, moved * world_from_segment(s, static_cast<std::size_t>(highlight_)));
}

void BodyLayer::build_ghosts(const BodyModel& model, const std::vector<SampleRecord>& poses,
                             bool optimised) {
  if (ghosts_) renderer_->RemoveActor(ghosts_);
  // Before: pale blue-grey; after (poses at the optimised times): pale amber.
  const Rgb colour = optimised ? Rgb{0.80, 0.70, 0.52} : Rgb{0.70, 0.76, 0.86};
  // All keyframe poses in one mesh and one actor: they never move, and one draw call instead
  // of one per segment and pose keeps software OpenGL near the frame rate without them.
  vtkNew<vtkAppendPolyData> all;
  for (const SampleRecord& pose : poses) {
    for (std::size_t i = 0; i < model.segments.size() && i < pose.segment_position.size(); ++i) {
      const Segment& seg = model.segments[i];
      // Thin (a third of the radius) so that a pose next to the body does not hide it.
      auto thin = capsule(Eigen::Vector3d(0, 0.5 * seg.shape.length, 0), seg.shape.length,
                          std::max(kGhostRadiusFactor * seg.shape.radius, 0.015), 8);
      all->AddInputData(placed_data(thin, world_from_segment(pose, i)));
    }
  }
  all->Update();
  ghosts_ = actor_for(mapper_for(all->GetOutput()));
  // Flat, unlit silhouettes rather than translucent bodies: VTK's order-independent
  // transparency would cost more than the rest of the frame in software OpenGL (measured: 16
  // against 40 frames per second). Without shading they read as shadows of the lit, coloured
  // body instead of as more bodies.
  set_colour(ghosts_, colour);
  ghosts_->GetProperty()->SetLighting(false);
  ghosts_->PickableOff();
  renderer_->AddActor(ghosts_);
}

void BodyLayer::set_ghosts_visible(bool visible) {
  if (ghosts_) ghosts_->SetVisibility(visible);
}

void BodyLayer::set_highlight(int segment) {
  highlight_ = segment < 0 ? -1 : segment;
  apply_highlight();
}

void BodyLayer::apply_highlight() {
  if (highlight_ >= static_cast<int>(segments_.size())) highlight_ = -1;
  for (std::size_t i = 0; i < segments_.size(); ++i)
    segments_[i]->GetProperty()->SetAmbient(static_cast<int>(i) == highlight_ ? kHighlightAmbient
                                                                              : 0.0);
  if (highlight_ >= 0) {
    outline_->SetMapper(mapper_for(outlines_[static_cast<std::size_t>(highlight_)]));
    outline_->GetMapper()->ScalarVisibilityOff();
  }
  outline_->SetVisibility(highlight_ >= 0);
}

int BodyLayer::segment_at(int x, int y) {
  if (segments_.empty()) return -1;
  if (!picker_->Pick(x, y, 0.0, renderer_)) return -1;
  const vtkActor* actor = picker_->GetActor();
  for (std::size_t i = 0; i < segments_.size(); ++i)
    if (segments_[i] == actor) return static_cast<int>(i);
  return -1;
}

double BodyLayer::lowest_y() const {
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& actor : segments_)
    lowest = std::min(lowest, actor->GetBounds()[2]);
  return lowest;
}

}  // namespace saltus::gui::scene
