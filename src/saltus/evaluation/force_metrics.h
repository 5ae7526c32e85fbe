#pragma once
/// @file
/// The root-force figures Saltus reports about a sampled motion: the paper's objective and
/// "average force acting on the root" (Table 1), RMS and peak force and moment.

#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/evaluation/strength_demand.h"
#include "saltus/motion/trajectory.h"

namespace saltus {

/// Root-force figures over a sampled motion (trapezoidal rule in time).
struct ForceMetrics {
  double objective = 0.0;       ///< J = (1/T) ∫ Σ F_i² dt (paper eq. 1), N² mixing N·m²
  double avg_root_force = 0.0;  ///< sqrt(J / 6): the paper's "average force acting on the root"
  double rms_force_N = 0.0;     ///< sqrt((1/T) ∫ |F_1..3|² dt)
  double rms_moment_Nm = 0.0;   ///< sqrt((1/T) ∫ |F_4..6|² dt)
  double max_force_N = 0.0;     ///< max over samples of |F_1..3|
  double max_moment_Nm = 0.0;   ///< max over samples of |F_4..6|
};

/// Figures over samples on a grid, by the trapezoidal rule in time (max over the samples).
ForceMetrics force_metrics(const std::vector<SampleRecord>& samples);

/// The dense check behind every figure Saltus reports (docs/formats.md: the motion's true residual,
/// whatever resolution the optimiser worked at): the root wrench on every knot span at
/// equally spaced points, at first at least kCheckPointsPerSpan intervals per span, at most
/// kCheckMaxSpacing apart and at least `min_points` over the flight, integrated span by span by
/// Simpson's rule (the wrench is smooth on a span and kinks only at knots); then every spacing
/// is halved until J changes by at most kCheckRelativeChange·J + kCheckObjectiveFloor (at most
/// kCheckMaxHalvings times), since a residual an optimiser left can wiggle between its nodes
/// faster than the first grid resolves (M7 optimised: 2.7 % off at 2.5 ms). Peaks over every
/// point. Independent of the optimiser's own quadrature (Gauss–Lobatto nodes on the spans).
/// The largest load one joint carried over the dense check's points: the wrench the parent exerts
/// on the child segment's subtree at their joint (inverse dynamics' joint wrench, child frame).
struct JointLoadPeak {
  double force_N = 0.0;  ///< max |force|
  double force_time_s = 0.0;
  double moment_Nm = 0.0;  ///< max |moment| about the joint centre
  double moment_time_s = 0.0;
};

struct DenseCheck {
  ForceMetrics metrics;
  /// Per segment, the load at its joint (segment 0's is the root wrench itself).
  std::vector<JointLoadPeak> joint_peaks;
  /// Per segment, its joint's largest share of the athlete's strength and when
  /// (strength_demand.h); the root's empty.
  std::vector<JointStrengthPeak> strength_peaks;
  int points = 0;                    ///< wrench evaluations used
  int halvings = 0;                  ///< times every spacing was halved
  double last_halving_change = 0.0;  ///< |ΔJ| at the last halving (N²)
  bool converged = false;            ///< the last halving changed J by no more than the tolerance
  /// Per knot span: its start and end (s) and ∫ Σ F_i² dt over it (N²·s), where the residual
  /// lives.
  std::vector<double> span_start, span_end, span_integral;
};
inline constexpr int kCheckPointsPerSpan = 10;
inline constexpr double kCheckMaxSpacing = 0.0025;  ///< s, on the first grid
inline constexpr double kCheckRelativeChange = 1e-3;
inline constexpr double kCheckObjectiveFloor = 1e-8;  ///< N² (an average root force of 4e-5 N)
inline constexpr int kCheckMaxHalvings = 4;

DenseCheck dense_check(const BodyModel& model, const Trajectory<double>& trajectory,
                       int min_points);

/// Where the residual lives: the dense check's span integrals (∫ΣF² dt, N²·s) summed per keyframe
/// interval, each span counted in the interval that holds its middle.
std::vector<double> residual_per_interval(const DenseCheck& check,
                                          const std::vector<double>& keyframe_times);

/// Each keyframe interval's share of the whole ∫ΣF² dt (fractions summing to 1; all 0 when there
/// is no residual at all).
std::vector<double> residual_shares(const DenseCheck& check,
                                    const std::vector<double>& keyframe_times);

/// The keyframe interval holding the largest share, in words for a reader of a run that missed
/// its target: "the largest share of the root force left is between keyframes 4 and 5
/// (0.62-0.84 s): 58 % of its integral". Keyframes count from 1. Empty when `shares` is.
std::string residual_location_words(const std::vector<double>& shares,
                                    const std::vector<double>& keyframe_times);

}  // namespace saltus
