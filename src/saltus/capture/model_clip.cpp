#include "saltus/capture/model_clip.h"

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace saltus {

namespace {

constexpr double kCentimetresPerMetre = 100.0;
/// BVH's most common rotation order (Blender, MotionBuilder, DeepMimic): R = Rz·Rx·Ry.
const std::vector<int> kRotationAxes{2, 0, 1};

std::vector<MocapChannel> rotation_channels() {
  return {MocapChannel::kZrotation, MocapChannel::kXrotation, MocapChannel::kYrotation};
}

}  // namespace

MocapClip model_skeleton_clip(const BodyModel& model) {
  MocapClip clip;
  std::vector<int> segment_of_joint;
  // Depth-first from the root, children in model order, as BVH nests them.
  std::function<void(int, int)> add = [&](int segment, int parent_joint) {
    const Segment& s = model.segments[segment];
    MocapJoint joint;
    joint.name = s.name;
    joint.parent = parent_joint;
    if (parent_joint < 0) {
      joint.channels = {MocapChannel::kXposition, MocapChannel::kYposition,
                        MocapChannel::kZposition};
    } else {
      joint.offset = kCentimetresPerMetre * s.joint_position;
    }
    for (MocapChannel c : rotation_channels())
      joint.channels.push_back(c);
    joint.first_column = clip.column_count();
    const Eigen::Vector3d tip(0.0, s.shape.length, 0.0);
    bool continued = false;
    for (const Segment& other : model.segments)
      if (other.parent == segment && (other.joint_position - tip).norm() < 1e-9) continued = true;
    if (!continued && s.shape.length != 0.0) joint.end_sites.push_back(kCentimetresPerMetre * tip);
    const int index = clip.joint_count();
    clip.joints.push_back(joint);
    segment_of_joint.push_back(segment);
    for (int child = 0; child < model.size(); ++child)
      if (model.segments[child].parent == segment) add(child, index);
  };
  for (int s = 0; s < model.size(); ++s)
    if (model.segments[s].parent < 0) add(s, -1);
  return clip;
}

MocapClip model_clip_from_states(const BodyModel& model, double frame_time,
                                 const std::vector<BodyState<double>>& states) {
  if (!(frame_time > 0) || !std::isfinite(frame_time))
    throw std::invalid_argument("the frame time must be > 0");
  MocapClip clip = model_skeleton_clip(model);
  clip.frame_time = frame_time;
  for (const BodyState<double>& state : states) {
    if (static_cast<int>(state.joints.size()) != model.size())
      throw std::invalid_argument("model_clip_from_states: a state does not fit the model");
    std::vector<double> row;
    row.reserve(clip.column_count());
    for (const MocapJoint& joint : clip.joints) {
      const int segment = model.segment_index(joint.name);
      if (joint.parent < 0)
        for (int i = 0; i < 3; ++i)
          row.push_back(kCentimetresPerMetre * state.root_position[i]);
      for (double angle : euler_deg_from_rotation(kRotationAxes, state.joints[segment].q))
        row.push_back(angle);
    }
    clip.frames.push_back(std::move(row));
  }
  validate_clip(clip);
  return clip;
}

double motion_clip_frame_count(double duration, double fps) {
  const double frames = std::round(duration * fps) + 1.0;
  return frames < 2.0 ? 2.0 : frames;  // NaN stays NaN
}

MocapClip motion_clip(const BodyModel& model, const Trajectory<double>& trajectory, double fps) {
  if (!(fps > 0) || !std::isfinite(fps))
    throw std::invalid_argument("frames per second must be > 0");
  if (trajectory.segment_count() != model.size())
    throw std::invalid_argument("motion_clip: the trajectory does not fit the model");
  const double duration = trajectory.duration();
  const double count = motion_clip_frame_count(duration, fps);
  if (!(count <= std::numeric_limits<int>::max()))
    throw std::invalid_argument("motion_clip: too many frames");
  const int frames = static_cast<int>(count);
  const double frame_time = duration / (frames - 1);
  std::vector<BodyState<double>> states(frames, BodyState<double>(model.size()));
  for (int f = 0; f < frames; ++f)
    trajectory.sample(f + 1 == frames ? duration : f * frame_time, states[f]);
  return model_clip_from_states(model, frame_time, states);
}

}  // namespace saltus
