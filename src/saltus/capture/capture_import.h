#pragma once
/// @file
/// Importing a motion capture onto the body model (the library call behind `saltus import` and
/// the GUI's File > Import): retargeting, the flight phase, the take-off state, the angular
/// momentum over the flight, the capture's own residual and keyframes picked for optimisation.
/// In memory only; use_cases/captures.h reads the files and writes the outputs.

#include <optional>
#include <string>
#include <vector>

#include "saltus/capture/flight.h"
#include "saltus/capture/keyframe_picking.h"
#include "saltus/capture/mocap_clip.h"
#include "saltus/capture/retarget.h"
#include "saltus/evaluation/force_metrics.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/motion/motion.h"
#include "saltus/motion/trajectory.h"

namespace saltus {

struct CaptureImportOptions {
  /// The flight in clip time (s), instead of finding it from the feet.
  std::optional<std::pair<double, double>> flight;
  /// Seconds per frame, instead of the file's.
  std::optional<double> frame_time;
  /// Keyframes for keyframes.motion.json: unset = automatic (pick_keyframes' tolerance rule).
  std::optional<int> keyframe_count;
  bool all_keyframes = false;  ///< every captured flight frame a keyframe
  /// kAuto turns the somersault axis onto x except for files in Saltus's own skeleton (what
  /// `saltus export` writes), which are already in Saltus's frame and keep their heading.
  enum class Heading { kAuto, kAlignSomersaultAxis, kKeep };
  Heading heading = Heading::kAuto;
  GroundContactOptions contact;
  /// Warn when the gravity implied by the CoM's flight is off 9.81 m/s² by more than this
  /// fraction (a wrong frame time, or not a free flight).
  double gravity_warning_fraction = 0.2;
  /// The longest flight imported (s from its first to its last frame); longer is refused
  /// before the flight is fitted (std::invalid_argument). Unset: no limit. `saltus import` sets
  /// the motion reader's flight-time limit.
  std::optional<double> max_flight_time;
  /// The most frames a flight imported may hold (refused the same way). Unset: no limit.
  /// `saltus import` sets plausible::kMaxCaptureFlightFrames.
  std::optional<int> max_flight_frames;
  /// Samples of the capture's residual per captured frame interval (trajectory.csv).
  int samples_per_frame = 10;
  std::string name;  ///< motion name ("" = "captured flight")
};

/// Angular momentum about the CoM (world, kg·m²/s) over the flight: from inverse dynamics of the
/// interpolated capture with the model's masses, averaged over time on the dense sample grid
/// (in a free flight it is constant; a capture's varies, and sampling only the captured frames
/// would weigh its course unevenly).
struct AngularMomentumSummary {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();                ///< time average
  Eigen::Vector3d standard_deviation = Eigen::Vector3d::Zero();  ///< over time, per component
  double max_deviation = 0.0;  ///< max over samples of |L − mean|
  int samples = 0;
};

struct CaptureImport {
  // The source.
  int source_joints = 0;
  int source_frames = 0;
  double stated_frame_time = 0.0;  ///< the file's
  double frame_time = 0.0;         ///< used (the file's or CaptureImportOptions::frame_time)
  Retargeting retargeting;
  /// Every frame of the clip on the model, in Saltus's frame after the heading turn.
  std::vector<RetargetedFrame> frames;
  std::vector<Eigen::Vector3d> com;  ///< per clip frame, the model's CoM (world, m)

  // Heading: the turn about +y applied to the whole capture, and why.
  double heading_yaw_deg = 0.0;
  std::string heading_rule;

  // The flight.
  FlightPhase flight;
  BallisticFit takeoff_fit;      ///< g fixed; t = 0 at the first flight frame
  BallisticFit free_fit;         ///< acceleration free
  double implied_gravity = 0.0;  ///< −free_fit.acceleration.y, m/s²
  /// When the implied gravity is off by more than the warning fraction: the frame time that
  /// makes the flight ballistic at 9.81 m/s².
  std::optional<double> suggested_frame_time;
  AngularMomentumSummary angular_momentum;
  /// The trunk's (abdomen's) turn about the x axis, degrees (negative = backward, as M1), over
  /// the flight (lift-off to touch-down, interpolated between frames) and over the whole clip.
  double somersault_flight_deg = 0.0;
  double somersault_clip_deg = 0.0;

  // Results.
  Motion captured;   ///< every flight frame a keyframe (captured root positions included)
  Motion keyframes;  ///< the picked keyframes
  KeyframePick pick;
  /// The capture itself as a trajectory (captured_trajectory; sample it on [0, T], T =
  /// captured.flight_time()) and its dynamics on a dense grid: how physically consistent the
  /// capture is.
  Trajectory<double> trajectory;
  std::vector<SampleRecord> samples;
  ForceMetrics metrics;
  ForceMetrics keyframes_metrics;     ///< the picked keyframes' interpolation, as `evaluate` does
  std::vector<std::string> warnings;  ///< sentences
};

/// Runs the import. Throws std::invalid_argument for a clip that cannot be imported (mapping,
/// no flight phase, bad options); the formats layer adds the file name.
CaptureImport import_capture(const MocapClip& clip, const BodyModel& model,
                             const SkeletonMapping& mapping,
                             const CaptureImportOptions& options = {});

/// Every clip frame as a body state on the model (joint rotations and root position; rates
/// zero), for drawing the whole capture, ground phases included, as a ghost beside a motion:
/// times are on the motions' clock, t = 0 at the flight's first frame (negative before it).
/// evaluate_states() gives the segment poses.
struct CaptureClipPoses {
  std::vector<double> times;
  std::vector<BodyState<double>> states;
};
CaptureClipPoses capture_clip_poses(const CaptureImport& capture);

/// The capture's own trajectory: quaternion splines through every keyframe and the root
/// translation through the keyframes' root positions (all must have one), knots at the
/// keyframe times. Two extrapolated frames continue it past each end (positions on the
/// parabola through the last three frames, rotations at their last rate of change), so that the
/// splines' free ends, which stop accelerating, lie outside [0, T]: an exact free flight then
/// keeps a near-zero residual up to its ends. Its knots span [−2Δt, T + 2Δt]; the flight is
/// [0, T].
Trajectory<double> captured_trajectory(const Motion& captured, const BodyModel& model);

/// Unwrapped turn (rad) about the world x axis of a segment's long (y) axis between frames,
/// from its world rotations: atan2 of the axis's z and y components, unwrapped frame to frame.
std::vector<double> somersault_angles(const std::vector<Eigen::Quaterniond>& world_rotations);

}  // namespace saltus
