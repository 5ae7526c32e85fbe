#pragma once
/// @file
/// The sanity checks of a flight that a teacher shows next to "why it spins": in the air only
/// gravity acts, so the centre of mass must stay on the parabola of its take-off state, the
/// angular momentum about it must stay constant, and the time in the air follows from the
/// take-off velocity and the height at which the flight ends. Each check compares the motion with
/// that ballistic answer, sample by sample.

#include <Eigen/Core>
#include <vector>

#include "saltus/evaluation/sampling.h"
#include "saltus/motion/motion.h"

namespace saltus {

struct FlightCheckSample {
  double time = 0.0;  ///< s
  /// |CoM(t) − s(t)|: distance from the take-off parabola s(t) (paper eq. 9), m.
  double com_off_parabola_m = 0.0;
  /// |L(t) − L(0)| / |L(0)| × 100: how much the angular momentum about the CoM has changed
  /// since take-off (0 in a valid flight); 0 when L(0) is 0.
  double angular_momentum_drift_percent = 0.0;
};

struct FlightChecks {
  std::vector<FlightCheckSample> samples;
  double max_com_off_parabola_m = 0.0;
  double max_angular_momentum_drift_percent = 0.0;
  /// The motion's flight time (last sample's time), s.
  double flight_time = 0.0;
  /// The time a ballistic CoM needs from the take-off state to the height of the motion's CoM at
  /// its last sample, s (ballistic_flight_time).
  double ballistic_flight_time = 0.0;
  /// CoM height change from take-off to the end of the flight, m (negative for a dive).
  double height_change_m = 0.0;
};

/// How far a flight may be from the ballistic answer and still count as free: the centre of mass
/// within a centimetre of its parabola (what video digitisation resolves), the angular momentum
/// within 2 % of its take-off value (2 % of a double somersault's spin is 14° at landing), and
/// the time in the air within 10 ms (half a frame of 50 Hz video) of the take-off's.
inline constexpr double kFreeFlightComToleranceM = 0.01;
inline constexpr double kFreeFlightAngularMomentumTolerancePercent = 2.0;
inline constexpr double kFreeFlightTimeToleranceS = 0.01;

/// Which checks a flight passes within those tolerances.
struct FlightCheckVerdict {
  bool on_parabola = false;
  bool angular_momentum_kept = false;
  bool flight_time_matches = false;
  /// How many of the three fail.
  int failed() const { return !on_parabola + !angular_momentum_kept + !flight_time_matches; }
};
FlightCheckVerdict judge_flight(const FlightChecks& checks);

/// The checks over sampled motion (SampleRecords in time order, the first at take-off).
/// Throws std::invalid_argument for no samples.
FlightChecks flight_checks(const Takeoff& takeoff, const std::vector<SampleRecord>& samples);

/// Time for a CoM thrown with the take-off state to come down to `landing_height` (world y, m):
/// the later root of y0 + v_y t − g t²/2 = landing_height; for a landing at the take-off height
/// 2 v_y / g. NaN if it never reaches that height (thrown too low).
double ballistic_flight_time(const Takeoff& takeoff, double landing_height);

/// +1 when a positive somersault count about world x (RotationSample::somersaults) is a forward
/// somersault of this athlete, −1 when it is a backward one. Forward carries the head towards
/// the side the body faces; at identity the body faces +z with its left along +x
/// (docs/method.md, "Conventions"), so forward is positive about the body's left axis, which is
/// the root segment's x axis at take-off. Judges name the direction by the take-off, whatever
/// twists follow.
/// @param takeoff  the first sample of the flight
double forward_somersault_sign(const SampleRecord& takeoff);

}  // namespace saltus
