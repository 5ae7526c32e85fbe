// The whole import on captures whose truth is known: an exact free flight (a tucked back
// somersault simulated in free flight, docs/method.md) exported as BVH on the model's skeleton and
// imported back, and the same performance rewritten in other capture conventions. Checked by
// paths independent of the importer: the simulator's own states, its take-off state and
// conserved angular momentum, and optimisation of the picked keyframes.

#include "saltus/capture/capture_import.h"

#include <gtest/gtest.h>

#include "saltus/capture/model_clip.h"
#include "saltus/dynamics/free_flight.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/formats/bvh_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/motion/interpolate.h"
#include "saltus/optim/optimize.h"
#include "saltus/use_cases/captures.h"
#include "support/capture_conventions.h"
#include "support/cli_runner.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

const Eigen::Vector3d kAngularMomentum(-30, 0, 0);

/// The tuck's joint motion in free flight, sampled at `fps`.
struct FreeFlight {
  BodyModel model = test::bundled_model();
  Motion source;
  std::vector<double> times;
  std::vector<BodyState<double>> states;
  double frame_time = 0.0;
};

FreeFlight free_flight(double fps) {
  FreeFlight out;
  out.source = test::tuck_motion(out.model);
  const Trajectory<double> joints = interpolate_keyframes(out.source, out.model);
  FreeFlightInitialState initial;
  initial.com_position = out.source.takeoff.com_position;
  initial.com_velocity = out.source.takeoff.com_velocity;
  initial.angular_momentum = kAngularMomentum;
  initial.root_orientation = joints.rotations[0].evaluate(0.0).q;
  const double duration = out.source.flight_time();
  const int frames = static_cast<int>(std::lround(duration * fps)) + 1;
  out.frame_time = duration / (frames - 1);
  for (int f = 0; f < frames; ++f)
    out.times.push_back(f * out.frame_time);
  out.states = simulate_free_flight(
      out.model,
      [&joints](double t, BodyState<double>& s) {
        for (int k = 1; k < joints.segment_count(); ++k) {
          const auto q = joints.rotations[k].evaluate(t);
          s.joints[k] = {q.q, q.omega, q.alpha};
        }
      },
      initial, out.times);
  return out;
}

/// Through BVH text, as a file.
MocapClip as_file(const MocapClip& clip) {
  return parse_bvh(bvh_text(clip), "flight.bvh");
}

double max_rotation_error(const Motion& imported, const std::vector<BodyState<double>>& states,
                          int first_segment) {
  double worst = 0.0;
  for (std::size_t f = 0; f < imported.keyframes.size(); ++f)
    for (std::size_t s = first_segment; s < states[f].joints.size(); ++s)
      worst = std::max(
          worst, rotation_angle_between(imported.keyframes[f].rotations[s], states[f].joints[s].q));
  return worst;
}

TEST(CaptureImport, AnExactFreeFlightImportsExactly) {
  const FreeFlight flight = free_flight(30.0);
  const MocapClip clip =
      as_file(model_clip_from_states(flight.model, flight.frame_time, flight.states));
  const CaptureImport im = import_capture(clip, flight.model, guess_skeleton_mapping(clip));
  EXPECT_EQ(im.retargeting.mapping.convention, "Saltus");
  EXPECT_EQ(im.flight.method, "no ground contact");
  EXPECT_EQ(im.flight.first_frame, 0);
  EXPECT_EQ(im.flight.last_frame, static_cast<int>(flight.states.size()) - 1);
  EXPECT_DOUBLE_EQ(im.heading_yaw_deg, 0.0);  // Saltus's own frame is kept

  // Every joint rotation and root position as simulated (BVH keeps 17 digits).
  ASSERT_EQ(im.captured.keyframes.size(), flight.states.size());
  EXPECT_LT(max_rotation_error(im.captured, flight.states, 0), 1e-9);
  for (std::size_t f = 0; f < flight.states.size(); ++f)
    EXPECT_LT((*im.captured.keyframes[f].root_position - flight.states[f].root_position).norm(),
              1e-9);

  // The take-off state the simulation started from, and the gravity it fell at.
  EXPECT_LT((im.takeoff_fit.position - flight.source.takeoff.com_position).norm(), 1e-6);
  EXPECT_LT((im.takeoff_fit.velocity - flight.source.takeoff.com_velocity).norm(), 1e-6);
  EXPECT_LT(im.takeoff_fit.max_residual_m, 1e-6);
  EXPECT_NEAR(im.implied_gravity, 9.81, 1e-5);
  EXPECT_FALSE(im.suggested_frame_time.has_value());
  // The angular momentum the simulation conserved, from inverse dynamics of the spline through
  // the frames.
  EXPECT_LT((im.angular_momentum.mean - kAngularMomentum).norm(), 1e-3 * kAngularMomentum.norm());
  EXPECT_LT(im.angular_momentum.max_deviation, 0.02 * kAngularMomentum.norm());
  // The capture's own residual: an exact flight through 30 Hz frames, the splines' ends
  // extrapolated (captured_trajectory).
  EXPECT_LT(im.metrics.avg_root_force, 5.0);
  EXPECT_GT(im.pick.frames.size(), 3u);
  EXPECT_LE(im.pick.max_quaternion_error, im.captured.tolerances.quaternion);

  // The clip's poses for drawing: on the motions' clock, the model's CoM where the fit says.
  const CaptureClipPoses poses = capture_clip_poses(im);
  ASSERT_EQ(poses.states.size(), flight.states.size());
  const std::vector<SampleRecord> drawn = evaluate_states(flight.model, poses.times, poses.states);
  for (std::size_t f = 0; f < drawn.size(); ++f) {
    EXPECT_NEAR(poses.times[f], flight.times[f], 1e-12);
    const double t = poses.times[f];
    const Eigen::Vector3d parabola = im.takeoff_fit.position + im.takeoff_fit.velocity * t +
                                     0.5 * im.takeoff_fit.acceleration * t * t;
    EXPECT_LT((drawn[f].com - parabola).norm(), 1e-6) << f;
  }
}

TEST(CaptureImport, AnExactFreeFlightsKeyframesOptimiseToNearZero) {
  const FreeFlight flight = free_flight(30.0);
  const MocapClip clip =
      as_file(model_clip_from_states(flight.model, flight.frame_time, flight.states));
  const CaptureImport im = import_capture(clip, flight.model, guess_skeleton_mapping(clip));
  // As the ground-truth test: refined knots, so that the true flight is (nearly) representable.
  OptimizeOptions options;
  options.nlp.knots_per_interval = 3;
  const OptimizationResult r = optimize_motion(im.keyframes, flight.model, options);
  std::printf("free flight, %zu picked keyframes: %s after %d iterations; %.3f -> %.3f N\n",
              im.keyframes.keyframes.size(), r.solve.status.c_str(), r.solve.iterations,
              r.before.metrics.avg_root_force, r.after.metrics.avg_root_force);
  EXPECT_TRUE(r.solve.solved) << r.solve.status;
  EXPECT_LT(r.after.metrics.avg_root_force, 0.5);
}

TEST(CaptureImport, OtherConventionsImportToTheSameMotion) {
  const FreeFlight flight = free_flight(30.0);
  const MocapClip saltus =
      as_file(model_clip_from_states(flight.model, flight.frame_time, flight.states));
  const CaptureImport reference =
      import_capture(saltus, flight.model, guess_skeleton_mapping(saltus));
  for (const auto& [label, convention] :
       {std::pair<std::string, test::CaptureConvention>{"Mixamo", test::mixamo_convention()},
        {"CMU", test::cmu_convention()},
        {"Rigify", test::rigify_convention()}}) {
    const MocapClip clip = as_file(test::convert_clip(saltus, convention));
    const CaptureImport im = import_capture(clip, flight.model, guess_skeleton_mapping(clip));
    EXPECT_EQ(im.retargeting.mapping.convention, label);
    EXPECT_EQ(im.flight.frame_count(), reference.flight.frame_count()) << label;
    // The joints below the root are relative rotations: exact. The root's heading comes from
    // the flight's angular momentum, a spline derivative: close.
    EXPECT_LT(max_rotation_error(im.captured, flight.states, 1), 1e-9) << label;
    double root = 0.0, position = 0.0;
    for (std::size_t f = 0; f < flight.states.size(); ++f) {
      root = std::max(root, rotation_angle_between(im.captured.keyframes[f].rotations[0],
                                                   flight.states[f].joints[0].q));
      position = std::max(
          position,
          (*im.captured.keyframes[f].root_position - flight.states[f].root_position).norm());
    }
    EXPECT_LT(root, 1e-5) << label;
    EXPECT_LT(position, 1e-4) << label;
    EXPECT_NEAR(im.heading_yaw_deg, -convention.performance_yaw_deg, 1e-3) << label;
    EXPECT_LT((im.angular_momentum.mean - reference.angular_momentum.mean).norm(), 1e-3) << label;
    EXPECT_EQ(im.pick.frames, reference.pick.frames) << label;
  }
}

TEST(CaptureImport, ExportThenImportGivesTheSameJointRotations) {
  // A twisting example: three-axis rotations, exported from its interpolated trajectory.
  const MotionFile file = load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                           "/motions/M4-front-somersault-half-twist.motion.json");
  const test::TempDir dir;
  const std::string bvh = dir / "m4.bvh";
  const MocapClip written = export_motion_bvh(file, bvh, 50.0);
  const Trajectory<double> trajectory = motion_trajectory(file.motion, file.model);
  CaptureFileOptions options;
  options.import.flight = std::make_pair(0.0, file.motion.flight_time());
  const CaptureFile back = import_capture_file(bvh, options);
  ASSERT_EQ(back.import.captured.keyframes.size(), static_cast<std::size_t>(written.frame_count()));
  double worst = 0.0, position = 0.0;
  BodyState<double> state(file.model.size());
  for (const Keyframe& k : back.import.captured.keyframes) {
    trajectory.sample(k.time, state);
    for (int s = 0; s < file.model.size(); ++s)
      worst = std::max(worst, rotation_angle_between(k.rotations[s], state.joints[s].q));
    position = std::max(position, (*k.root_position - state.root_position).norm());
  }
  std::printf("M4 exported at 50 fps and imported: largest joint rotation error %.3g rad\n", worst);
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(position, 1e-9);
}

}  // namespace
}  // namespace saltus
