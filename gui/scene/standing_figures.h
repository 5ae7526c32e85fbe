#pragma once
/// @file
/// Athletes side by side on one scale (the New athlete dialog's previews): each drawn by the 3D
/// view's body layer from its model's shapes, in the standing pose (every joint at identity, the
/// library's standing_origins) or in a pose of a flight (its landing: upside down when it lands
/// upside down), its lowest joint on one floor, seen from the front a little from the right, its
/// label above it. A shorter athlete looks shorter.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/sampling.h"

class vtkRenderWindow;

namespace saltus::gui {

class StandingFigures {
 public:
  /// One athlete: the model, the words above it, and whether it is drawn in the body's colours
  /// or in grey (the model it is compared with).
  struct Figure {
    BodyModel model;
    std::string label;
    bool grey = false;
    /// A pose of a flight (world positions and rotations per segment, e.g. a free flight's
    /// landing), drawn with its orientation as it is, moved onto its place and the floor; none:
    /// standing.
    std::optional<SampleRecord> pose;
  };

  StandingFigures();
  ~StandingFigures();
  StandingFigures(const StandingFigures&) = delete;
  StandingFigures& operator=(const StandingFigures&) = delete;

  void attach(vtkRenderWindow* window);
  /// Draws these figures, left to right (none: an empty floor), and frames them.
  void set_figures(const std::vector<Figure>& figures);
  /// The height of each figure as drawn (m): its standing body's.
  std::vector<double> drawn_heights() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace saltus::gui
