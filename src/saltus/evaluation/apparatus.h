#pragma once
/// @file
/// Where a flight happens, read off the motion itself so that a picture of it can show the right
/// scene: a flight that ends well below its take-off is a dive (a platform at the height the
/// feet leave from, the water where the body ends), anything else a trampoline (the bed at the
/// height the feet leave from). Drawing the apparatus is the front end's business; where it is
/// follows from the motion's numbers, so it is decided here.

#include <Eigen/Core>
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

/// The lowest point of the body in a sample: the lowest of the segment origins and of the ends
/// of their shapes (origin + shape.length along the segment's y axis), world y, m.
double lowest_body_point(const BodyModel& model, const SampleRecord& sample);

/// The apparatus of a flight: its take-off state and its samples in time order (the first at
/// take-off). Throws std::invalid_argument for no samples.
Apparatus apparatus_for(const BodyModel& model, const Takeoff& takeoff,
                        const std::vector<SampleRecord>& samples);

}  // namespace saltus
