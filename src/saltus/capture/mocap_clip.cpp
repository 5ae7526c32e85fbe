#include "saltus/capture/mocap_clip.h"

#include <cmath>
#include <set>
#include <stdexcept>

#include "saltus/base/constants.h"

namespace saltus {

namespace {

constexpr double kRadiansPerDegree = kPi / 180.0;

Eigen::Vector3d unit_axis(int axis) {
  return Eigen::Vector3d::Unit(axis);
}

/// Local translation: the offset with the joint's position channels substituted.
Eigen::Vector3d local_translation(const MocapJoint& joint, const std::vector<double>& row) {
  Eigen::Vector3d t = joint.offset;
  for (std::size_t c = 0; c < joint.channels.size(); ++c) {
    if (!mocap_channel_is_rotation(joint.channels[c]))
      t[mocap_channel_axis(joint.channels[c])] = row[joint.first_column + c];
  }
  return t;
}

Eigen::Quaterniond local_rotation(const MocapJoint& joint, const std::vector<double>& row) {
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  for (std::size_t c = 0; c < joint.channels.size(); ++c) {
    if (mocap_channel_is_rotation(joint.channels[c]))
      q = q *
          Eigen::Quaterniond(Eigen::AngleAxisd(row[joint.first_column + c] * kRadiansPerDegree,
                                               unit_axis(mocap_channel_axis(joint.channels[c]))));
  }
  return q;
}

MocapPose pose_from_row(const MocapClip& clip, const std::vector<double>& row) {
  MocapPose pose;
  pose.world_rotation.resize(clip.joints.size());
  pose.world_position.resize(clip.joints.size());
  for (std::size_t j = 0; j < clip.joints.size(); ++j) {
    const MocapJoint& joint = clip.joints[j];
    const Eigen::Vector3d t = local_translation(joint, row);
    const Eigen::Quaterniond r = local_rotation(joint, row);
    if (joint.parent < 0) {
      pose.world_position[j] = t;
      pose.world_rotation[j] = r;
    } else {
      pose.world_position[j] =
          pose.world_position[joint.parent] + pose.world_rotation[joint.parent] * t;
      pose.world_rotation[j] = pose.world_rotation[joint.parent] * r;
    }
  }
  return pose;
}

}  // namespace

const char* mocap_channel_name(MocapChannel channel) {
  switch (channel) {
    case MocapChannel::kXposition:
      return "Xposition";
    case MocapChannel::kYposition:
      return "Yposition";
    case MocapChannel::kZposition:
      return "Zposition";
    case MocapChannel::kXrotation:
      return "Xrotation";
    case MocapChannel::kYrotation:
      return "Yrotation";
    case MocapChannel::kZrotation:
      return "Zrotation";
  }
  return "?";
}

int mocap_channel_axis(MocapChannel channel) {
  switch (channel) {
    case MocapChannel::kXposition:
    case MocapChannel::kXrotation:
      return 0;
    case MocapChannel::kYposition:
    case MocapChannel::kYrotation:
      return 1;
    case MocapChannel::kZposition:
    case MocapChannel::kZrotation:
      return 2;
  }
  return 0;
}

bool mocap_channel_is_rotation(MocapChannel channel) {
  return channel == MocapChannel::kXrotation || channel == MocapChannel::kYrotation ||
         channel == MocapChannel::kZrotation;
}

int MocapClip::column_count() const {
  int n = 0;
  for (const MocapJoint& joint : joints)
    n += static_cast<int>(joint.channels.size());
  return n;
}

int MocapClip::joint_index(const std::string& name) const {
  for (std::size_t j = 0; j < joints.size(); ++j)
    if (joints[j].name == name) return static_cast<int>(j);
  return -1;
}

std::vector<int> MocapClip::children(int joint) const {
  std::vector<int> out;
  for (std::size_t j = 0; j < joints.size(); ++j)
    if (joints[j].parent == joint) out.push_back(static_cast<int>(j));
  return out;
}

void validate_clip(const MocapClip& clip) {
  if (clip.joints.empty()) throw std::invalid_argument("the clip has no joints");
  if (!(clip.frame_time > 0.0) || !std::isfinite(clip.frame_time))
    throw std::invalid_argument("the frame time must be a positive number");
  if (clip.frames.empty()) throw std::invalid_argument("the clip has no frames");
  std::set<std::string> names;
  // Depth-first order: a joint's parent is on the stack of open ancestors of the previous joint.
  std::vector<int> open;
  int column = 0;
  for (std::size_t j = 0; j < clip.joints.size(); ++j) {
    const MocapJoint& joint = clip.joints[j];
    if (!names.insert(joint.name).second)
      throw std::invalid_argument("joint name \"" + joint.name + "\" is used twice");
    if (j == 0 && joint.parent != -1) throw std::invalid_argument("the first joint is not a root");
    if (j > 0) {
      while (!open.empty() && open.back() != joint.parent)
        open.pop_back();
      if (open.empty())
        throw std::invalid_argument("joint \"" + joint.name +
                                    "\" is not in depth-first order after its parent");
    }
    open.push_back(static_cast<int>(j));
    if (joint.first_column != column)
      throw std::invalid_argument("joint \"" + joint.name + "\" channels start at column " +
                                  std::to_string(joint.first_column) + ", expected " +
                                  std::to_string(column));
    column += static_cast<int>(joint.channels.size());
    if (!joint.offset.allFinite())
      throw std::invalid_argument("joint \"" + joint.name + "\" has a non-finite offset");
  }
  for (std::size_t f = 0; f < clip.frames.size(); ++f) {
    if (static_cast<int>(clip.frames[f].size()) != column)
      throw std::invalid_argument("frame " + std::to_string(f) + " has " +
                                  std::to_string(clip.frames[f].size()) + " values, expected " +
                                  std::to_string(column));
    for (double v : clip.frames[f])
      if (!std::isfinite(v))
        throw std::invalid_argument("frame " + std::to_string(f) + " has a non-finite value");
  }
}

Eigen::Quaterniond rotation_from_euler_deg(const std::vector<int>& axes,
                                           const std::vector<double>& angles_deg) {
  if (axes.size() != angles_deg.size())
    throw std::invalid_argument("rotation_from_euler_deg: axes and angles differ in count");
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  for (std::size_t i = 0; i < axes.size(); ++i)
    q = q * Eigen::Quaterniond(
                Eigen::AngleAxisd(angles_deg[i] * kRadiansPerDegree, unit_axis(axes[i])));
  return q;
}

std::vector<double> euler_deg_from_rotation(const std::vector<int>& axes,
                                            const Eigen::Quaterniond& q) {
  if (axes.size() != 3 || axes[0] == axes[1] || axes[1] == axes[2] || axes[0] == axes[2])
    throw std::invalid_argument("euler_deg_from_rotation: needs three distinct axes");
  const int i = axes[0], j = axes[1], k = axes[2];
  // Parity of (i, j, k) as a permutation of (0, 1, 2): +1 for XYZ, YZX, ZXY.
  const double s = ((j - i + 3) % 3 == 1) ? 1.0 : -1.0;
  const Eigen::Matrix3d r = q.normalized().toRotationMatrix();
  // R = R_i(a) R_j(b) R_k(c): R(i,k) = s·sin b, R(j,k) = -s·sin a cos b, R(k,k) = cos a cos b,
  // R(i,j) = -s·cos b sin c, R(i,i) = cos b cos c.
  const double cos_b = std::hypot(r(i, i), r(i, j));
  const double b = std::atan2(s * r(i, k), cos_b);
  double a, c;
  if (cos_b > 1e-12) {
    a = std::atan2(-s * r(j, k), r(k, k));
    c = std::atan2(-s * r(i, j), r(i, i));
  } else {
    // Gimbal lock: only a ± c is defined; put it all in a (c = 0), read from R_i(a)·R_j(±90°).
    a = std::atan2(s * r(k, j), r(j, j));
    c = 0.0;
  }
  return {a / kRadiansPerDegree, b / kRadiansPerDegree, c / kRadiansPerDegree};
}

MocapPose mocap_pose(const MocapClip& clip, int frame) {
  return pose_from_row(clip, clip.frames.at(frame));
}

MocapPose mocap_rest_pose(const MocapClip& clip) {
  MocapPose pose;
  pose.world_rotation.assign(clip.joints.size(), Eigen::Quaterniond::Identity());
  pose.world_position.resize(clip.joints.size());
  for (std::size_t j = 0; j < clip.joints.size(); ++j) {
    const MocapJoint& joint = clip.joints[j];
    pose.world_position[j] =
        joint.parent < 0 ? joint.offset : pose.world_position[joint.parent] + joint.offset;
  }
  return pose;
}

Eigen::Quaterniond mocap_local_rotation(const MocapClip& clip, int joint, int frame) {
  return local_rotation(clip.joints.at(joint), clip.frames.at(frame));
}

}  // namespace saltus
