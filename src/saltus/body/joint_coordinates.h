#pragma once
/// @file
/// Each ball joint's three anatomical coordinates (flexion-extension, ab-adduction, axial
/// rotation), the one definition behind the strength report and the OpenSim export.
///
/// The joint's rotation parent_from_child is split into Cardan angles about the segment axes in
/// the order x, z, y: R = Rx(a)·Rz(b)·Ry(c), x being the model's left axis, z forward and y the
/// segment's long axis (docs/method.md, "Joint coordinates"). With a limb hanging, a is the
/// sagittal swing, b the frontal one and c the twist about the limb; with the limb raised 90° in
/// flexion, b becomes the horizontal ab-adduction, as in the strength tables. Each coordinate is
/// sign·angle + offset, so that flexion, adduction and internal rotation read positive on both
/// sides (the ISB's and OpenSim's habit), and the ankle reads 0 at neutral.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <string>

#include "saltus/body/body_model.h"

namespace saltus {

/// The Cardan axis a coordinate turns about, in the order of the decomposition.
enum class CardanAxis { x = 0, z = 1, y = 2 };

/// One rotational coordinate of a ball joint: value = sign · Cardan angle + offset (rad).
struct JointCoordinate {
  std::string name;      ///< "hip_flexion_r": unique in a model, OpenSim-like
  std::string positive;  ///< the direction in which the value grows ("flexion")
  std::string negative;  ///< the opposite direction ("extension")
  CardanAxis axis = CardanAxis::x;
  double sign = 1.0;        ///< +1 or -1
  double offset_rad = 0.0;  ///< the value at the model's identity pose
};

/// A ball joint's three coordinates, in Cardan order (x, z, y), and what kind of joint it is.
struct JointCoordinates {
  std::string kind;  ///< "hip", "knee", "ankle", "shoulder", "elbow", "lumbar", "thoracic", "joint"
  std::array<JointCoordinate, 3> coordinates;
};

/// The model's identity foot hangs along the shank: a pointed foot, read as this much plantar
/// flexion (the end of the normal range, 50°), so the ankle coordinate is 0 at neutral.
inline constexpr double kPointedFootPlantarFlexionRad = 0.872664625997164788;  // 50°

/// The coordinates of the joint between segment `segment` (>= 1) and its parent, from the joint's
/// name (hip_l, knee_r, ankle_l, shoulder_r, elbow_l, lumbar, thoracic; a joint of another name
/// gets "<joint>_x", "<joint>_z", "<joint>_y" with sign +1).
JointCoordinates joint_coordinates(const BodyModel& model, int segment);

/// Cardan angles (a, b, c) of R = Rx(a)·Rz(b)·Ry(c) = parent_from_child, rad; b in [-π/2, π/2].
Eigen::Vector3d cardan_xzy(const Eigen::Quaterniond& parent_from_child);

/// The rotation of Cardan angles (a, b, c): the inverse of cardan_xzy.
Eigen::Quaterniond from_cardan_xzy(const Eigen::Vector3d& angles);

/// The 3x3 map from Cardan rates (ȧ, ḃ, ċ) to the relative angular velocity in the child frame:
/// ω_child = E(b, c)·(ȧ, ḃ, ċ). Singular at b = ±π/2.
Eigen::Matrix3d cardan_rate_matrix(const Eigen::Vector3d& angles);

/// The three coordinates' values (rad), rates (rad/s) and generalised moments (N·m) of a joint
/// state, in Cardan order. The generalised moment of a coordinate is the moment's component that
/// does work on that coordinate (n·ω = Σ moment_i · rate_i), what OpenSim reports as the
/// coordinate's force; positive where it drives the coordinate's positive direction.
struct JointCoordinateState {
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
  Eigen::Vector3d rate = Eigen::Vector3d::Zero();
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
};

/// @param parent_from_child  the joint's rotation
/// @param omega_child        relative angular velocity, child frame, rad/s
/// @param moment_child       moment the parent exerts on the child at the joint, child frame, N·m
JointCoordinateState joint_coordinate_state(const JointCoordinates& coordinates,
                                            const Eigen::Quaterniond& parent_from_child,
                                            const Eigen::Vector3d& omega_child,
                                            const Eigen::Vector3d& moment_child);

/// The rotation parent_from_child at the given coordinate values (rad, Cardan order).
Eigen::Quaterniond joint_rotation_from_coordinates(const JointCoordinates& coordinates,
                                                   const Eigen::Vector3d& values);

}  // namespace saltus
