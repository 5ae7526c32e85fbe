#include "saltus/optim/keyframe_targets.h"

#include "saltus/motion/interpolate.h"

namespace saltus {

KeyframeTargets::KeyframeTargets(const Motion& motion, const BodyModel& model)
    : takeoff_(motion.takeoff) {
  for (const Keyframe& k : motion.keyframes) {
    com_offset_.push_back(com_with_root_at_origin(model, k.rotations));
    fixed_root_.push_back(k.root_position);
    rotation_.push_back(k.rotations);
  }
}

Eigen::Vector3d KeyframeTargets::root(int keyframe, double time) const {
  if (fixed_root_[keyframe]) return *fixed_root_[keyframe];
  return ballistic_com(takeoff_, time) - com_offset_[keyframe];
}

Eigen::Vector3d KeyframeTargets::root_rate(int keyframe, double time) const {
  if (fixed_root_[keyframe]) return Eigen::Vector3d::Zero();
  return ballistic_com_velocity(takeoff_, time);
}

Eigen::Vector4d aligned_target(const Eigen::Quaterniond& target, const Eigen::Vector4d& q) {
  const Eigen::Vector4d t(target.w(), target.x(), target.y(), target.z());
  return t.dot(q) < 0 ? Eigen::Vector4d(-t) : t;
}

}  // namespace saltus
