#pragma once
/// @file
/// Mass, centre of mass and inertia of rigid pieces, composed exactly (parallel-axis theorem),
/// and of a whole model in its standing pose (every joint at identity). Used to build models
/// from anthropometric tables and to describe a model to people (`saltus model info`).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"

namespace saltus {

/// A rigid piece: mass (kg), CoM (m) and inertia about that CoM (kg·m²), both in one frame.
struct RigidMass {
  double mass = 0.0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

/// A piece of `mass` whose CoM is at `com` with principal radii of gyration `radii` (m) along
/// the frame's axes x, y, z: inertia diag(m·rx², m·ry², m·rz²).
RigidMass rigid_mass_from_radii(double mass, const Eigen::Vector3d& com,
                                const Eigen::Vector3d& radii);

/// The pieces as one rigid body: masses add, the CoM is their mass-weighted mean, and each
/// piece's inertia moves to it by the parallel-axis theorem, I + m(|d|²E − d dᵀ).
RigidMass combine(const RigidMass& a, const RigidMass& b);

/// Where a model's segments are in its standing pose: the world position of each segment's
/// origin with every joint at identity and the root's origin at the world's origin.
std::vector<Eigen::Vector3d> standing_origins(const BodyModel& model);

/// A summary of a model standing (every joint at identity, the segment frames parallel to the
/// world's): whole-body mass, CoM and inertia about it (world axes), the heights of the lowest
/// and highest points the segments reach (their drawing extents and joint centres), and the
/// principal moments of the whole-body inertia, ascending.
struct StandingBody {
  RigidMass body;
  double lowest_y = 0.0;   ///< m, in the root's frame
  double highest_y = 0.0;  ///< m
  double height() const { return highest_y - lowest_y; }
  /// Height of the whole-body CoM above the lowest point, m.
  double com_height() const { return body.com.y() - lowest_y; }
  Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();  ///< kg·m², ascending
};

StandingBody standing_body(const BodyModel& model);

/// One segment as `saltus model info` shows it.
struct SegmentSummary {
  std::string name;   ///< "thigh_l"
  std::string label;  ///< "left thigh"
  double mass = 0.0;  ///< kg
  double mass_percent = 0.0;
  /// m: the length of its drawing shape along its axis (the bundled models: joint to joint, the
  /// thorax to the top of the head, the forearm to the hand's end), else its farthest child joint.
  double length = 0.0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();                ///< segment frame, m
  Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();  ///< about the CoM, ascending
};

/// A model described for people: its segments and the standing whole body.
struct ModelSummary {
  std::string name;
  std::string source;
  double total_mass = 0.0;
  std::vector<SegmentSummary> segments;
  StandingBody standing;
};

ModelSummary summarize_model(const BodyModel& model);

}  // namespace saltus
