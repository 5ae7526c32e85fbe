#pragma once
/// @file
/// Keyframes too far apart for the flight's twist. Between two keyframes the interpolation turns
/// the root the short way (at most half a turn about some axis), whatever the athlete did; a fast
/// twist keyed sparsely (3 twists in 1.8 s on 9 keyframes: 160° and more of twist between
/// neighbours) then loses or reverses a twist, and an optimisation that starts from it stays the
/// wrong way round in that interval. The free flight from the motion's take-off state with its
/// joints' movements twists as the take-off says, so an interval whose two twists differ by more
/// than half a turn while both get from one keyframe's orientation to the next's is one the
/// keyframes cannot describe; the user adds a keyframe inside it, and the optimiser starts from the
/// flight's way round (optimize.cpp).

#include <Eigen/Geometry>
#include <string>
#include <utility>
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
  /// The way the free flight turns the root inside the interval, as root orientations
  /// (world_from_root) at interior times no more than 90° of turn apart: the flight's turn since
  /// the interval's first keyframe applied to that keyframe's root, so a drift of the free flight
  /// before the interval does not move them (InterpolationOptions::root_guides).
  std::vector<std::pair<double, Eigen::Quaterniond>> flight_roots;
};

/// Twists of the free flight and of the interpolation differing by more than this in one
/// keyframe interval (degrees): half a turn, the most a short-way interpolation can be off by
/// without having turned the other way.
inline constexpr double kSparseTwistLimitDeg = 180.0;
/// ... and the free flight's turn over the interval (world_from_root at its end times its
/// inverse at its start) within this of the keyframes' (degrees): the flight gets from one
/// keyframe's orientation to the next's, only another way round. Beyond it the free flight
/// disagrees with the keyframes themselves (a motion flown by a body it was not made for drifts
/// by its landing), which a keyframe more would not mend.
inline constexpr double kSparseTwistSameTurnDeg = 45.0;

/// The intervals of `motion` (its stored spline, else interpolated as `evaluate` does) whose twist
/// differs from the free flight's by more than kSparseTwistLimitDeg while the flight's turn over
/// it stays within kSparseTwistSameTurnDeg of the keyframes', in time order; empty when every
/// interval holds. Flies the motion once as simulate_motion does (its take-off state, its joints'
/// movements) and reads both twists every 5 ms at most, the keyframe times among them.
std::vector<SparseTwistInterval> sparse_twist_intervals(const Motion& motion,
                                                        const BodyModel& model);

/// "keyframes 3-4 (0.59-0.89 s) are too far apart for the twist: the free flight from the
/// take-off twists +290 deg between them, the interpolation -70 deg; add a keyframe near
/// t = 0.74 s" (keyframes counted from 1, as the motion file's list is read).
std::string sparse_twist_words(const SparseTwistInterval& interval);

}  // namespace saltus
