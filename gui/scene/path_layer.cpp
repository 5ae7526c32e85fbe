#include "scene/path_layer.h"

#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>

#include "scene/vtk_util.h"

namespace saltus::gui::scene {

namespace {
const Rgb kParabolaColour{0.92, 0.92, 0.95};
const Rgb kTraceColour{1.0, 0.70, 0.20};
const Rgb kComColour{1.0, 0.90, 0.25};
constexpr int kParabolaPoints = 240;
}  // namespace

PathLayer::PathLayer(vtkRenderer* renderer, vtkRenderer* overlay) : renderer_(renderer) {
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.06);
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  com_ = actor_for(mapper_for(sphere->GetOutputPort()));
  set_colour(com_, kComColour);
  com_->GetProperty()->SetAmbient(0.4);
  com_->PickableOff();
  overlay->AddActor(com_);
}

void PathLayer::clear() {
  for (vtkSmartPointer<vtkActor>* a : {&parabola_, &trace_}) {
    if (!*a) continue;
    renderer_->RemoveActor(*a);
    for (vtkRenderer* r : also_in_)
      r->RemoveActor(*a);
    *a = nullptr;
  }
}

void PathLayer::show_in(vtkRenderer* other) {
  also_in_.push_back(other);
  for (vtkSmartPointer<vtkActor>* a : {&parabola_, &trace_})
    if (*a) other->AddActor(*a);
  other->AddActor(com_);
}

void PathLayer::build(const Document& d, Stage stage) {
  clear();
  const ParabolaSamples p = d.parabola(kParabolaPoints);
  parabola_ = actor_for(mapper_for(polyline(p.points)));
  set_colour(parabola_, kParabolaColour);
  parabola_->GetProperty()->SetLineWidth(2.0f);
  parabola_->GetProperty()->SetLighting(false);
  std::vector<Eigen::Vector3d> com;
  for (const SampleRecord& s : d.plot_samples(stage))
    com.push_back(s.com);
  trace_ = actor_for(mapper_for(polyline(com)));
  set_colour(trace_, kTraceColour);
  trace_->GetProperty()->SetLineWidth(3.5f);
  trace_->GetProperty()->SetLighting(false);
  for (vtkActor* a : {parabola_.Get(), trace_.Get()}) {
    a->PickableOff();
    renderer_->AddActor(a);
    for (vtkRenderer* r : also_in_)
      r->AddActor(a);
  }
  bounds_.setEmpty();
  for (const Eigen::Vector3d& q : p.points)
    bounds_.extend(q);
  for (const Eigen::Vector3d& q : com)
    bounds_.extend(q);
}

void PathLayer::set_visible(bool parabola, bool trace, bool com) {
  if (parabola_) parabola_->SetVisibility(parabola);
  if (trace_) trace_->SetVisibility(trace);
  com_->SetVisibility(com);
}

void PathLayer::set_com(const Eigen::Vector3d& com) {
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.translate(com);
  set_matrix(com_, t);
}

}  // namespace saltus::gui::scene
