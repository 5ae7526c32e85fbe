#pragma once
/// @file
/// The lecture figure (File > Export lecture figure…, `--lecture-figure`): the library's
/// stroboscopic side view of the stage shown (poses at equal time steps, their spin rates, the
/// centre of mass's path, the side it is seen from, any spread) with the words a teacher reads
/// under it and the colours of the spin rate. Drawn by scene/lecture_figure_picture.

#include <string>

#include "core/chart_spec.h"
#include "core/document.h"
#include "saltus/evaluation/stroboscope.h"

namespace saltus::gui {

struct LectureFigure {
  Stroboscope strobe;
  BodyModel model;
  std::string title;  ///< the motion and the stage: "M1 … — optimised motion (after optimisation)"
  std::string caption;  ///< lines: the poses' times, the view, the scale or spread, the colour
  std::string colour_bar_title;  ///< the spin rate in words and units
  double spin_low =
      0.0;  ///< rev/s at the colour bar's bottom: a whole step at or below the slowest
  double spin_high = 1.0;  ///< rev/s at its top: a whole step at or above the fastest
  double spin_step = 0.1;  ///< rev/s between the colour bar's labels: 0.1, 0.2, 0.5, 1 or 2
};

/// The figure of `stage` of the document's motion (the available stage: before without a run).
/// Requires a loaded document; pose_count >= 2.
LectureFigure lecture_figure(const Document& document, Stage stage,
                             int pose_count = kDefaultStroboscopePoses);

/// The words for a stroboscope of the motion `name` at the stage `stage_words`. Throws
/// std::invalid_argument for a stroboscope without poses.
LectureFigure lecture_figure_of(Stroboscope strobe, const BodyModel& model, const std::string& name,
                                const std::string& stage_words);

/// The colour of a spin rate `fraction` of the way up the colour bar (clamped to [0, 1]): dark
/// blue (slow) through teal and orange to red (fast); every step readable on white paper.
Rgb spin_colour(double fraction);

}  // namespace saltus::gui
