#pragma once
/// @file
/// How near the body comes to the apparatus, and how a dive enters the water, measured against
/// the apparatus the app draws (apparatus.h: one set of sizes for both). The body is its segment
/// origins and the ends of their shapes, the points lowest_body_point uses.
///
/// A platform's space is everything behind its front edge and below its top, across its width,
/// down to the water: the tower under the platform. A body point in it has struck the platform.
/// A trampoline's frame is the ring between the bed's edge and the frame's outer edge, just below
/// the bed.

#include <optional>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/apparatus.h"
#include "saltus/evaluation/sampling.h"

namespace saltus {

/// A body point: a segment's origin (its joint) or the end of its shape.
struct BodyPoint {
  int segment = 0;
  bool end = false;  ///< the end of the segment's shape, else its origin
};

/// The point's world position in a sample.
Eigen::Vector3d body_point_position(const BodyModel& model, const SampleRecord& sample,
                                    const BodyPoint& point);

/// What a coach calls the point: "left ankle" (the foot's origin), "left toes" (its end), "right
/// hand" (the forearm's end), "head" (the thorax's end), "end of the left lower leg".
std::string body_point_label(const BodyModel& model, const BodyPoint& point);

/// Signed distance (m) of a point in the apparatus frame from the apparatus: from the platform's
/// space (platform), or from the frame's ring (trampoline); negative inside it. `drop` is how far
/// the water lies below the take-off surface (a platform's space reaches down to it).
double apparatus_distance(ApparatusKind kind, const Eigen::Vector3d& local, double drop);

/// The smallest clearance between the body and the apparatus over a flight.
struct ApparatusClearance {
  ApparatusKind kind = ApparatusKind::kTrampoline;
  std::vector<double> times;     ///< the samples' times, s
  std::vector<double> distance;  ///< per sample, the smallest over the body's points, m
  /// The closest pass is searched from this time on. A dive: from the CoM's apex (the feet stand
  /// on the platform at take-off and rise off it; the danger is the way down past the edge). A
  /// trampoline: from take-off (where the feet leave and land on the bed matters).
  double from_s = 0.0;
  double min_distance_m = 0.0;  ///< negative: inside the apparatus (a collision)
  double time_s = 0.0;          ///< when
  std::string segment;          ///< the model's segment name of the closest point
  bool segment_end = false;     ///< the closest point is the end of the segment's shape
  std::string point;            ///< body_point_label of it
  /// Platform: how far the point is behind the front edge (negative: ahead of it). Trampoline:
  /// how far it is inside the bed's edge, horizontally (negative: over the frame or beyond).
  double edge_m = 0.0;
  /// Platform: how far the point is below the platform's top. Trampoline: its height above the
  /// frame's top. Either negative on the other side.
  double vertical_m = 0.0;
  bool collision = false;  ///< min_distance_m < 0: the point is inside the apparatus
};

/// The clearance of a flight: its samples in time order, the first at take-off, and the
/// apparatus apparatus_for gives for them. Throws std::invalid_argument for no samples.
ApparatusClearance apparatus_clearance(const BodyModel& model, const Apparatus& apparatus,
                                       const std::vector<SampleRecord>& samples);

/// Within this many degrees of the vertical, an entry is vertical (diving judges' "vertical
/// entry": a deviation up to about 10 degrees is hardly marked down).
inline constexpr double kVerticalEntryToleranceDeg = 10.0;

/// A dive's entry into the water.
struct DiveEntry {
  /// When the body first reaches the water (Apparatus::landing_height), interpolated between
  /// samples on the lowest body point's height. The first contact, not the CoM's: the flight's
  /// samples end when the body touches the water, the CoM still above it.
  double time_s = 0.0;
  std::string first_contact;  ///< body_point_label of the point that touches first
  double com_height_m = 0.0;  ///< the CoM above the water then
  /// Angle of the body line (from the middle of the two feet's ends to the head, the thorax's
  /// end) to the vertical then, interpolated between samples, 0..90 degrees.
  double angle_to_vertical_deg = 0.0;
  bool head_first = false;  ///< the head below the feet
  bool vertical = false;    ///< angle_to_vertical_deg <= kVerticalEntryToleranceDeg
};

/// The entry of a dive (a platform apparatus); none for a trampoline, or a model without the
/// segments "foot_l", "foot_r" and "thorax". Throws std::invalid_argument for no samples.
std::optional<DiveEntry> dive_entry(const BodyModel& model, const Apparatus& apparatus,
                                    const std::vector<SampleRecord>& samples);

}  // namespace saltus
