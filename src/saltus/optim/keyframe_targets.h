#pragma once
/// @file
/// What the keyframes ask of the motion, as the keyframe terms and constraint blocks read it:
/// the root translation B̄_i at keyframe i's current time (eq. 2: the CoM parabola at that time
/// minus the keyframe pose's CoM offset s'_i, unless the keyframe fixes root_position) and the
/// joint rotations Q̄ (eq. 3).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/motion/motion.h"

namespace saltus {

class KeyframeTargets {
 public:
  KeyframeTargets(const Motion& motion, const BodyModel& model);

  int size() const { return static_cast<int>(rotation_.size()); }
  /// B̄_i when keyframe i is at `time` (m, world).
  Eigen::Vector3d root(int keyframe, double time) const;
  /// dB̄_i/dt_i: how the target moves with the keyframe's time (zero for a fixed root_position).
  Eigen::Vector3d root_rate(int keyframe, double time) const;
  /// Whether B̄_i follows the parabola (and so moves with the keyframe's time).
  bool root_moves_with_time(int keyframe) const { return !fixed_root_[keyframe]; }
  /// Q̄ of segment k at keyframe i.
  const Eigen::Quaterniond& rotation(int keyframe, int segment) const {
    return rotation_[keyframe][segment];
  }

 private:
  Takeoff takeoff_;
  std::vector<Eigen::Vector3d> com_offset_;                 ///< s'_i of each keyframe pose
  std::vector<std::optional<Eigen::Vector3d>> fixed_root_;  ///< root_position if given
  std::vector<std::vector<Eigen::Quaterniond>> rotation_;   ///< [keyframe][segment]
};

/// The keyframe quaternion sign-aligned to the curve's q (w, x, y, z): the paper's eq. (3)
/// compares rotations, not signs.
Eigen::Vector4d aligned_target(const Eigen::Quaterniond& target, const Eigen::Vector4d& q);

}  // namespace saltus
