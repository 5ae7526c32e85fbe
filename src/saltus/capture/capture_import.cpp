#include "saltus/capture/capture_import.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/math/bspline_basis.h"
#include "saltus/motion/interpolate.h"

namespace saltus {

namespace {

/// Extrapolated frames beyond each end of the capture's own splines (captured_trajectory).
constexpr int kGhostFrames = 4;

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

/// Every flight frame as a keyframe, t = 0 at the first; root positions as captured.
Motion flight_motion(const std::vector<RetargetedFrame>& frames, const FlightPhase& flight,
                     double frame_time, const BodyModel& model, const std::string& name) {
  Motion motion;
  motion.name = name;
  motion.model = model.name;
  for (int f = flight.first_frame; f <= flight.last_frame; ++f) {
    Keyframe k;
    k.time = (f - flight.first_frame) * frame_time;
    k.rotations = frames[f].joint_rotation;
    k.root_position = frames[f].root_position;
    motion.keyframes.push_back(std::move(k));
  }
  return motion;
}

/// Time averages over the flight (trapezoidal rule on the samples' grid).
AngularMomentumSummary summarize_angular_momentum(const std::vector<SampleRecord>& samples) {
  AngularMomentumSummary out;
  out.samples = static_cast<int>(samples.size());
  const double duration = samples.back().time - samples.front().time;
  auto time_average = [&](auto value) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t i = 1; i < samples.size(); ++i)
      sum += 0.5 * (samples[i].time - samples[i - 1].time) *
             (value(samples[i]) + value(samples[i - 1]));
    return Eigen::Vector3d(sum / duration);
  };
  out.mean = time_average([](const SampleRecord& r) { return r.angular_momentum; });
  const Eigen::Vector3d variance = time_average([&](const SampleRecord& r) {
    const Eigen::Vector3d d = r.angular_momentum - out.mean;
    return Eigen::Vector3d(d.cwiseProduct(d));
  });
  out.standard_deviation = variance.cwiseSqrt();
  for (const SampleRecord& r : samples)
    out.max_deviation = std::max(out.max_deviation, (r.angular_momentum - out.mean).norm());
  return out;
}

/// The capture's trajectory sampled densely over the flight, with its dynamics.
std::vector<SampleRecord> sample_capture(const BodyModel& model,
                                         const Trajectory<double>& trajectory,
                                         const Motion& captured, int samples_per_frame) {
  const int intervals = static_cast<int>(captured.keyframes.size()) - 1;
  return evaluate_trajectory(
      model, trajectory,
      uniform_times(captured.flight_time(),
                    std::max(kDefaultSamples, intervals * samples_per_frame + 1)));
}

/// Angle at clip time t from per-frame angles (linear between frames, clamped at the ends).
double angle_at(const std::vector<double>& angles, double frame_time, double t) {
  const double position = std::clamp(t / frame_time, 0.0, double(angles.size() - 1));
  const std::size_t i = std::min(static_cast<std::size_t>(position), angles.size() - 2);
  const double u = position - i;
  return angles[i] + u * (angles[i + 1] - angles[i]);
}

}  // namespace

Trajectory<double> captured_trajectory(const Motion& captured, const BodyModel& model) {
  const std::size_t n = captured.keyframes.size();
  if (n < 3) throw std::invalid_argument("captured_trajectory: needs at least 3 frames");
  std::vector<double> times;
  std::vector<Eigen::Vector3d> roots;
  for (const Keyframe& k : captured.keyframes) {
    if (!k.root_position)
      throw std::invalid_argument("captured_trajectory: every keyframe needs a root position");
    times.push_back(k.time);
    roots.push_back(*k.root_position);
  }
  // Ghost frames continue the motion past each end (positions on the parabola through the last
  // three frames, rotations turning on at their last rate of change), so the splines' free ends,
  // which stop accelerating, lie outside the flight.
  std::vector<double> ghost_times = times;
  std::vector<Eigen::Vector3d> ghost_roots = roots;
  for (int g = 0; g < kGhostFrames; ++g) {
    const double step_front = ghost_times[1] - ghost_times[0];
    const double step_back = ghost_times.back() - ghost_times[ghost_times.size() - 2];
    ghost_times.insert(ghost_times.begin(), ghost_times.front() - step_front);
    ghost_times.push_back(ghost_times.back() + step_back);
    const std::size_t m = ghost_roots.size();
    ghost_roots.insert(ghost_roots.begin(),
                       3.0 * ghost_roots[0] - 3.0 * ghost_roots[1] + ghost_roots[2]);
    ghost_roots.push_back(3.0 * ghost_roots[m] - 3.0 * ghost_roots[m - 1] + ghost_roots[m - 2]);
  }
  Trajectory<double> trajectory;
  trajectory.knots = clamped_cubic_knots(ghost_times);
  std::vector<Eigen::Quaterniond> targets(n);
  for (int s = 0; s < model.size(); ++s) {
    for (std::size_t i = 0; i < n; ++i)
      targets[i] = captured.keyframes[i].rotations[s];
    for (std::size_t i = 1; i < n; ++i)
      if (targets[i].coeffs().dot(targets[i - 1].coeffs()) < 0) targets[i].coeffs() *= -1.0;
    for (int g = 0; g < kGhostFrames; ++g) {
      // The next step repeats the last one changed by the last change: w0 = 2·w1 − w2 with
      // w_k the rotation vector of the k-th step from the end.
      auto extend = [](const Eigen::Quaterniond& q0, const Eigen::Quaterniond& q1,
                       const Eigen::Quaterniond& q2) {
        const Eigen::Vector3d w1 = quat_log(Eigen::Quaterniond(q1.conjugate() * q0));
        const Eigen::Vector3d w2 = quat_log(Eigen::Quaterniond(q2.conjugate() * q1));
        return Eigen::Quaterniond(q0 * quat_exp(Eigen::Vector3d(2.0 * w1 - w2))).normalized();
      };
      const std::size_t m = targets.size();
      targets.insert(targets.begin(), extend(targets[0], targets[1], targets[2]));
      targets.push_back(extend(targets[m], targets[m - 1], targets[m - 2]));
    }
    trajectory.rotations.emplace_back(
        trajectory.knots, fit_quaternion_spline(trajectory.knots, ghost_times, targets));
    targets.resize(n);
  }
  trajectory.root_translation = VectorSpline<double>(
      trajectory.knots, fit_vector_spline(trajectory.knots, ghost_times, ghost_roots));
  return trajectory;
}

CaptureClipPoses capture_clip_poses(const CaptureImport& capture) {
  CaptureClipPoses out;
  for (std::size_t f = 0; f < capture.frames.size(); ++f) {
    const RetargetedFrame& frame = capture.frames[f];
    BodyState<double> state(static_cast<int>(frame.joint_rotation.size()));
    state.root_position = frame.root_position;
    for (std::size_t s = 0; s < frame.joint_rotation.size(); ++s)
      state.joints[s].q = frame.joint_rotation[s];
    out.times.push_back((static_cast<double>(f) - capture.flight.first_frame) * capture.frame_time);
    out.states.push_back(std::move(state));
  }
  return out;
}

std::vector<double> somersault_angles(const std::vector<Eigen::Quaterniond>& world_rotations) {
  std::vector<double> out;
  for (const Eigen::Quaterniond& r : world_rotations) {
    const Eigen::Vector3d axis = r * Eigen::Vector3d::UnitY();
    double angle = std::atan2(axis.z(), axis.y());
    if (!out.empty()) {
      while (angle - out.back() > kPi)
        angle -= 2 * kPi;
      while (angle - out.back() < -kPi)
        angle += 2 * kPi;
    }
    out.push_back(angle);
  }
  return out;
}

CaptureImport import_capture(const MocapClip& clip, const BodyModel& model,
                             const SkeletonMapping& mapping, const CaptureImportOptions& options) {
  validate_clip(clip);
  if (options.frame_time && !(*options.frame_time > 0))
    throw std::invalid_argument("the frame time must be > 0 s");
  if (options.samples_per_frame < 1)
    throw std::invalid_argument("samples per frame must be at least 1");
  CaptureImport out;
  out.source_joints = clip.joint_count();
  out.source_frames = clip.frame_count();
  out.stated_frame_time = clip.frame_time;
  out.frame_time = options.frame_time.value_or(clip.frame_time);
  const double dt = out.frame_time;
  const std::string name = options.name.empty() ? "captured flight" : options.name;

  out.retargeting = plan_retargeting(clip, model, mapping);
  out.frames = retarget_clip(clip, model, out.retargeting);
  out.flight = options.flight ? flight_between(clip.frame_count(), dt, options.flight->first,
                                               options.flight->second)
                              : detect_flight(out.frames, dt, options.contact);
  const FlightPhase& flight = out.flight;
  const double flight_span = (flight.last_frame - flight.first_frame) * dt;
  if (options.max_flight_time && flight_span > *options.max_flight_time)
    throw CaptureError(
        options.flight ? CapturePart::kFlightOption : CapturePart::kFrames,
        "the flight (" + flight.method + ": frames " + std::to_string(flight.first_frame) + "-" +
            std::to_string(flight.last_frame) + ") lasts " + format("%.6g", flight_span) +
            " s, longer than a motion may (" + format("%.6g", *options.max_flight_time) +
            " s); give the flight with --flight START:END");
  const int flight_frames = flight.last_frame - flight.first_frame + 1;
  if (options.max_flight_frames && flight_frames > *options.max_flight_frames)
    throw CaptureError(
        options.flight ? CapturePart::kFlightOption : CapturePart::kFrames,
        "the flight (" + flight.method + ": frames " + std::to_string(flight.first_frame) + "-" +
            std::to_string(flight.last_frame) + ") holds " + std::to_string(flight_frames) +
            " frames; Saltus imports at most " + std::to_string(*options.max_flight_frames) +
            " (every one is fitted as a keyframe): give a shorter flight with --flight START:END");

  // Heading: the somersault axis (the horizontal part of the flight's angular momentum) onto
  // x, the sign chosen so that the body's left at take-off points to +x as nearly as it can.
  CaptureImportOptions::Heading heading = options.heading;
  if (heading == CaptureImportOptions::Heading::kAuto)
    heading = out.retargeting.mapping.convention == "Saltus"
                  ? CaptureImportOptions::Heading::kKeep
                  : CaptureImportOptions::Heading::kAlignSomersaultAxis;
  if (heading == CaptureImportOptions::Heading::kKeep) {
    out.heading_rule = out.retargeting.mapping.convention == "Saltus"
                           ? "kept: the file uses Saltus's own skeleton and frame"
                           : "kept as in the file";
  } else {
    const Motion provisional = flight_motion(out.frames, flight, dt, model, name);
    const AngularMomentumSummary l = summarize_angular_momentum(sample_capture(
        model, captured_trajectory(provisional, model), provisional, options.samples_per_frame));
    const Eigen::Vector3d left =
        out.frames[flight.first_frame].world_rotation[0] * Eigen::Vector3d::UnitX();
    Eigen::Vector3d horizontal(l.mean.x(), 0.0, l.mean.z());
    if (horizontal.norm() > 0.1 * l.mean.norm() && horizontal.norm() > 1.0) {
      if (horizontal.dot(Eigen::Vector3d(left.x(), 0.0, left.z())) < 0) horizontal = -horizontal;
      out.heading_rule =
          "the horizontal part of the flight's mean angular momentum (the somersault axis) "
          "turned onto x, the body's left at take-off towards +x";
    } else {
      horizontal = Eigen::Vector3d(left.x(), 0.0, left.z());
      out.heading_rule =
          "no somersault in the flight (horizontal angular momentum under 1 kg·m²/s or 10 %): "
          "the body's left at take-off turned onto +x";
    }
    const double yaw = std::atan2(horizontal.z(), horizontal.x());
    apply_heading(out.frames, yaw);
    out.heading_yaw_deg = yaw * kDegreesPerRadian;
  }

  // The model's CoM per frame and the ballistic fits over the flight.
  for (const RetargetedFrame& frame : out.frames)
    out.com.push_back(com_with_root_at_origin(model, frame.joint_rotation) + frame.root_position);
  std::vector<double> times;
  std::vector<Eigen::Vector3d> com;
  for (int f = flight.first_frame; f <= flight.last_frame; ++f) {
    times.push_back((f - flight.first_frame) * dt);
    com.push_back(out.com[f]);
  }
  out.takeoff_fit = fit_ballistic_fixed(times, com, gravity());
  out.free_fit = fit_ballistic_free(times, com);
  out.implied_gravity = -out.free_fit.acceleration.y();
  const double g = -gravity().y();
  const std::string frames_label =
      "frames " + std::to_string(flight.first_frame) + "-" + std::to_string(flight.last_frame);
  if (std::abs(out.implied_gravity - g) > options.gravity_warning_fraction * g) {
    std::string warning = "the centre of mass falls at " + format("%.3g", out.implied_gravity) +
                          " m/s² during the flight (" + frames_label + " read " +
                          format("%.6g", dt) + " s apart), not " + format("%.3g", g) + " m/s²: ";
    if (out.implied_gravity > 0) {
      out.suggested_frame_time = ballistic_frame_time(dt, out.implied_gravity, g);
      warning += "the frame time is likely wrong; at " + format("%.4g", *out.suggested_frame_time) +
                 " s per frame (" + format("%.3g", 1.0 / *out.suggested_frame_time) +
                 " Hz) the flight is ballistic (re-import with --frame-time " +
                 format("%.4g", *out.suggested_frame_time) + ")";
    } else {
      warning +=
          "it does not fall at all, so these frames are not a free flight (check "
          "--flight)";
    }
    out.warnings.push_back(warning);
  }
  if (out.takeoff_fit.rms_residual_m > 0.03)
    out.warnings.push_back("the centre of mass is " +
                           format("%.3g", out.takeoff_fit.rms_residual_m) +
                           " m RMS off the ballistic parabola (g = 9.81 m/s²) fitted to " +
                           frames_label + ": the take-off state is uncertain");
  if (flight.method == "no ground contact")
    out.warnings.push_back(
        "the feet never touch the ground in the clip: the whole clip is taken as the flight");
  if (out.retargeting.axes.unit_detected &&
      (out.retargeting.axes.rest_height_m < 1.2 || out.retargeting.axes.rest_height_m > 2.2))
    out.warnings.push_back("the skeleton is " + format("%.3g", out.retargeting.axes.rest_height_m) +
                           " m tall in " + out.retargeting.axes.unit +
                           ", unusual for a person: check the unit (mapping file \"unit\")");

  // The captured flight, its trajectory, residual and angular momentum.
  out.captured = flight_motion(out.frames, flight, dt, model, name);
  out.trajectory = captured_trajectory(out.captured, model);
  out.samples = sample_capture(model, out.trajectory, out.captured, options.samples_per_frame);
  out.metrics = force_metrics(out.samples);
  out.angular_momentum = summarize_angular_momentum(out.samples);
  out.captured.takeoff.com_position = out.takeoff_fit.position;
  out.captured.takeoff.com_velocity = out.takeoff_fit.velocity;
  out.captured.takeoff.angular_momentum = out.angular_momentum.mean;
  const double duration = out.captured.flight_time();
  const int intervals = static_cast<int>(out.captured.keyframes.size()) - 1;
  out.samples = evaluate_trajectory(
      model, out.trajectory,
      uniform_times(duration,
                    std::max(kDefaultSamples, intervals * options.samples_per_frame + 1)));
  out.metrics = force_metrics(out.samples);
  const double l_norm = out.angular_momentum.mean.norm();
  if (out.angular_momentum.max_deviation > 0.2 * l_norm && out.angular_momentum.max_deviation > 1.0)
    out.warnings.push_back("the angular momentum about the centre of mass varies by up to " +
                           format("%.3g", out.angular_momentum.max_deviation) + " kg·m²/s (" +
                           format("%.0f", 100 * out.angular_momentum.max_deviation / l_norm) +
                           " % of its mean) over the flight; in a free flight it is constant");

  std::vector<Eigen::Quaterniond> trunk;
  for (const RetargetedFrame& frame : out.frames)
    trunk.push_back(frame.world_rotation[0]);
  const std::vector<double> angles = somersault_angles(trunk);
  out.somersault_flight_deg =
      (angle_at(angles, dt, flight.touchdown_time) - angle_at(angles, dt, flight.liftoff_time)) *
      kDegreesPerRadian;
  out.somersault_clip_deg = (angles.back() - angles.front()) * kDegreesPerRadian;

  // Keyframes for optimisation.
  if (options.all_keyframes) {
    std::vector<int> every(out.captured.keyframes.size());
    for (std::size_t i = 0; i < every.size(); ++i)
      every[i] = static_cast<int>(i);
    out.pick = keyframe_errors_of(out.captured, every);
    out.pick.rule = "--keyframes all: every captured frame of the flight";
  } else {
    out.pick = pick_keyframes(out.captured, model, options.keyframe_count);
    if (!options.keyframe_count &&
        out.pick.max_quaternion_error > out.captured.tolerances.quaternion)
      out.warnings.push_back(
          "the interpolation through " + std::to_string(out.pick.frames.size()) +
          " keyframes (the most picked) still misses a captured frame's joint rotation by " +
          format("%.3g", out.pick.max_rotation_error_deg) +
          " deg; keyframes.motion.json keeps them (--keyframes all keeps every frame)");
  }
  out.keyframes = keep_keyframes(out.captured, out.pick.frames);
  out.keyframes_metrics = evaluate_motion(out.keyframes, model).metrics;
  return out;
}

}  // namespace saltus
