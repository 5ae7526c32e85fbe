#pragma once
/// @file
/// The articulated body: segments in topological order (parent before child), each attached to
/// its parent by a ball joint, the root (abdomen) attached to the world by a free joint.
/// A BodyModel is constant during an algorithm; algorithms are free functions taking it by const
/// reference (Pinocchio's Model/Data split).

#include <Eigen/Core>
#include <string>
#include <vector>

namespace saltus {

/// One piece of a segment's drawing (a head, a hand, a foot), in segment coordinates.
struct ShapePart {
  std::string name;                ///< what it is ("head", "hand"), for people and colours
  std::string type = "ellipsoid";  ///< "ellipsoid" or "capsule"
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< m
  /// Ellipsoid: semi-axes along the segment's x, y, z, m (> 0).
  Eigen::Vector3d radii = Eigen::Vector3d::Zero();
  double length = 0.0;  ///< capsule: cylinder length along the segment's y axis, m (signed)
  double radius = 0.0;  ///< capsule: m (> 0)
};

/// Drawing shape of a segment, in segment coordinates. Not used by any physics.
struct SegmentShape {
  std::string type = "capsule";  ///< "capsule", "ellipsoid" or "box"
  double length = 0.0;           ///< m, along the segment's y axis (signed: negative = -y)
  double radius = 0.0;           ///< m
  /// Optional: what to draw instead of the single shape above, which stays the segment's
  /// extent (the thorax's capsule reaches the top of the head it carries). Files without
  /// "parts" draw the single shape, as before.
  std::vector<ShapePart> parts;
};

/// Whose strength a model has (body/joint_strength.h builds its curves; docs/method.md,
/// "Strength"): a population's by sex and age, or the elite gymnast's, scaled to the model's
/// mass and standing height; any joint and direction may be given as measured.
struct StrengthSpec {
  /// "population": Anderson et al. 2007's hip, knee and ankle for `sex` and `age_years`, the
  /// gymnast's upper body and trunk scaled to that population; "elite-gymnast": every joint the
  /// gymnast's.
  std::string reference = "population";
  bool female = false;
  double age_years = 21.0;  ///< the age groups' rule: joint_strength.h
  /// A measured peak isometric moment: `joint` is a kind ("hip", both sides) or a joint
  /// ("hip_l"); `direction` one of its coordinates' directions ("extension").
  struct Measured {
    std::string joint;
    std::string direction;
    double peak_moment_Nm = 0.0;
  };
  std::vector<Measured> measured;
};

struct Segment {
  std::string name;   ///< e.g. "thigh_l"
  int parent = -1;    ///< index into BodyModel::segments, -1 for the root
  std::string joint;  ///< name of the joint to the parent, e.g. "hip_l" (root: "root")
  /// Joint centre in the parent's frame, m. Root: ignored (world placement is a motion variable).
  Eigen::Vector3d joint_position = Eigen::Vector3d::Zero();
  double mass = 0.0;                              ///< kg, > 0
  Eigen::Vector3d com = Eigen::Vector3d::Zero();  ///< centre of mass, segment frame, m
  /// About the CoM, segment axes, kg·m². In files: 3 principal moments, or 6 values
  /// [Ixx, Iyy, Izz, Ixy, Ixz, Iyz] that are the matrix entries themselves (I(0,1) = Ixy), not
  /// the negated products of inertia.
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  SegmentShape shape;
};

/// A body model: fixed topology and mass parameters.
struct BodyModel {
  std::string name;
  std::string source;  ///< where the numbers come from (citation), free text
  std::vector<Segment> segments;
  StrengthSpec strength;  ///< whose strength the athlete has

  int size() const { return static_cast<int>(segments.size()); }
  double total_mass() const;
  /// Index of the segment whose joint has this name, or -1.
  int joint_index(const std::string& joint_name) const;
  /// Index of the segment with this name, or -1.
  int segment_index(const std::string& segment_name) const;
};

/// A copy of `model` with one segment's (or, for segment == "", every segment's) mass and inertia
/// multiplied by `factor` (> 0). Used for mass-sensitivity studies.
BodyModel scale_segment_mass(const BodyModel& model, const std::string& segment, double factor);

}  // namespace saltus
