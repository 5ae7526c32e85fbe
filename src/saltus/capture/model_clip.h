#pragma once
/// @file
/// A motion on the body model as a motion-capture clip, for `saltus export --format bvh`: the
/// model's segments become joints named after the segments (abdomen the root, so BVH's root
/// translation is Saltus's root translation), offsets in centimetres, y up, the body facing +z
/// in the rest pose (Saltus's identity pose: arms hanging, feet neutral), every rotation as
/// Z, X, Y Euler channels (R = Rz·Rx·Ry, degrees), End Sites at the tips of segments no joint
/// continues (head, hands, feet, hip centre). Importing such a clip gives the motion back
/// (retargeting maps it segment to segment, rest corrections are identities, the heading is
/// kept).

#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/capture/mocap_clip.h"
#include "saltus/dynamics/body_state.h"
#include "saltus/motion/trajectory.h"

namespace saltus {

/// The model's skeleton with no frames (frame_time 0; add frames before validating).
MocapClip model_skeleton_clip(const BodyModel& model);

/// Poses as frames `frame_time` apart: each state's root position and joint rotations (rates
/// are not used). Throws std::invalid_argument for frame_time <= 0 or states that do not fit
/// the model.
MocapClip model_clip_from_states(const BodyModel& model, double frame_time,
                                 const std::vector<BodyState<double>>& states);

/// Frames of motion_clip's clip `duration` s long at about `fps` frames per second:
/// round(duration·fps) + 1, at least 2. A double, so that a caller checks it against a limit
/// before sampling (a huge rate gives a huge count, a NaN rate NaN, never an int overflow).
double motion_clip_frame_count(double duration, double fps);

/// The trajectory sampled on [0, T] at about `fps` frames per second: motion_clip_frame_count
/// frames, spaced exactly T/(frames − 1) so the last frame is the landing. Throws
/// std::invalid_argument for fps <= 0 or a trajectory that does not fit the model.
MocapClip motion_clip(const BodyModel& model, const Trajectory<double>& trajectory, double fps);

}  // namespace saltus
