#pragma once
/// @file
/// Physically exact flights for testing the optimiser on motions nobody tuned: a seeded
/// generator of random skills (tucked, piked, straight, twisting; 0-4 somersaults forwards or
/// backwards; trampoline or platform take-offs; flight times 0.4-2.5 s), each flown by the
/// free-flight simulator and keyframed at times a user would type. The true root wrench of every
/// one is zero, so whatever residual Saltus reports after optimisation is its own error.

#include <cstdint>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/motion/motion.h"

namespace saltus {

enum class FlightShape { kTucked, kPiked, kStraight };

/// What was drawn for one flight, and what the flight then did.
struct ExactFlight {
  std::uint64_t seed = 0;
  FlightShape shape = FlightShape::kStraight;
  bool platform = false;       ///< platform take-off (lands lower), else trampoline
  double drop_m = 0.0;         ///< take-off CoM height above the landing CoM height
  double somersaults = 0.0;    ///< asked for, turns (negative: backwards)
  double twists = 0.0;         ///< asked for, turns about the body's long axis
  double root_turn_deg = 0.0;  ///< the root's accumulated turn over the flight, as flown
  /// Twisting flights (make_twisting_flight): where the twist comes from, "take-off" (angular
  /// momentum tilted from the somersault axis by takeoff_tilt_deg) or "arm" (one arm brought
  /// down early while the other stays overhead); "" for make_exact_flight's.
  std::string twist_source;
  double takeoff_tilt_deg = 0.0;
  double flown_twists = 0.0;        ///< Yeadon's twists of the flight as flown (revolutions)
  Motion motion;                    ///< keyframes read off the flight, its exact take-off state
  std::string description() const;  ///< "seed 7: tucked, 2.0 somersaults backwards, ..."
};

/// The flight drawn from `seed` for `model` (whose joints must include the bundled model's:
/// thoracic, shoulders, elbows, hips, knees). Deterministic: the same seed, the same flight, on
/// any machine (its own random numbers, not the standard library's distributions).
ExactFlight make_exact_flight(const BodyModel& model, std::uint64_t seed);

/// The twisting flight drawn from `seed`: a layout (or, twisting from an arm, a pike opening to a
/// layout) of 1.0-2.0 s with at least one somersault, whose twist comes from the take-off
/// (angular momentum tilted 5-30° from the somersault axis towards the body's long axis) or from
/// the air (one arm adducting early, the other overhead). Deterministic like make_exact_flight,
/// from a stream of its own.
ExactFlight make_twisting_flight(const BodyModel& model, std::uint64_t seed);

/// The hard twisting flight drawn from `seed` (issue 45's held-out kind): a straight 1 somersault
/// (mostly backwards) of 1.5-2.0 s with 2, 2.5 or 3 twists from a take-off momentum tilted up to
/// 40°, both arms coming in from overhead, keyframed at 7-11 roughly even times whatever the body
/// turns between them (up to ~200° of twist per interval). Deterministic, from a stream of its own.
ExactFlight make_hard_twisting_flight(const BodyModel& model, std::uint64_t seed);

/// `motion` with each interior keyframe time moved by up to ±max_shift (s), drawn from `seed`,
/// each move limited to 40 % of the gap towards its neighbours so the order stays; first and last
/// stay. Times keep two decimals, as typed.
Motion disturb_interior_times(const Motion& motion, double max_shift, std::uint64_t seed);

}  // namespace saltus
