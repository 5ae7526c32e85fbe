#include "saltus/body/joint_coordinates.h"

#include <algorithm>
#include <cmath>

#include "saltus/body/segment_names.h"

namespace saltus {

namespace {

JointCoordinate coordinate(std::string name, std::string positive, std::string negative,
                           CardanAxis axis, double sign, double offset_rad = 0.0) {
  return {std::move(name), std::move(positive), std::move(negative), axis, sign, offset_rad};
}

/// The signs follow from the model's axes (x left, y up or along the limb, z forward), worked out
/// in docs/method.md ("Joint coordinates"): a limb hanging along -y swings forward for a negative
/// a; it moves to the left (+x) for a positive b, which is abduction on the left side and
/// adduction on the right; its front turns to the left for a positive c, which is external
/// rotation on the left and internal on the right.
JointCoordinates coordinates_of(const std::string& joint) {
  const auto [side, base] = split_side(joint);
  const std::string suffix = side.empty() ? "" : (side == "left" ? "_l" : "_r");
  const double medial = side == "left" ? -1.0 : 1.0;  // towards the midline, for b and c
  JointCoordinates j;
  j.kind = base;
  if (!side.empty() && base == "hip") {
    j.coordinates = {
        coordinate("hip_flexion" + suffix, "flexion", "extension", CardanAxis::x, -1),
        coordinate("hip_adduction" + suffix, "adduction", "abduction", CardanAxis::z, medial),
        coordinate("hip_rotation" + suffix, "internal rotation", "external rotation", CardanAxis::y,
                   medial)};
  } else if (!side.empty() && base == "knee") {
    j.coordinates = {
        coordinate("knee_flexion" + suffix, "flexion", "extension", CardanAxis::x, 1),
        coordinate("knee_adduction" + suffix, "adduction", "abduction", CardanAxis::z, medial),
        coordinate("knee_rotation" + suffix, "internal rotation", "external rotation",
                   CardanAxis::y, medial)};
  } else if (!side.empty() && base == "ankle") {
    // Dorsiflexion swings the foot forward (a < 0); identity is the pointed foot.
    j.coordinates = {
        coordinate("ankle_dorsiflexion" + suffix, "dorsiflexion", "plantar flexion", CardanAxis::x,
                   -1, -kPointedFootPlantarFlexionRad),
        coordinate("ankle_adduction" + suffix, "adduction", "abduction", CardanAxis::z, medial),
        coordinate("ankle_rotation" + suffix, "internal rotation", "external rotation",
                   CardanAxis::y, medial)};
  } else if (!side.empty() && base == "shoulder") {
    j.coordinates = {
        coordinate("shoulder_flexion" + suffix, "flexion", "extension", CardanAxis::x, -1),
        coordinate("shoulder_adduction" + suffix, "adduction", "abduction", CardanAxis::z, medial),
        coordinate("shoulder_rotation" + suffix, "internal rotation", "external rotation",
                   CardanAxis::y, medial)};
  } else if (!side.empty() && base == "elbow") {
    j.coordinates = {
        coordinate("elbow_flexion" + suffix, "flexion", "extension", CardanAxis::x, -1),
        coordinate("elbow_adduction" + suffix, "adduction", "abduction", CardanAxis::z, medial),
        coordinate("elbow_pronation" + suffix, "pronation", "supination", CardanAxis::y, medial)};
  } else if (side.empty() && base == "lumbar") {
    // The pelvis below the abdomen: the trunk bending forward tilts the pelvis back (a < 0).
    j.coordinates = {
        coordinate("lumbar_extension", "extension", "flexion", CardanAxis::x, 1),
        coordinate("lumbar_bending", "bending left", "bending right", CardanAxis::z, 1),
        coordinate("lumbar_rotation", "rotation left", "rotation right", CardanAxis::y, -1)};
  } else if (side.empty() && base == "thoracic") {
    // The thorax above the abdomen: bending forward tips it forward (a > 0).
    j.coordinates = {
        coordinate("thoracic_extension", "extension", "flexion", CardanAxis::x, -1),
        coordinate("thoracic_bending", "bending left", "bending right", CardanAxis::z, -1),
        coordinate("thoracic_rotation", "rotation left", "rotation right", CardanAxis::y, 1)};
  } else {
    j.kind = "joint";
    j.coordinates = {coordinate(joint + "_x", "positive x", "negative x", CardanAxis::x, 1),
                     coordinate(joint + "_z", "positive z", "negative z", CardanAxis::z, 1),
                     coordinate(joint + "_y", "positive y", "negative y", CardanAxis::y, 1)};
  }
  return j;
}

}  // namespace

JointCoordinates joint_coordinates(const BodyModel& model, int segment) {
  return coordinates_of(model.segments.at(segment).joint);
}

Eigen::Vector3d cardan_xzy(const Eigen::Quaterniond& parent_from_child) {
  const Eigen::Matrix3d r = parent_from_child.normalized().toRotationMatrix();
  // R = Rx(a)·Rz(b)·Ry(c): R01 = -sin b, (R21, R11) = cos b (sin a, cos a),
  // (R02, R00) = cos b (sin c, cos c).
  const double b = std::asin(std::clamp(-r(0, 1), -1.0, 1.0));
  const double a = std::atan2(r(2, 1), r(1, 1));
  const double c = std::atan2(r(0, 2), r(0, 0));
  return {a, b, c};
}

Eigen::Quaterniond from_cardan_xzy(const Eigen::Vector3d& angles) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angles[0], Eigen::Vector3d::UnitX()) *
                            Eigen::AngleAxisd(angles[1], Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(angles[2], Eigen::Vector3d::UnitY()));
}

Eigen::Matrix3d cardan_rate_matrix(const Eigen::Vector3d& angles) {
  // ω_child = Ry(c)ᵀ·Rz(b)ᵀ·e_x·ȧ + Ry(c)ᵀ·e_z·ḃ + e_y·ċ.
  const Eigen::Matrix3d ry_t =
      Eigen::AngleAxisd(angles[2], Eigen::Vector3d::UnitY()).toRotationMatrix().transpose();
  const Eigen::Matrix3d rz_t =
      Eigen::AngleAxisd(angles[1], Eigen::Vector3d::UnitZ()).toRotationMatrix().transpose();
  Eigen::Matrix3d e;
  e.col(0) = ry_t * rz_t * Eigen::Vector3d::UnitX();
  e.col(1) = ry_t * Eigen::Vector3d::UnitZ();
  e.col(2) = Eigen::Vector3d::UnitY();
  return e;
}

JointCoordinateState joint_coordinate_state(const JointCoordinates& coordinates,
                                            const Eigen::Quaterniond& parent_from_child,
                                            const Eigen::Vector3d& omega_child,
                                            const Eigen::Vector3d& moment_child) {
  const Eigen::Vector3d angles = cardan_xzy(parent_from_child);
  const Eigen::Matrix3d e = cardan_rate_matrix(angles);
  // Rates from ω = E·θ̇; the moments conjugate to them, E'·n, so that n·ω = Σ τ_i θ̇_i.
  const Eigen::Vector3d rates = e.fullPivLu().solve(omega_child);
  const Eigen::Vector3d moments = e.transpose() * moment_child;
  JointCoordinateState state;
  for (int i = 0; i < 3; ++i) {
    const JointCoordinate& c = coordinates.coordinates[i];
    state.value[i] = c.sign * angles[i] + c.offset_rad;
    state.rate[i] = c.sign * rates[i];
    state.moment[i] = c.sign * moments[i];
  }
  return state;
}

Eigen::Quaterniond joint_rotation_from_coordinates(const JointCoordinates& coordinates,
                                                   const Eigen::Vector3d& values) {
  Eigen::Vector3d angles;
  for (int i = 0; i < 3; ++i) {
    const JointCoordinate& c = coordinates.coordinates[i];
    angles[i] = (values[i] - c.offset_rad) / c.sign;
  }
  return from_cardan_xzy(angles);
}

}  // namespace saltus
