#include "saltus/body/drawn_parts.h"

#include <algorithm>

namespace saltus {

std::vector<DrawnPart> drawn_parts(const Segment& segment) {
  std::vector<DrawnPart> out;
  if (segment.shape.parts.empty()) {
    ShapePart capsule;
    capsule.name = segment.name;
    capsule.type = "capsule";
    capsule.center = Eigen::Vector3d(0, 0.5 * segment.shape.length, 0);
    capsule.length = segment.shape.length;
    capsule.radius = std::max(segment.shape.radius, kMinDrawnRadius);
    out.push_back({capsule, segment_colour(segment)});
  }
  for (const ShapePart& part : segment.shape.parts)
    out.push_back({part, part_colour(segment, part)});
  return out;
}

}  // namespace saltus
