#pragma once
/// @file
/// Where a flight happens, read off the motion itself so that a picture of it can show the right
/// scene: a flight that ends well below its take-off is a dive (a platform at the height the
/// feet leave from, the water where the body ends), anything else a trampoline (the bed at the
/// height the feet leave from). Drawing the apparatus is the front end's business; where it is
/// follows from the motion's numbers, so it is decided here.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/motion/motion.h"

namespace saltus {

enum class ApparatusKind { kTrampoline, kPlatform };

struct Apparatus {
  ApparatusKind kind = ApparatusKind::kTrampoline;
  /// World y of the surface the flight starts from: the bed, or the platform's top, m.
  double takeoff_height = 0.0;
  /// World y of the surface the flight ends on: the bed, or the water, m.
  double landing_height = 0.0;
  /// On the take-off surface, under the take-off CoM, m.
  Eigen::Vector3d takeoff_point = Eigen::Vector3d::Zero();
  /// Horizontal unit vector along which the apparatus lies. A dive: the way the athlete leaves
  /// (the take-off velocity's horizontal part; the platform lies behind it). A trampoline: the
  /// way the body faces at take-off (athletes face along the bed's long side; their small drift
  /// says nothing about the bed).
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};

/// A flight that ends this far (m) or more below its take-off is a dive.
inline constexpr double kDiveDrop = 2.0;

/// The apparatus's size, one set for the app's drawing and the clearances (clearance.h), so the
/// two cannot disagree. Lengths in m, in the apparatus frame (world_from_apparatus).
/// Trampoline (FIG apparatus norms): bed 4.28 m × 2.14 m, frame with pads 5.05 × 2.91; the
/// athlete travels along the bed's long side. The bed's top is where the feet leave; the frame's
/// top lies just below it.
inline constexpr double kBedLength = 4.28, kBedWidth = 2.14, kBedThickness = 0.02;
inline constexpr double kFrameLength = 5.05, kFrameWidth = 2.91, kFrameThickness = 0.06;
inline constexpr double kFrameTop = -0.015;  ///< the frame's top below the bed's top
/// Platform (FINA diving facilities rules: at least 2 m wide and 6 m long for the 5 m level),
/// 0.25 m thick, its front edge this far ahead of the take-off CoM (the toes at the edge), a
/// square column under its back.
inline constexpr double kPlatformWidth = 3.0, kPlatformLength = 6.0, kPlatformThickness = 0.25;
inline constexpr double kPlatformEdgeAhead = 0.15;
inline constexpr double kPillarSide = 1.2;

/// World from the apparatus frame: origin at the take-off point, z along the travel direction,
/// y up. A platform lies at z <= kPlatformEdgeAhead, a trampoline's bed is centred on the origin.
Eigen::Affine3d world_from_apparatus(const Apparatus& apparatus);

/// The lowest point of the body in a sample: the lowest of the segment origins and of the ends
/// of their shapes (origin + shape.length along the segment's y axis), world y, m.
double lowest_body_point(const BodyModel& model, const SampleRecord& sample);

/// The apparatus of a flight: its take-off state and its samples in time order (the first at
/// take-off). Throws std::invalid_argument for no samples.
Apparatus apparatus_for(const BodyModel& model, const Takeoff& takeoff,
                        const std::vector<SampleRecord>& samples);

}  // namespace saltus
