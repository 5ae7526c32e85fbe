#include "saltus/body/drawing_colours.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace saltus {

namespace {

constexpr DrawingColour kLeftColour{0.25, 0.47, 0.88};
constexpr DrawingColour kRightColour{0.93, 0.45, 0.18};
constexpr DrawingColour kTrunkColour{0.86, 0.82, 0.74};
constexpr DrawingColour kSkinColour{0.95, 0.78, 0.64};
constexpr DrawingColour kNoseColour{0.82, 0.52, 0.44};

bool ends_with(const std::string& name, const char* suffix) {
  return name.size() > 2 && name.compare(name.size() - 2, 2, suffix) == 0;
}

int channel(double value) {
  return static_cast<int>(std::lround(255.0 * std::clamp(value, 0.0, 1.0)));
}

}  // namespace

DrawingColour segment_colour(const Segment& segment) {
  if (ends_with(segment.name, "_l")) return kLeftColour;
  if (ends_with(segment.name, "_r")) return kRightColour;
  return kTrunkColour;
}

DrawingColour part_colour(const Segment& segment, const ShapePart& part) {
  if (part.name == "nose") return kNoseColour;
  if (part.name == "head" || part.name == "neck" || part.name == "hand") return kSkinColour;
  return segment_colour(segment);
}

std::string hex_colour(const DrawingColour& colour) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", channel(colour.r), channel(colour.g),
                channel(colour.b));
  return text;
}

}  // namespace saltus
