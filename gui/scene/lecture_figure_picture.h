#pragma once
/// @file
/// The lecture figure drawn offscreen into a PNG: every pose of the stroboscope in its spin
/// rate's colour (the 3D view's body shapes), the centre of mass's path as a grey line, each
/// pose's time under it, the title above, the caption below and the colour bar at the right, on
/// white (for slides and paper). No Qt.

#include <string>

#include "core/lecture_figure.h"

namespace saltus::gui {

/// Default size of the picture, pixels: wide, as a flight seen from the side is.
inline constexpr int kLectureFigureWidth = 1800;
inline constexpr int kLectureFigureHeight = 900;

/// Writes the figure as a width × height PNG. Throws std::runtime_error if it cannot be written.
void write_lecture_figure_png(const LectureFigure& figure, const std::string& path,
                              int width = kLectureFigureWidth, int height = kLectureFigureHeight);

}  // namespace saltus::gui
