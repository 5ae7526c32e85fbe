#pragma once
/// @file
/// The arrows (a layer of BodyScene; private to gui/scene): the residual force (one head) and
/// moment (two heads) at the CoM, drawn on the layer above the body, and optional joint-force
/// arrows. Lengths and colours follow GlyphScales made from the typical sizes of what is shown
/// (Document::glyph_typicals), or from sizes shared with another view (compare).

#include <vtkActor.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <vector>

#include "core/document.h"
#include "core/glyph_scale.h"

namespace saltus::gui::scene {

class GlyphLayer {
 public:
  /// Full-scale arrow lengths, m.
  static constexpr double kResidualArrowLength = 0.6;
  static constexpr double kJointArrowLength = 0.4;

  GlyphLayer(vtkRenderer* renderer, vtkRenderer* overlay);

  /// One joint arrow per joint of a model with `segments` segments (root excluded).
  void build(int segments);
  void clear();
  void set_scales(const GlyphTypicals& typicals);
  const GlyphScale& force_scale() const { return force_scale_; }
  const GlyphScale& moment_scale() const { return moment_scale_; }
  const GlyphScale& joint_scale() const { return joint_scale_; }
  /// The residual force arrow as drawn: its length in metres, read off its actor (0 when
  /// hidden).
  double force_length() const;
  /// Places the arrows for a sample; hidden ones are not drawn.
  void update(const SampleRecord& sample, bool residual, bool joints);
  void hide();

 private:
  void place(vtkActor* actor, const Eigen::Vector3d& origin, const Eigen::Vector3d& vector,
             const GlyphScale& scale, double thickness, bool shown);

  vtkRenderer* renderer_;
  vtkSmartPointer<vtkPolyDataMapper> arrow_mapper_;
  vtkSmartPointer<vtkPolyDataMapper> double_arrow_mapper_;
  vtkSmartPointer<vtkActor> force_;
  vtkSmartPointer<vtkActor> moment_;
  std::vector<vtkSmartPointer<vtkActor>> joints_;
  GlyphScale force_scale_, moment_scale_, joint_scale_;
};

}  // namespace saltus::gui::scene
