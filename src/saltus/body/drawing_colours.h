#pragma once
/// @file
/// The colours a body is drawn in, by segment and shape-part name: left side blue, right side
/// orange, trunk sand, skin where an athlete in a leotard shows it (head, neck, hands), the nose
/// darker. The desktop app (gui/scene/body_layer.cpp) and the flight page (use_cases/flight_page)
/// draw these colours. Not used by any physics.

#include <string>

#include "saltus/body/body_model.h"

namespace saltus {

/// A colour, each channel in [0, 1].
struct DrawingColour {
  double r = 0.0, g = 0.0, b = 0.0;
};

/// Of a segment drawn as one shape: by its side, from the name's "_l" / "_r" ending.
DrawingColour segment_colour(const Segment& segment);

/// Of one part of a segment's shape: skin for "head", "neck" and "hand", the nose's own, else
/// the segment's colour.
DrawingColour part_colour(const Segment& segment, const ShapePart& part);

/// "#rrggbb", each channel rounded to 0-255.
std::string hex_colour(const DrawingColour& colour);

}  // namespace saltus
