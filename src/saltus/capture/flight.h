#pragma once
/// @file
/// The flight phase of a capture and the ballistic fits of its centre of mass: where both feet
/// are off the ground, the take-off CoM state (a parabola with g fixed), and the gravity the
/// CoM's flight implies (a parabola with free acceleration), which exposes a wrong frame time.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "saltus/capture/retarget.h"

namespace saltus {

/// Ground contact of a foot: its lowest point (ankle, toes, End Sites) is within
/// `height_tolerance_m` of that foot's ground level, in a stretch of such low frames where at
/// some frame it moves slower than `speed_tolerance_m_s` (towards the previous or the next
/// frame). So a landing foot that still slides or sinks in counts from the frame it comes down,
/// and a clip that never touches the ground (feet low but fast at take-off and landing) is all
/// flight. The ground level of each foot is a low percentile of its lowest point's height over
/// the clip (a foot pressed into the floor at an impact does not set it, and a capture's two
/// feet may stand at slightly different heights).
struct GroundContactOptions {
  double height_tolerance_m = 0.04;
  double speed_tolerance_m_s = 1.5;
  double ground_percentile = 0.2;
};

struct FlightPhase {
  int first_frame = 0;  ///< first airborne frame (clip index)
  int last_frame = 0;   ///< last airborne frame, inclusive
  /// Lift-off and touch-down in clip time (s): where the lower foot crosses the contact height,
  /// interpolated between frames; the clip's ends when the flight reaches them.
  double liftoff_time = 0.0;
  double touchdown_time = 0.0;
  /// "feet" (found from the feet), "no ground contact" (the whole clip is in the air) or
  /// "given" (--flight).
  std::string method;
  std::array<double, 2> ground_height{0.0, 0.0};  ///< per foot (left, right), world y, m
  int frame_count() const { return last_frame - first_frame + 1; }
};

/// Finds the longest stretch of frames with both feet off the ground. Throws
/// std::invalid_argument when it has fewer than 3 frames (then give the flight explicitly).
FlightPhase detect_flight(const std::vector<RetargetedFrame>& frames, double frame_time,
                          const GroundContactOptions& options = {});

/// The flight given as clip times [start, end] (s): the frames inside it. Throws
/// std::invalid_argument when start >= end or fewer than 3 frames lie inside.
FlightPhase flight_between(int frame_count, double frame_time, double start, double end);

/// A parabola p(t) = p0 + v0 t + ½ a t² fitted by least squares to points at times.
struct BallisticFit {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();      ///< p0, m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      ///< v0, m/s
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  ///< given (fixed) or fitted, m/s²
  double rms_residual_m = 0.0;                             ///< over the fitted points
  double max_residual_m = 0.0;
};

/// p0 and v0 with the acceleration fixed (gravity). Needs at least 2 points.
BallisticFit fit_ballistic_fixed(const std::vector<double>& times,
                                 const std::vector<Eigen::Vector3d>& points,
                                 const Eigen::Vector3d& acceleration);

/// p0, v0 and a free acceleration, per coordinate. Needs at least 3 points.
BallisticFit fit_ballistic_free(const std::vector<double>& times,
                                const std::vector<Eigen::Vector3d>& points);

/// The frame time that would make a flight fall at `gravity` (m/s²) when read at
/// `frame_time` it falls at `implied_gravity`: the positions stay, times scale by k and
/// accelerations by 1/k², so k = sqrt(implied / gravity).
double ballistic_frame_time(double frame_time, double implied_gravity, double gravity);

}  // namespace saltus
