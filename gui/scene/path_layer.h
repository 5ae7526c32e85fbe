#pragma once
/// @file
/// The paths of the flight (a layer of BodyScene; private to gui/scene): the ballistic CoM
/// parabola of the take-off state (white), the CoM path the motion takes (orange) and the CoM
/// now (a yellow ball, drawn on the layer above the body so the trunk never hides it).

#include <vtkActor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <Eigen/Geometry>
#include <vector>

#include "core/document.h"

namespace saltus::gui::scene {

class PathLayer {
 public:
  /// @param renderer  the scene; @param overlay  the layer above it (the CoM ball)
  PathLayer(vtkRenderer* renderer, vtkRenderer* overlay);

  void build(const Document& document, Stage stage);
  void clear();
  /// Also draws the paths and the CoM ball in another renderer (the whole-flight inset).
  void show_in(vtkRenderer* other);
  void set_visible(bool parabola, bool trace, bool com);
  void set_com(const Eigen::Vector3d& com);
  /// The box the parabola spans (the flight), m.
  const Eigen::AlignedBox3d& flight_bounds() const { return bounds_; }

 private:
  vtkRenderer* renderer_;
  std::vector<vtkRenderer*> also_in_;
  vtkSmartPointer<vtkActor> parabola_;
  vtkSmartPointer<vtkActor> trace_;
  vtkSmartPointer<vtkActor> com_;
  Eigen::AlignedBox3d bounds_;
};

}  // namespace saltus::gui::scene
