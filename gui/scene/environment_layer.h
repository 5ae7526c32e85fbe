#pragma once
/// @file
/// The place of the flight (a layer of BodyScene; private to gui/scene): the apparatus the
/// library reads off the motion (evaluation/apparatus.h) — a trampoline whose bed is where the
/// feet leave from, or a platform at the take-off height above water where the flight ends — and
/// a floor grid (on the water for a dive).

#include <vtkActor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <Eigen/Geometry>
#include <vector>

#include "saltus/evaluation/apparatus.h"

namespace saltus::gui::scene {

class EnvironmentLayer {
 public:
  explicit EnvironmentLayer(vtkRenderer* renderer);

  /// Actors for an apparatus (replacing earlier ones); `flight` is the box the CoM path spans.
  void build(const Apparatus& apparatus, const Eigen::AlignedBox3d& flight);
  void clear();
  /// Also draws the apparatus in another renderer (the whole-flight inset).
  void show_in(vtkRenderer* other);
  void set_visible(bool apparatus, bool grid);
  /// What the whole-flight inset should frame of the apparatus (the part near the flight).
  const Eigen::AlignedBox3d& frame_bounds() const { return frame_; }

 private:
  void add(const vtkSmartPointer<vtkActor>& actor, bool apparatus);

  vtkRenderer* renderer_;
  std::vector<vtkRenderer*> also_in_;
  std::vector<vtkSmartPointer<vtkActor>> apparatus_;
  std::vector<vtkSmartPointer<vtkActor>> grid_;
  Eigen::AlignedBox3d frame_;
};

}  // namespace saltus::gui::scene
