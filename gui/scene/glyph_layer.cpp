#include "scene/glyph_layer.h"

#include <vtkAppendPolyData.h>
#include <vtkArrowSource.h>
#include <vtkConeSource.h>
#include <vtkMatrix4x4.h>
#include <vtkProperty.h>

#include <algorithm>
#include <cmath>

#include "scene/vtk_util.h"

namespace saltus::gui::scene {

namespace {

/// Arrow of the given length along `direction` from `origin`; the unit glyph points along +x.
/// Thickness shrinks with very short arrows so that a tiny residual looks tiny.
Eigen::Affine3d arrow_transform(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                double length, double thickness) {
  const Eigen::Quaterniond turn =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), direction.normalized());
  const double w = thickness * std::min(1.0, length / 0.25);
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.translate(origin);
  t.rotate(turn);
  t.scale(Eigen::Vector3d(length, w, w));
  return t;
}

}  // namespace

GlyphLayer::GlyphLayer(vtkRenderer* renderer, vtkRenderer* overlay) : renderer_(renderer) {
  vtkNew<vtkArrowSource> arrow;
  arrow->SetTipLength(0.25);
  arrow->SetTipRadius(0.08);
  arrow->SetShaftRadius(0.025);
  arrow->SetTipResolution(16);
  arrow->SetShaftResolution(12);
  arrow_mapper_ = mapper_for(arrow->GetOutputPort());
  vtkNew<vtkConeSource> second_head;
  second_head->SetHeight(0.25);
  second_head->SetRadius(0.08);
  second_head->SetResolution(16);
  second_head->SetDirection(1, 0, 0);
  second_head->SetCenter(0.625, 0, 0);
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(arrow->GetOutputPort());
  both->AddInputConnection(second_head->GetOutputPort());
  double_arrow_mapper_ = mapper_for(both->GetOutputPort());
  force_ = actor_for(arrow_mapper_);
  moment_ = actor_for(double_arrow_mapper_);
  for (vtkActor* a : {force_.Get(), moment_.Get()}) {
    a->GetProperty()->SetSpecular(0.3);
    a->PickableOff();
    a->SetVisibility(false);
    overlay->AddActor(a);
  }
}

void GlyphLayer::clear() {
  for (auto& a : joints_)
    renderer_->RemoveActor(a);
  joints_.clear();
}

void GlyphLayer::build(int segments) {
  clear();
  for (int i = 1; i < segments; ++i) {
    auto a = actor_for(arrow_mapper_);
    a->PickableOff();
    renderer_->AddActor(a);
    joints_.push_back(a);
  }
}

void GlyphLayer::set_scales(const GlyphTypicals& t) {
  force_scale_ = GlyphScale(t.residual_force, kResidualArrowLength);
  moment_scale_ = GlyphScale(t.residual_moment, kResidualArrowLength);
  joint_scale_ = GlyphScale(t.joint_force, kJointArrowLength);
}

void GlyphLayer::place(vtkActor* actor, const Eigen::Vector3d& origin,
                       const Eigen::Vector3d& vector, const GlyphScale& scale, double thickness,
                       bool shown) {
  const double magnitude = vector.norm();
  const double length = scale.length(magnitude);
  if (!shown || length < 1e-4) {
    actor->SetVisibility(false);
    return;
  }
  actor->SetVisibility(true);
  set_matrix(actor, arrow_transform(origin, vector, length, thickness));
  set_colour(actor, scale.colour(magnitude));
}

void GlyphLayer::update(const SampleRecord& s, bool residual, bool joints) {
  place(force_, s.com, s.residual.head<3>(), force_scale_, 0.9, residual);
  place(moment_, s.com, s.residual.tail<3>(), moment_scale_, 0.6, residual);
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    const std::size_t seg = i + 1;
    // joint_wrench is the parent's push on the child, child frame: rotate into the world.
    const Eigen::Vector3d f = s.segment_rotation[seg] * s.joint_wrench[seg].head<3>();
    place(joints_[i], s.segment_position[seg], f, joint_scale_, 0.45, joints);
  }
}

double GlyphLayer::force_length() const {
  vtkMatrix4x4* m = force_->GetUserMatrix();
  if (!force_->GetVisibility() || !m) return 0.0;
  // The unit arrow points along +x: the first column is the arrow, scaled to its length.
  return std::hypot(m->GetElement(0, 0), m->GetElement(1, 0), m->GetElement(2, 0));
}

void GlyphLayer::hide() {
  force_->SetVisibility(false);
  moment_->SetVisibility(false);
  for (auto& a : joints_)
    a->SetVisibility(false);
}

}  // namespace saltus::gui::scene
