#pragma once
/// @file
/// The ballistic path of the centre of mass (paper eq. 9) sampled for drawing, from the motion's
/// take-off state through the library's ballistic_com.

#include <Eigen/Core>
#include <vector>

#include "saltus/motion/motion.h"

namespace saltus::gui {

struct ParabolaSamples {
  std::vector<double> times;            ///< s, uniform on [0, T]
  std::vector<Eigen::Vector3d> points;  ///< CoM, world, m
  double apex_time = 0.0;               ///< s, when the vertical velocity is 0 (clamped to [0, T])
  Eigen::Vector3d apex = Eigen::Vector3d::Zero();  ///< CoM at apex_time
};

/// `count` >= 2 points on [0, duration]. Throws std::invalid_argument otherwise.
ParabolaSamples sample_parabola(const Takeoff& takeoff, double duration, int count);

}  // namespace saltus::gui
