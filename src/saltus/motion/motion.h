#pragma once
/// @file
/// Keyframed motions (docs/formats.md, "Motion"). Their files are read and written in
/// formats/motion_file.h.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"

namespace saltus {

/// Take-off state of the whole body's centre of mass (world frame).
struct Takeoff {
  Eigen::Vector3d com_position = Eigen::Vector3d(0, 1, 0);  ///< m
  Eigen::Vector3d com_velocity = Eigen::Vector3d::Zero();   ///< m/s
  /// Angular momentum about the CoM, world frame, kg·m²/s. When absent, free-flight simulation
  /// uses the constant that best fits the motion's own L(t) over the flight (its time average,
  /// evaluation/flight_state.h), not L(0).
  std::optional<Eigen::Vector3d> angular_momentum;
};

/// Keyframe tolerances of the relaxed model (paper eqs. 2-3: ε1, ε2).
struct Tolerances {
  double translation_m = 0.25;  ///< ε1, per coordinate of the root translation
  double quaternion = 0.05;     ///< ε2, ‖Q − Q̄‖ after sign alignment
};

struct Keyframe {
  double time = 0.0;  ///< s
  /// One rotation per model segment, indexed like BodyModel::segments: segment i's frame relative
  /// to its parent's (the root's: relative to the world). Unit norm.
  std::vector<Eigen::Quaterniond> rotations;
  /// Optional root (abdomen origin) position, world, m. Default: from the CoM parabola (§5.3).
  std::optional<Eigen::Vector3d> root_position;
};

/// A fitted trajectory stored with an optimised motion so it reloads exactly
/// ("spline" member of the motion file). Knots are the full clamped cubic knot vector.
struct StoredSpline {
  std::vector<double> knots;
  std::vector<Eigen::Vector3d> root_translation;               ///< control points
  std::vector<std::vector<Eigen::Quaterniond>> joint_control;  ///< [segment][control index]
};

struct Motion {
  std::string name;
  /// Free text for people (the file's "description"): kept through edits and optimisation and
  /// written back, so a saved or optimised motion still says what it is.
  std::string description;
  std::string model;  ///< the "model" field as written (name or relative path)
  Takeoff takeoff;
  Tolerances tolerances;
  std::vector<Keyframe> keyframes;  ///< at least 2; times strictly increase, first 0, last T
  std::optional<StoredSpline> spline;

  double flight_time() const { return keyframes.empty() ? 0.0 : keyframes.back().time; }
};

/// A motion with the body model it refers to.
/// How a motion's take-off state was carried over to another athlete than its own (`--model`
/// with `--takeoff`): the same keyframes and times, the same take-off CoM position and velocity,
/// and the angular momentum by `rule`.
struct TakeoffAdaptation {
  std::string rule;       ///< "same spin" or "same angular momentum"
  std::string own_model;  ///< the model the motion was made for
  Eigen::Vector3d own_angular_momentum = Eigen::Vector3d::Zero();  ///< on it, kg·m²/s
  Eigen::Vector3d angular_momentum = Eigen::Vector3d::Zero();      ///< on this athlete
};

struct MotionFile {
  std::string path;  ///< the motion file it came from ("" if built in memory)
  Motion motion;
  BodyModel model;
  /// Set when the motion is flown by another athlete than its own (load_motion_for_athlete).
  std::optional<TakeoffAdaptation> takeoff_adaptation;
};

}  // namespace saltus
