#pragma once
/// @file
/// The athlete (a layer of BodyScene; private to gui/scene): one actor per segment drawn from the
/// model's shapes — its parts when it has them (head, hands, pointed feet), else its capsule —
/// smooth-shaded; left limbs blue, right orange, the trunk neutral, head and hands skin-coloured
/// with a nose that shows where the face is. The picked segment is drawn lighter with a cyan
/// rim; the keyframe poses are thin pale figures.

#include <vtkActor.h>
#include <vtkCellPicker.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <optional>
#include <vector>

#include "core/chart_spec.h"
#include "saltus/body/body_model.h"
#include "saltus/evaluation/sampling.h"

namespace saltus::gui::scene {

class BodyLayer {
 public:
  explicit BodyLayer(vtkRenderer* renderer);

  /// Actors for a model (replacing earlier ones). With `uniform`, every part in that one colour
  /// and not pickable: a second figure beside the athlete (a motion capture).
  void build(const BodyModel& model, const std::optional<Rgb>& uniform = std::nullopt);
  void set_visible(bool visible);
  void clear();
  bool empty() const { return segments_.empty(); }
  /// Also draws the body in another renderer (the whole-flight inset); the actors are shared.
  void show_in(vtkRenderer* other);

  /// Poses every segment (and the rim of the picked one) as in the sample, moved by `offset`
  /// (world, m).
  void pose(const SampleRecord& sample, const Eigen::Vector3d& offset = Eigen::Vector3d::Zero());

  /// The keyframe poses as thin figures, pale blue-grey (given) or pale amber (optimised).
  void build_ghosts(const BodyModel& model, const std::vector<SampleRecord>& poses, bool optimised);
  void set_ghosts_visible(bool visible);

  /// The segment drawn lighter with a rim (-1: none); kept while the index exists.
  void set_highlight(int segment);
  int highlight() const { return highlight_; }
  /// The segment at a pixel of the main renderer (device pixels from the bottom-left), the
  /// nearest along the line of sight; -1 where none is.
  int segment_at(int x, int y);

  /// The lowest point of the body as posed now (world y, m; its shapes included): where it
  /// touches a floor.
  double lowest_y() const;

  /// Height of the drawn body standing at the identity pose, m (the cameras frame it).
  double standing_height() const { return standing_height_; }

 private:
  void apply_highlight();

  vtkRenderer* renderer_;
  std::vector<vtkRenderer*> also_in_;
  std::vector<vtkSmartPointer<vtkActor>> segments_;
  std::vector<vtkSmartPointer<vtkPolyData>> outlines_;  ///< each segment inflated by its rim
  vtkNew<vtkActor> outline_;
  vtkSmartPointer<vtkActor> ghosts_;
  vtkNew<vtkCellPicker> picker_;
  int highlight_ = -1;
  double standing_height_ = 1.7;
};

}  // namespace saltus::gui::scene
