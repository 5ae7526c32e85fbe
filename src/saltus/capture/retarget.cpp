#include "saltus/capture/retarget.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "saltus/base/constants.h"

namespace saltus {

namespace {

/// The joint each limb's bone points at, by mapping key.
const std::map<std::string, std::string>& limb_ends() {
  static const std::map<std::string, std::string> kEnds{
      {"upper_arm_l", "forearm_l"}, {"forearm_l", "hand_l"}, {"upper_arm_r", "forearm_r"},
      {"forearm_r", "hand_r"},      {"thigh_l", "shank_l"},  {"shank_l", "foot_l"},
      {"thigh_r", "shank_r"},       {"shank_r", "foot_r"}};
  return kEnds;
}

int require_joint(const MocapClip& clip, const std::string& key, const std::string& name) {
  const int j = clip.joint_index(name);
  if (j < 0)
    throw MappingError(key,
                       "the mapping's joint \"" + name + "\" (for " + key + ") is not in the file");
  return j;
}

/// Source joints of a mapping key; empty when the key is absent or derived.
std::vector<int> mapped_joints(const MocapClip& clip, const SkeletonMapping& mapping,
                               const std::string& key) {
  std::vector<int> out;
  const auto it = mapping.joints.find(key);
  if (it == mapping.joints.end()) return out;
  for (const std::string& name : it->second)
    out.push_back(require_joint(clip, key, name));
  return out;
}

std::vector<int> ancestors_and_self(const MocapClip& clip, int joint) {
  std::vector<int> out;
  for (int j = joint; j >= 0; j = clip.joints[j].parent)
    out.push_back(j);
  return out;
}

int lowest_common_ancestor(const MocapClip& clip, int a, int b) {
  const std::vector<int> up_a = ancestors_and_self(clip, a);
  const std::set<int> set_a(up_a.begin(), up_a.end());
  for (int j = b; j >= 0; j = clip.joints[j].parent)
    if (set_a.count(j)) return j;
  return 0;
}

/// The tree path from a to b, both included.
std::vector<int> tree_path(const MocapClip& clip, int a, int b) {
  const int top = lowest_common_ancestor(clip, a, b);
  std::vector<int> up, down;
  for (int j = a; j != top; j = clip.joints[j].parent)
    up.push_back(j);
  up.push_back(top);
  for (int j = b; j != top; j = clip.joints[j].parent)
    down.push_back(j);
  up.insert(up.end(), down.rbegin(), down.rend());
  return up;
}

bool is_descendant(const MocapClip& clip, int joint, int ancestor) {
  for (int j = joint; j >= 0; j = clip.joints[j].parent)
    if (j == ancestor) return true;
  return false;
}

std::string axis_name(const Eigen::Vector3d& axis) {
  const char* names[] = {"x", "y", "z"};
  int i = 0;
  axis.cwiseAbs().maxCoeff(&i);
  return std::string(axis[i] < 0 ? "-" : "+") + names[i];
}

/// The coordinate axis (±x, ±y, ±z) closest to a direction.
Eigen::Vector3d snap_to_axis(const Eigen::Vector3d& v) {
  int i = 0;
  v.cwiseAbs().maxCoeff(&i);
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  out[i] = v[i] < 0 ? -1.0 : 1.0;
  return out;
}

struct UnitCandidate {
  const char* name;
  double metres;
};

/// The unit that makes the rest skeleton's height closest (in ratio) to a person's, 1.7 m.
/// Heights of 1.2-2.2 m are told apart from each other unit by a factor of 2.54 or more.
void detect_unit(CaptureAxes& axes, double height_in_units) {
  static const UnitCandidate kUnits[] = {{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"inch", 0.0254}};
  double best = 1e300;
  for (const UnitCandidate& u : kUnits) {
    const double miss = std::abs(std::log(height_in_units * u.metres / 1.7));
    if (miss < best) best = miss, axes.metres_per_unit = u.metres, axes.unit = u.name;
  }
}

/// The bone of `joint` when no mapped joint ends it: its longest non-helper child or End Site.
std::pair<Eigen::Vector3d, std::string> longest_bone(const MocapClip& clip, int joint) {
  Eigen::Vector3d best = Eigen::Vector3d::Zero();
  std::string to;
  for (int child : clip.children(joint)) {
    if (is_helper_joint(clip, child)) continue;
    if (clip.joints[child].offset.norm() > best.norm())
      best = clip.joints[child].offset, to = clip.joints[child].name;
  }
  for (const Eigen::Vector3d& site : clip.joints[joint].end_sites)
    if (site.norm() > best.norm()) best = site, to = "End Site of " + clip.joints[joint].name;
  return {best, to};
}

std::string join_names(const MocapClip& clip, const std::vector<int>& joints) {
  std::string out;
  for (std::size_t i = 0; i < joints.size(); ++i)
    out += (i == 0 ? "" : i + 1 == joints.size() ? " and " : ", ") + clip.joints[joints[i]].name;
  return out;
}

Eigen::Vector3d model_long_axis(const Segment& segment) {
  return Eigen::Vector3d(0, segment.shape.length < 0 ? -1.0 : 1.0, 0);
}

bool is_limb(const std::string& segment) {
  return limb_ends().count(segment) > 0;
}

void collect_foot_points(const MocapClip& clip, int base, bool include_base,
                         std::vector<std::pair<int, Eigen::Vector3d>>& out) {
  if (include_base) out.emplace_back(base, Eigen::Vector3d::Zero());
  for (const Eigen::Vector3d& site : clip.joints[base].end_sites)
    out.emplace_back(base, site);
  for (int child : clip.children(base))
    if (!is_helper_joint(clip, child)) collect_foot_points(clip, child, true, out);
}

}  // namespace

const std::vector<std::string>& retargeted_segments() {
  static const std::vector<std::string> kSegments{
      "abdomen", "pelvis",  "thorax", "upper_arm_l", "forearm_l", "upper_arm_r", "forearm_r",
      "thigh_l", "shank_l", "foot_l", "thigh_r",     "shank_r",   "foot_r"};
  return kSegments;
}

Eigen::Quaterniond shortest_rotation(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  const Eigen::Vector3d a = from.normalized(), b = to.normalized();
  const double c = a.dot(b);
  if (c < -1.0 + 1e-12) {
    // Opposite: half a turn about an axis perpendicular to both, x when it is.
    Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
    if (std::abs(a.dot(axis)) > 0.9) axis = Eigen::Vector3d::UnitZ();
    axis = (axis - a * a.dot(axis)).normalized();
    return Eigen::Quaterniond(Eigen::AngleAxisd(kPi, axis));
  }
  return Eigen::Quaterniond::FromTwoVectors(a, b);
}

Eigen::Quaterniond average_rotation(const std::vector<Eigen::Quaterniond>& rotations,
                                    const std::vector<double>& weights) {
  Eigen::Vector4d sum = Eigen::Vector4d::Zero();
  for (std::size_t i = 0; i < rotations.size(); ++i) {
    const Eigen::Vector4d c = rotations[i].coeffs();
    sum += weights[i] * (c.dot(rotations[0].coeffs()) < 0 ? -c : c);
  }
  Eigen::Quaterniond q;
  q.coeffs() = sum.normalized();
  return q;
}

Retargeting plan_retargeting(const MocapClip& clip, const BodyModel& model,
                             const SkeletonMapping& mapping) {
  for (const std::string& name : retargeted_segments())
    if (model.segment_index(name) < 0)
      throw CaptureError(CapturePart::kModel,
                         "model \"" + model.name + "\" has no segment \"" + name +
                             "\" (a capture maps onto the 13 segments of docs/formats.md)");
  Retargeting plan;
  plan.mapping = mapping;
  const MocapPose rest = mocap_rest_pose(clip);

  std::map<std::string, std::vector<int>> joints;
  for (const std::string& key : mapping_keys())
    joints[key] = mapped_joints(clip, mapping, key);
  for (const char* key : {"pelvis", "upper_arm_l", "upper_arm_r", "forearm_l", "forearm_r",
                          "thigh_l", "thigh_r", "shank_l", "shank_r"})
    if (joints[key].size() != 1)
      throw MappingError(key, std::string("the mapping must give one source joint for ") + key);
  plan.pelvis_joint = joints["pelvis"][0];
  plan.hip_joints = {joints["thigh_l"][0], joints["thigh_r"][0]};

  // The chest: given, or where the two arms' chains meet.
  std::vector<int> thorax = joints["thorax"];
  const bool thorax_given = !thorax.empty();
  if (!thorax_given)
    thorax = {lowest_common_ancestor(clip, joints["upper_arm_l"][0], joints["upper_arm_r"][0])};
  plan.thorax_joint = thorax.front();

  // Axes: up from the rest trunk (snapped to the file's axis), left from the hips.
  CaptureAxes& axes = plan.axes;
  if (mapping.up) {
    axes.up = mapping.up->normalized();
    axes.up_detected = false;
  } else {
    const Eigen::Vector3d trunk =
        rest.world_position[plan.thorax_joint] - rest.world_position[plan.pelvis_joint];
    const Eigen::Vector3d hips_to_arms =
        0.5 * (rest.world_position[joints["upper_arm_l"][0]] +
               rest.world_position[joints["upper_arm_r"][0]]) -
        0.5 * (rest.world_position[plan.hip_joints[0]] + rest.world_position[plan.hip_joints[1]]);
    const Eigen::Vector3d v = trunk.norm() > 1e-6 * hips_to_arms.norm() ? trunk : hips_to_arms;
    if (v.norm() == 0.0)
      throw CaptureError(CapturePart::kSkeleton, "the rest skeleton has its shoulders at its hips");
    axes.up = snap_to_axis(v);
  }
  axes.up_name = axis_name(axes.up);
  Eigen::Vector3d left =
      rest.world_position[plan.hip_joints[0]] - rest.world_position[plan.hip_joints[1]];
  left -= axes.up * axes.up.dot(left);
  if (left.norm() < 1e-9) {
    left = rest.world_position[joints["upper_arm_l"][0]] -
           rest.world_position[joints["upper_arm_r"][0]];
    left -= axes.up * axes.up.dot(left);
  }
  if (left.norm() < 1e-9)
    throw CaptureError(
        CapturePart::kSkeleton,
        "the rest skeleton has its left and right hips (and shoulders) at one point");
  left.normalize();
  axes.saltus_from_source.row(0) = left.transpose();
  axes.saltus_from_source.row(1) = axes.up.transpose();
  axes.saltus_from_source.row(2) = left.cross(axes.up).transpose();

  // Units from the rest skeleton's height along up (helpers excluded: some have broken offsets).
  double lo = 1e300, hi = -1e300;
  for (int j = 0; j < clip.joint_count(); ++j) {
    if (is_helper_joint(clip, j)) continue;
    std::vector<Eigen::Vector3d> points{rest.world_position[j]};
    for (const Eigen::Vector3d& site : clip.joints[j].end_sites)
      points.push_back(rest.world_position[j] + site);
    for (const Eigen::Vector3d& p : points) {
      lo = std::min(lo, axes.up.dot(p));
      hi = std::max(hi, axes.up.dot(p));
    }
  }
  if (mapping.metres_per_unit) {
    axes.metres_per_unit = *mapping.metres_per_unit;
    axes.unit = "given";
    axes.unit_detected = false;
  } else {
    if (!(hi > lo)) throw CaptureError(CapturePart::kSkeleton, "the rest skeleton has no height");
    detect_unit(axes, hi - lo);
  }
  axes.rest_height_m = (hi - lo) * axes.metres_per_unit;

  const Eigen::Quaterniond a(axes.saltus_from_source);
  plan.drives.resize(model.segments.size());
  for (const std::string& name : retargeted_segments()) {
    const int s = model.segment_index(name);
    SegmentDrive& drive = plan.drives[s];
    std::vector<int> source = name == "thorax" ? thorax : joints[name];
    if (name == "abdomen" && mapping.joints.count("abdomen") == 0) {
      // Spine joints between the pelvis and the chest, each weighted by its bone's length.
      const std::vector<int> path = tree_path(clip, plan.pelvis_joint, plan.thorax_joint);
      source.clear();
      drive.weights.clear();
      for (std::size_t i = 1; i + 1 < path.size(); ++i) {
        source.push_back(path[i]);
        drive.weights.push_back(
            (rest.world_position[path[i + 1]] - rest.world_position[path[i]]).norm());
      }
    }
    if (source.empty()) {
      if (name == "abdomen") {
        drive.kind = SegmentDrive::Kind::kHalfway;
        drive.description = "halfway between " + clip.joints[plan.pelvis_joint].name + " and " +
                            clip.joints[plan.thorax_joint].name;
      } else {
        drive.kind = SegmentDrive::Kind::kFollows;
        drive.description =
            "no source joint: follows " + model.segments[model.segments[s].parent].name;
      }
      continue;
    }
    drive.joints = source;
    if (source.size() == 1) {
      drive.kind = SegmentDrive::Kind::kJoint;
      drive.weights = {1.0};
      drive.description = clip.joints[source[0]].name;
    } else {
      drive.kind = SegmentDrive::Kind::kAverage;
      if (drive.weights.size() != source.size()) drive.weights.assign(source.size(), 1.0);
      double total = 0.0;
      for (double w : drive.weights)
        total += w;
      for (double& w : drive.weights)
        w = total > 0 ? w / total : 1.0 / source.size();
      drive.description = "average of " + join_names(clip, source);
    }
    if (name == "thorax" && !thorax_given) drive.description += " (where the arms' chains meet)";
    if (!is_limb(name)) continue;

    // Limbs: the long axis follows the bone from this joint to the next mapped one.
    const int j = source.front();
    const std::vector<int>& end = joints[limb_ends().at(name)];
    Eigen::Vector3d d;
    if (!end.empty()) {
      if (!is_descendant(clip, end.front(), j))
        throw MappingError(limb_ends().at(name), "the mapping's " + limb_ends().at(name) +
                                                     " joint \"" + clip.joints[end.front()].name +
                                                     "\" is not below the " + name + " joint \"" +
                                                     clip.joints[j].name + "\"");
      d = rest.world_position[end.front()] - rest.world_position[j];
      drive.rest_direction_to = clip.joints[end.front()].name;
    } else {
      std::tie(d, drive.rest_direction_to) = longest_bone(clip, j);
    }
    if (d.norm() < 1e-9)
      throw MappingError(name, "the " + name + " bone (joint \"" + clip.joints[j].name +
                                   "\") has no length in the rest pose");
    drive.along_bone = true;
    drive.rest_direction = d.normalized();
    drive.rest_correction =
        shortest_rotation(model_long_axis(model.segments[s]), a * drive.rest_direction);
  }

  // The model's hip centre in its pelvis frame.
  const int thigh_l = model.segment_index("thigh_l"), thigh_r = model.segment_index("thigh_r");
  const int pelvis = model.segment_index("pelvis");
  if (model.segments[thigh_l].parent != pelvis || model.segments[thigh_r].parent != pelvis)
    throw CaptureError(CapturePart::kModel,
                       "model \"" + model.name + "\": the thighs must hang from the pelvis");
  plan.model_hip_centre =
      0.5 * (model.segments[thigh_l].joint_position + model.segments[thigh_r].joint_position);

  // Foot points: the foot joint and what hangs below it (toes, End Sites); without a foot
  // joint, what hangs below the shank.
  for (int side = 0; side < 2; ++side) {
    const std::string suffix = side == 0 ? "_l" : "_r";
    const std::vector<int>& foot = joints["foot" + suffix];
    if (!foot.empty())
      collect_foot_points(clip, foot.front(), true, plan.foot_points[side]);
    else
      collect_foot_points(clip, joints["shank" + suffix].front(), false, plan.foot_points[side]);
    if (plan.foot_points[side].empty())
      throw CaptureError(CapturePart::kSkeleton,
                         "the " + std::string(side == 0 ? "left" : "right") +
                             " leg has nothing below the knee (no foot joint or End Site)");
  }

  std::set<int> used{plan.pelvis_joint, plan.thorax_joint};
  for (const SegmentDrive& drive : plan.drives)
    used.insert(drive.joints.begin(), drive.joints.end());
  for (const char* key : {"hand_l", "hand_r", "foot_l", "foot_r"})
    used.insert(joints[key].begin(), joints[key].end());
  for (int j = 0; j < clip.joint_count(); ++j)
    if (!used.count(j))
      plan.unused_joints.emplace_back(clip.joints[j].name, unused_joint_reason(clip, j));
  return plan;
}

RetargetedFrame retarget_frame(const MocapClip& clip, const BodyModel& model,
                               const Retargeting& plan, int frame) {
  const MocapPose pose = mocap_pose(clip, frame);
  const Eigen::Matrix3d& a_matrix = plan.axes.saltus_from_source;
  const Eigen::Quaterniond a(a_matrix);
  const double scale = plan.axes.metres_per_unit;
  auto in_saltus = [&](const Eigen::Quaterniond& w) { return a * w * a.conjugate(); };

  RetargetedFrame out;
  out.world_rotation.resize(model.segments.size());
  out.joint_rotation.resize(model.segments.size());
  for (std::size_t s = 0; s < model.segments.size(); ++s) {
    const SegmentDrive& drive = plan.drives[s];
    Eigen::Quaterniond r;
    switch (drive.kind) {
      case SegmentDrive::Kind::kJoint:
        r = in_saltus(pose.world_rotation[drive.joints[0]]);
        break;
      case SegmentDrive::Kind::kAverage: {
        std::vector<Eigen::Quaterniond> rotations;
        for (int j : drive.joints)
          rotations.push_back(pose.world_rotation[j]);
        r = in_saltus(average_rotation(rotations, drive.weights));
        break;
      }
      case SegmentDrive::Kind::kHalfway:
        r = in_saltus(pose.world_rotation[plan.pelvis_joint].slerp(
            0.5, pose.world_rotation[plan.thorax_joint]));
        break;
      case SegmentDrive::Kind::kFollows:
        r = out.world_rotation[model.segments[s].parent];
        break;
    }
    out.world_rotation[s] = (r * drive.rest_correction).normalized();
    const int parent = model.segments[s].parent;
    out.joint_rotation[s] =
        parent < 0 ? out.world_rotation[s]
                   : (out.world_rotation[parent].conjugate() * out.world_rotation[s]).normalized();
  }
  const Eigen::Vector3d hip_centre =
      scale * a_matrix *
      (0.5 * (pose.world_position[plan.hip_joints[0]] + pose.world_position[plan.hip_joints[1]]));
  const int pelvis = model.segment_index("pelvis");
  out.root_position = hip_centre - out.world_rotation[pelvis] * plan.model_hip_centre;
  for (int side = 0; side < 2; ++side)
    for (const auto& [joint, offset] : plan.foot_points[side])
      out.foot_points[side].push_back(
          scale * a_matrix * (pose.world_position[joint] + pose.world_rotation[joint] * offset));
  return out;
}

std::vector<RetargetedFrame> retarget_clip(const MocapClip& clip, const BodyModel& model,
                                           const Retargeting& plan) {
  std::vector<RetargetedFrame> frames;
  frames.reserve(clip.frames.size());
  for (int f = 0; f < clip.frame_count(); ++f) {
    RetargetedFrame frame = retarget_frame(clip, model, plan, f);
    // Keep each rotation's sign continuous from frame to frame (same rotations, tidier files).
    if (!frames.empty()) {
      const RetargetedFrame& previous = frames.back();
      for (std::size_t s = 0; s < frame.joint_rotation.size(); ++s) {
        if (frame.joint_rotation[s].coeffs().dot(previous.joint_rotation[s].coeffs()) < 0)
          frame.joint_rotation[s].coeffs() *= -1.0;
        if (frame.world_rotation[s].coeffs().dot(previous.world_rotation[s].coeffs()) < 0)
          frame.world_rotation[s].coeffs() *= -1.0;
      }
    }
    frames.push_back(std::move(frame));
  }
  return frames;
}

void apply_heading(std::vector<RetargetedFrame>& frames, double yaw) {
  const Eigen::Quaterniond y(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()));
  for (RetargetedFrame& frame : frames) {
    for (Eigen::Quaterniond& r : frame.world_rotation)
      r = y * r;
    frame.joint_rotation[0] = y * frame.joint_rotation[0];
    frame.root_position = y * frame.root_position;
    for (auto& points : frame.foot_points)
      for (Eigen::Vector3d& p : points)
        p = y * p;
  }
}

}  // namespace saltus
