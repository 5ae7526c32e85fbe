#pragma once
/// @file
/// Keyframes too far apart for the flight's twist. Between two keyframes the interpolation turns
/// the root the short way (at most half a turn about some axis), whatever the athlete did; a fast
/// twist keyed sparsely (3 twists in 1.8 s on 9 keyframes: 160° and more of twist between
/// neighbours) then loses or reverses a twist, and no optimisation of the root force brings it
/// back: the motion it starts from twists the wrong way in that interval. The free flight from
/// the motion's take-off state with its joints' movements twists as the take-off says, so an
/// interval whose two twists differ by more than half a turn is one the keyframes cannot
/// describe; the user adds a keyframe inside it.

#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/motion/motion.h"

namespace saltus {

/// One keyframe interval the keyframes cannot describe.
struct SparseTwistInterval {
  int first_keyframe = 0;  ///< the interval runs from keyframe first_keyframe to the next (0-based)
  double start_s = 0.0, end_s = 0.0;
  /// Yeadon's twist ψ's change over the interval (unwrapped, degrees, > 0 to the left): of the
  /// free flight from the take-off state, and of the keyframes' interpolation.
  double flight_twist_deg = 0.0, interpolation_twist_deg = 0.0;
};

/// Twists of the free flight and of the interpolation differing by more than this in one
/// keyframe interval (degrees): half a turn, the most a short-way interpolation can be off by
/// without having turned the other way.
inline constexpr double kSparseTwistLimitDeg = 180.0;

/// The intervals of `motion` (its stored spline, else interpolated as `evaluate` does) whose twist
/// differs from the free flight's by more than kSparseTwistLimitDeg, in time order; empty when
/// every interval holds. Flies the motion once (simulate_motion) on a grid at most 2.5 ms apart.
std::vector<SparseTwistInterval> sparse_twist_intervals(const Motion& motion,
                                                        const BodyModel& model);

/// "keyframes 3-4 (0.59-0.89 s) are too far apart for the twist: the free flight from the
/// take-off twists +290 deg between them, the interpolation -70 deg; add a keyframe near
/// t = 0.74 s" (keyframes counted from 1, as the motion file's list is read).
std::string sparse_twist_words(const SparseTwistInterval& interval);

}  // namespace saltus
