#pragma once
/// @file
/// How well a trajectory meets its keyframes (the relaxed model's tolerances ε1, ε2).

#include <Eigen/Core>
#include <vector>

#include "saltus/motion/motion.h"
#include "saltus/motion/trajectory.h"

namespace saltus {

/// How far a trajectory is from its keyframes at the given keyframe times.
struct KeyframeErrors {
  double max_translation_error_m = 0.0;  ///< max over keyframes and coordinates |B − B̄|
  double max_quaternion_error = 0.0;     ///< max ‖Q − Q̄‖, sign-aligned (paper eq. 3)
  double max_rotation_error_deg = 0.0;   ///< the same as a rotation angle
};

/// @param keyframe_times  where to evaluate (the given times, or the optimised ones)
/// @param root_targets    B̄ per keyframe (keyframe_root_targets)
KeyframeErrors keyframe_errors(const Motion& motion, const Trajectory<double>& trajectory,
                               const std::vector<double>& keyframe_times,
                               const std::vector<Eigen::Vector3d>& root_targets);

}  // namespace saltus
