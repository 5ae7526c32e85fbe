#pragma once
/// @file
/// The stroboscopic side view of a flight (a lecture figure): poses at equal time steps from
/// take-off to landing, each with the whole-body spin rate at its time, the centre of mass's
/// path, and the side the flight is seen from. The poses come from evaluate_trajectory and the
/// spin from rotation_metrics (|ω|, ω = I⁻¹·L); this file only picks the times, the view and,
/// when the flight travels too little for the poses to stand apart, a stated horizontal spread.

#include <Eigen/Core>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/motion/trajectory.h"

namespace saltus {

/// Poses of a lecture figure unless asked otherwise: one every 0.2-0.25 s of a 2 s flight.
inline constexpr int kDefaultStroboscopePoses = 10;
/// Consecutive poses at least this many standing heights apart along the figure (CoM to CoM),
/// so that a body lying level with its arms overhead (about 1.25 heights long) clears an upright
/// neighbour: at 0.6 a platform dive's first two poses overlapped.
inline constexpr double kStroboscopeSpacingPerHeight = 0.9;
/// Below this take-off horizontal speed (m/s) the flight has no direction of its own: it is seen
/// along the body's lateral axis at take-off. The speed is the CoM's mean horizontal velocity
/// over the flight, which a ballistic flight keeps from take-off.
inline constexpr double kStroboscopeStillSpeed = 0.1;

struct StroboscopePose {
  double time = 0.0;  ///< s, from take-off
  /// The pose at `time`, every segment position moved by `shift` (com too): as drawn.
  SampleRecord sample;
  /// Whole-body spin rate |ω| at `time`, revolutions per second (ω of rotation_metrics).
  double spin_rev_per_s = 0.0;
  /// The spread added to this pose, world, m (zero when the flight travels far enough).
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
};

struct Stroboscope {
  std::vector<StroboscopePose> poses;  ///< equal time steps, first at take-off, last at landing
  /// The CoM path at kDefaultSamples equal steps, moved by the spread as the poses are.
  std::vector<Eigen::Vector3d> com_path;
  /// Unit, horizontal: the camera looks along it, across the plane of the CoM's path. Its sign
  /// makes the flight run left to right on the picture.
  Eigen::Vector3d view_direction = Eigen::Vector3d::UnitX();
  /// Unit, horizontal: right on the picture (view_direction × up), the way the flight travels.
  Eigen::Vector3d right = -Eigen::Vector3d::UnitZ();
  /// Whether the view follows the take-off horizontal velocity (false: the body's lateral axis
  /// at take-off, from the athlete's right, the flight having no horizontal speed to speak of).
  bool along_velocity = false;
  /// Horizontal distance the CoM travels from take-off to landing along `right`, m.
  double travel_m = 0.0;
  /// Distance added between consecutive poses along `right` for legibility, m (0: none).
  double spread_m = 0.0;
  /// Consecutive poses' CoMs apart along `right` as drawn, m.
  double step_m = 0.0;
};

/// The figure's poses for a trajectory flown by `model`. Throws std::invalid_argument for
/// pose_count < 2 or a model that does not match the trajectory.
Stroboscope stroboscope(const BodyModel& model, const Trajectory<double>& trajectory,
                        int pose_count = kDefaultStroboscopePoses);

}  // namespace saltus
