#include "saltus/math/quaternion.h"

#include <cmath>
#include <stdexcept>

namespace saltus {

namespace {
int axis_index(char c) {
  switch (c) {
    case 'X':
    case 'x':
      return 0;
    case 'Y':
    case 'y':
      return 1;
    case 'Z':
    case 'z':
      return 2;
    default:
      return -1;
  }
}

void check_order(const std::string& order) {
  if (order.size() != 3) throw std::invalid_argument("Euler order must have three letters");
  for (std::size_t i = 0; i < 3; ++i) {
    if (axis_index(order[i]) < 0)
      throw std::invalid_argument("Euler order letters must be X, Y or Z");
    if (i > 0 && axis_index(order[i]) == axis_index(order[i - 1]))
      throw std::invalid_argument("Euler order must not repeat an axis twice in a row");
  }
}
}  // namespace

Quat<double> quat_from_euler_deg(const Eigen::Vector3d& angles_deg, const std::string& order) {
  check_order(order);
  constexpr double kDegToRad = M_PI / 180.0;
  Quat<double> q = Quat<double>::Identity();
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    axis[axis_index(order[i])] = 1.0;
    q = q * Quat<double>(Eigen::AngleAxisd(angles_deg[i] * kDegToRad, axis));
  }
  return q.normalized();
}

}  // namespace saltus
