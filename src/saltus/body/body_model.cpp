#include "saltus/body/body_model.h"

namespace saltus {

double BodyModel::total_mass() const {
  double m = 0.0;
  for (const auto& s : segments) m += s.mass;
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

}  // namespace saltus
