#include "saltus/evaluation/keyframe_errors.h"

#include <algorithm>

#include "saltus/base/constants.h"
#include "saltus/math/quaternion.h"

namespace saltus {

KeyframeErrors keyframe_errors(const Motion& motion, const Trajectory<double>& trajectory,
                               const std::vector<double>& keyframe_times,
                               const std::vector<Eigen::Vector3d>& root_targets) {
  KeyframeErrors e;
  for (std::size_t i = 0; i < motion.keyframes.size(); ++i) {
    const double t = keyframe_times[i];
    const Eigen::Vector3d b = trajectory.root_translation.evaluate(t).position;
    e.max_translation_error_m =
        std::max(e.max_translation_error_m, (b - root_targets[i]).cwiseAbs().maxCoeff());
    for (int seg = 0; seg < trajectory.segment_count(); ++seg) {
      const Eigen::Quaterniond q = trajectory.rotations[seg].evaluate(t).q;
      const Eigen::Quaterniond& target = motion.keyframes[i].rotations[seg];
      e.max_quaternion_error = std::max(e.max_quaternion_error, quaternion_distance(q, target));
      e.max_rotation_error_deg = std::max(e.max_rotation_error_deg,
                                          degrees_from_radians(rotation_angle_between(q, target)));
    }
  }
  return e;
}

}  // namespace saltus
