#pragma once
/// @file
/// What a segment looks like: the pieces it is drawn as and their colours, as the app, the
/// flight page and the exports (MuJoCo's display geoms, glTF's meshes, OpenSim's geometry) draw
/// it. Not used by any physics.

#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/body/drawing_colours.h"

namespace saltus {

/// Below this a segment drawn as its single shape gets this radius, m, so that it stays visible.
inline constexpr double kMinDrawnRadius = 0.01;

/// One piece of a segment's drawing, in segment coordinates.
struct DrawnPart {
  ShapePart shape;  ///< "ellipsoid" (center, radii) or "capsule" (center, length along y, radius)
  DrawingColour colour;
};

/// The shape's parts with their colours (part_colour); a segment without parts is one capsule
/// from its origin along its y axis, `shape.length` long (signed), radius `shape.radius` (at
/// least kMinDrawnRadius), in the segment's colour.
std::vector<DrawnPart> drawn_parts(const Segment& segment);

}  // namespace saltus
