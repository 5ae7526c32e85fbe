#pragma once
/// @file
/// Where a twist comes from, by Yeadon's method of counterfactual free flights (M. R. Yeadon,
/// "The biomechanics of twisting somersaults", J. Sports Sci. 11, 1993): a twist needs tilt,
/// and the tilt at mid-flight comes from the take-off (angular momentum tilted from the
/// somersault axis) and from asymmetric movements in the air. A movement is taken away by
/// replacing it with its symmetric part (with_symmetric_joints: an arm by the mean of itself and
/// the other arm's mirror image, legs and trunk likewise). The take-off's share is the tilt of the
/// flight with every movement made symmetric; each movement's share is its Shapley value, the
/// tilt it adds averaged over every order of taking the movements away (2^n flights for n
/// movements), so that the shares add up to the actual flight's tilt exactly, also when the
/// movements act only together (one arm adducting while the other stays overhead: the asymmetry
/// lies between the two arms, and each arm's symmetric part removes half of it).

#include <string>
#include <vector>

#include "saltus/evaluation/evaluate.h"

namespace saltus {

/// Below this tilt at mid-flight (degrees) a flight has nothing to twist with: the sentence says so
/// instead of sharing out a tilt that is not there (its percentages would divide by nearly 0).
inline constexpr double kMinTwistTiltDeg = 1.0;

/// Whether the flight is tilted enough at mid-flight for its shares to mean something.
inline bool has_tilt_to_share(double total_tilt_deg) {
  return total_tilt_deg >= kMinTwistTiltDeg || total_tilt_deg <= -kMinTwistTiltDeg;
}

struct TwistShare {
  std::string source;     ///< "take-off", "left arm", "right arm", "legs", "trunk"
  double tilt_deg = 0.0;  ///< its share of the tilt at the reference time
  double percent = 0.0;   ///< of the total tilt (signed: < 0 works against it)
};

struct TwistSources {
  double reference_time_s = 0.0;   ///< mid-flight, T/2
  double total_tilt_deg = 0.0;     ///< of the motion's own free flight at the reference time
  double twists = 0.0;             ///< Yeadon's twists of that free flight (revolutions)
  std::vector<TwistShare> shares;  ///< the take-off first, then each aerial movement
  /// total − Σ shares: 0 up to rounding (the shares are Shapley values); written as the check.
  double interaction_deg = 0.0;
  /// Tilt over time (degrees, at `times`) of the actual flight and of some counterfactuals, in
  /// the order: actual, every movement symmetric (take-off only), then without each movement
  /// alone (the flights without two or three movements enter the shares, not these curves).
  std::vector<double> times;
  std::vector<std::string> flight_names;
  std::vector<std::vector<double>> tilt_deg;
  /// "Of the 24.2° of tilt at mid-flight, 70 % came from the right arm, 28 % from the take-off."
  /// (the tilt to a tenth of a degree, as the app's panel and the CLI's table give it)
  std::string sentence;
};

/// Flies the motion (its take-off angular momentum: the motion file's, or the constant that
/// best fits its own L(t), as simulate_motion) and its counterfactuals, all with the same
/// take-off state, the counterfactuals on as many threads as the machine has cores. Throws
/// std::invalid_argument when the model lacks a left-right pair.
TwistSources twist_sources(const Motion& motion, const BodyModel& model,
                           const EvaluateOptions& options = {});

/// The motion with each joint of `joints` replaced by its symmetric part: the mean of its rotation
/// and the mirror image (in the body's sagittal plane) of its counterpart's (*_l ↔ *_r; an
/// unpaired joint's own), keyframe by keyframe. The other joints, the root and the take-off stay.
Motion with_symmetric_joints(const Motion& motion, const BodyModel& model,
                             const std::vector<std::string>& joints);

}  // namespace saltus
