#pragma once
/// @file
/// The athletes study (`saltus study athletes`): one motion flown by several athletes, each case
/// one athlete. Per athlete: the motion's true residual (the dense check) before and after
/// optimisation, the free flight of the motion as given and of the optimised motion (landing
/// error, Yeadon's somersaults and twists), the largest joint loads of the optimised motion and
/// the largest rise of a joint's load over the athlete's own input, and the athlete's size and
/// take-off angular momentum. The motion on the athlete comes from
/// use_cases/athlete_models.h (load_motion_for_athlete); the files from formats/athletes_files.h.

#include <Eigen/Core>
#include <string>

#include "saltus/motion/motion.h"
#include "saltus/optim/optimize.h"

namespace saltus {

/// One athlete's row of the study. Forces in N, moments in N·m, angles in degrees, turns in
/// revolutions (somersaults > 0 forward, twists > 0 to the left: evaluation/yeadon_angles.h).
struct AthleteOutcome {
  std::string athlete;  ///< the model's name
  std::string takeoff;  ///< "own model", "same spin" or "same angular momentum"
  double mass_kg = 0.0;
  double height_m = 0.0;  ///< standing height (body/mass_properties.h, standing_body)
  /// Take-off angular momentum of the motion as given on this athlete (the file's, the rule's,
  /// or the constant nearest its L(t)), kg·m²/s.
  Eigen::Vector3d takeoff_angular_momentum = Eigen::Vector3d::Zero();
  std::string status;  ///< the optimisation's (SolveReport::status)
  bool solved = false;
  int iterations = 0;
  double seconds = 0.0;  ///< wall time of the optimisation
  /// True average root force sqrt(J/6) (the dense check) of the interpolated and optimised motion.
  double avg_root_force_before_N = 0.0;
  double avg_root_force_after_N = 0.0;
  double max_root_force_after_N = 0.0;  ///< max |F| of the optimised motion's root wrench
  /// Free flight with the motion's joint movements: whole-body orientation at T against the last
  /// keyframe, for the motion as given (its take-off L) and the optimised one (its own take-off).
  double landing_error_before_deg = 0.0;
  double landing_error_after_deg = 0.0;
  /// Yeadon's counts of the same two free flights.
  double somersaults_before = 0.0, twists_before = 0.0;
  double somersaults_after = 0.0, twists_after = 0.0;
  /// The optimised motion's largest joint moment and largest joint force (dense-check peaks over
  /// every joint but the root) and where; the force also in % of body weight.
  std::string peak_moment_joint;
  double peak_moment_Nm = 0.0;
  std::string peak_force_joint;
  double peak_force_N = 0.0;
  double peak_force_pct_bw = 0.0;
  /// The optimised motion's largest joint load rise against this athlete's own interpolated
  /// input (largest_joint_load_rise: peak after over peak before, force or moment, whichever
  /// rose more) and its joint: above kJointLoadRiseLimit (1.5x) the optimiser made that joint
  /// pay for the root force on this body. 0 and "" in case files written before it.
  std::string joint_rise_joint;
  double joint_rise = 0.0;
};

/// The study's row for `file` (the motion already on the athlete, `file.model`): optimised with
/// `options`, both flights simulated with `options.nlp.samples` samples.
AthleteOutcome run_athlete_case(const MotionFile& file, const OptimizeOptions& options);

}  // namespace saltus
