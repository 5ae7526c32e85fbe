#pragma once
/// @file
/// Joint loads a person can read: how the optimised motion's peak load at each joint compares
/// with the peak the interpolated input needed (a motion made physical in the air must not make
/// a joint pay for it), and loads in % of body weight.

#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/force_metrics.h"

namespace saltus {

/// Peaks below these count as these in a ratio: a joint that carried nearly nothing before does
/// not make a large ratio out of a few newtons after.
inline constexpr double kJointForceFloorN = 10.0;
inline constexpr double kJointMomentFloorNm = 1.0;

/// A joint whose peak load after optimisation is more than this multiple of its peak before
/// (the interpolated input's) is flagged to the reader: the optimiser made it pay for the root
/// residual, a load the keyframes did not ask for (docs/optimizer.md, "Joint loads").
inline constexpr double kJointLoadRiseLimit = 1.5;

/// One joint's peak load after against before (dense-check peaks).
struct JointLoadRise {
  std::string joint;  ///< e.g. "hip_r"
  JointLoadPeak before, after;
  double force_ratio = 1.0;   ///< after / before, each at least kJointForceFloorN
  double moment_ratio = 1.0;  ///< after / before, each at least kJointMomentFloorNm
  double ratio() const { return force_ratio > moment_ratio ? force_ratio : moment_ratio; }
};

/// Every joint of the model (the root left out), in model order.
std::vector<JointLoadRise> joint_load_rises(const BodyModel& model, const DenseCheck& before,
                                            const DenseCheck& after);

/// The joint whose ratio() is largest; a default JointLoadRise for a model of one segment.
JointLoadRise largest_joint_load_rise(const BodyModel& model, const DenseCheck& before,
                                      const DenseCheck& after);

/// Body weight m·g, N: the scale of "% of body weight".
double body_weight_N(const BodyModel& model);

/// The rise in words, by its larger ratio: "elbow_l, moment 7.17 N·m at t = 0.224 s after,
/// 2.6 N·m before (2.76x)"; a force also in % of `body_weight` (N).
std::string joint_load_rise_words(const JointLoadRise& rise, double body_weight);

/// What the largest rise means, in one sentence the CLI and the app both show: "every joint
/// within 1.30x of its peak load before", or, above kJointLoadRiseLimit, "ankle_l carries 14.38x
/// its peak load before (more than 1.5x): the optimiser made it pay for the root force; do not
/// read it as the athlete's".
std::string joint_load_verdict_words(const JointLoadRise& rise);

}  // namespace saltus
