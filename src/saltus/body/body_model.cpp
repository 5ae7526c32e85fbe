#include "saltus/body/body_model.h"

#include <cmath>
#include <stdexcept>

#include "saltus/base/text_format.h"

namespace saltus {

double BodyModel::total_mass() const {
  double m = 0.0;
  for (const auto& s : segments)
    m += s.mass;
  return m;
}

int BodyModel::joint_index(const std::string& joint_name) const {
  for (int i = 0; i < size(); ++i)
    if (segments[i].joint == joint_name) return i;
  return -1;
}

int BodyModel::segment_index(const std::string& segment_name) const {
  for (int i = 0; i < size(); ++i)
    if (segments[i].name == segment_name) return i;
  return -1;
}

BodyModel scale_segment_mass(const BodyModel& model, const std::string& segment, double factor) {
  if (!std::isfinite(factor) || !(factor > 0.0))
    throw std::invalid_argument(
        "scale_segment_mass: factor must be a positive finite number, got " +
        message_number(factor));
  BodyModel scaled = model;
  if (segment.empty()) {
    for (Segment& s : scaled.segments) {
      s.mass *= factor;
      s.inertia *= factor;
    }
    return scaled;
  }
  const int index = model.segment_index(segment);
  if (index < 0)
    throw std::invalid_argument("scale_segment_mass: model \"" + model.name +
                                "\" has no segment \"" + segment + "\"");
  // Same shape, denser material: mass and inertia scale together, the CoM stays put.
  Segment& s = scaled.segments[static_cast<std::size_t>(index)];
  s.mass *= factor;
  s.inertia *= factor;
  return scaled;
}

}  // namespace saltus
