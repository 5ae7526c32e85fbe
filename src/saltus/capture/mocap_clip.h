#pragma once
/// @file
/// A motion-capture clip in memory, as a BVH file describes it: a skeleton of named joints, each
/// placed at a fixed offset in its parent's frame and moved by its own channels (positions and
/// Euler rotations in any order), and one row of channel values per frame. Units and axes are
/// the file's own; retarget.h turns a clip into Saltus's frames. No file parsing here
/// (formats/bvh_file.h reads and writes the text).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <stdexcept>
#include <string>
#include <vector>

namespace saltus {

/// The part of a user's input a capture problem lies in, so that the front end names it (the
/// line of the BVH file, the flag, the model or mapping file) as every other message does.
enum class CapturePart {
  kSkeleton,         ///< the BVH file's HIERARCHY (its joints and offsets)
  kFrames,           ///< the BVH file's MOTION section (its frames)
  kFlightOption,     ///< the flight phase the user gave (--flight)
  kKeyframesOption,  ///< the keyframe count the user gave (--keyframes)
  kModel,            ///< the body model the capture is imported onto
  kMapping,          ///< the mapping file the user gave (--mapping)
};

/// A capture that cannot be imported, with the part of the input that causes it.
class CaptureError : public std::invalid_argument {
 public:
  CaptureError(CapturePart part, const std::string& problem)
      : std::invalid_argument(problem), part_(part) {}
  CapturePart part() const { return part_; }

 private:
  CapturePart part_;
};

/// One BVH channel: a translation or a rotation (degrees) about one axis of the joint's frame.
enum class MocapChannel { kXposition, kYposition, kZposition, kXrotation, kYrotation, kZrotation };

/// "Xposition", ... as in BVH files.
const char* mocap_channel_name(MocapChannel channel);
/// 0, 1, 2 for x, y, z.
int mocap_channel_axis(MocapChannel channel);
bool mocap_channel_is_rotation(MocapChannel channel);

struct MocapJoint {
  std::string name;
  int parent = -1;  ///< index into MocapClip::joints, -1 for the root
  /// Joint centre in the parent's frame (the root's: in the world), file units. A position
  /// channel replaces the matching coordinate (BVH readers such as Blender's do so: a root
  /// OFFSET equal to frame 0's position must not be added twice).
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  std::vector<MocapChannel> channels;  ///< in file order
  int first_column = 0;                ///< where this joint's channels start in a frame row
  /// "End Site" offsets (joint's frame, file units): where a chain ends, e.g. the top of the
  /// head or the toe tip. Usually zero or one.
  std::vector<Eigen::Vector3d> end_sites;
};

struct MocapClip {
  /// Depth-first order as in the file (parent before child, each subtree contiguous); the
  /// columns of a frame row follow the same order.
  std::vector<MocapJoint> joints;
  double frame_time = 0.0;                  ///< s per frame as stated by the file
  std::vector<std::vector<double>> frames;  ///< one row of channel values per frame

  int joint_count() const { return static_cast<int>(joints.size()); }
  int frame_count() const { return static_cast<int>(frames.size()); }
  int column_count() const;
  /// Index of the joint with this exact name, or -1.
  int joint_index(const std::string& name) const;
  /// The joints whose parent is `joint`, in file order.
  std::vector<int> children(int joint) const;
};

/// Checks the invariants the other functions rely on (parents before children in depth-first
/// order, unique names, columns laid out joint after joint, every row as long as the channels,
/// finite numbers, frame time > 0, at least one frame). Throws std::invalid_argument naming
/// the first problem (parsers check earlier, with file and line).
void validate_clip(const MocapClip& clip);

/// Rotation from Euler angles in degrees applied in the listed (intrinsic) order:
/// axes {2, 0, 1} ("Zrotation Xrotation Yrotation") gives Rz(a)·Rx(b)·Ry(c).
Eigen::Quaterniond rotation_from_euler_deg(const std::vector<int>& axes,
                                           const std::vector<double>& angles_deg);

/// The inverse for three distinct axes: angles (degrees) with
/// rotation_from_euler_deg(axes, angles) = q. The middle angle is in [-90°, 90°]; the outer two
/// in (-180°, 180°]. Exact to rounding, including at gimbal lock (where the split between the
/// outer angles is arbitrary but their product is q).
std::vector<double> euler_deg_from_rotation(const std::vector<int>& axes,
                                            const Eigen::Quaterniond& q);

/// World placement of every joint at one frame, in file units and axes.
struct MocapPose {
  std::vector<Eigen::Quaterniond> world_rotation;  ///< world_from_joint
  std::vector<Eigen::Vector3d> world_position;     ///< joint centres
};

/// Forward kinematics of one frame (joint local rotation = product of its rotation channels;
/// local translation = offset with position channels substituted).
MocapPose mocap_pose(const MocapClip& clip, int frame);

/// The same at the rest pose (every channel zero, offsets only): what the skeleton looks like
/// before any motion, e.g. a T-pose.
MocapPose mocap_rest_pose(const MocapClip& clip);

/// Rotation of `joint` relative to its parent at `frame` (its rotation channels only).
Eigen::Quaterniond mocap_local_rotation(const MocapClip& clip, int joint, int frame);

}  // namespace saltus
