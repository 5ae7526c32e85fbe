#pragma once
/// @file
/// Athletes standing side by side on one scale (the New athlete dialog's preview): each drawn by
/// the 3D view's body layer from its model's shapes, in the standing pose (every joint at
/// identity, the library's standing_origins), feet on one floor, seen from the front a little
/// from the right, its label above its head. A shorter athlete looks shorter.

#include <memory>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"

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
