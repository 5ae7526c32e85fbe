// Keyframe interpolation (motion/interpolate.h, paper §5): the ballistic CoM of eq. 9, the root
// targets of eq. 10 checked through the body's own CoM, and the interpolated motion: through the
// keyframes, with its CoM on the parabola (computed by inverse dynamics, not by eq. 10's code);
// per-interval knot spans, and a trajectory refitted onto finer knots.

#include "saltus/motion/interpolate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "saltus/base/constants.h"
#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/math/quaternion.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// Whole-body CoM for the given root position and segment rotations, by inverse dynamics.
Eigen::Vector3d body_com(const BodyModel& model, const Eigen::Vector3d& root,
                         const std::vector<Eigen::Quaterniond>& rotations) {
  BodyState<double> state(model.size());
  state.root_position = root;
  for (int i = 0; i < model.size(); ++i)
    state.joints[i].q = rotations[i];
  DynamicsData<double> data(model);
  inverse_dynamics(model, data, state);
  return data.com;
}

TEST(BallisticCom, IsTheParabolaOfEquation9) {
  Takeoff takeoff;
  takeoff.com_position = Eigen::Vector3d(0.1, 1.2, -0.3);
  takeoff.com_velocity = Eigen::Vector3d(0.4, 7.0, 0.2);
  EXPECT_EQ(ballistic_com(takeoff, 0.0), takeoff.com_position);
  EXPECT_EQ(ballistic_com_velocity(takeoff, 0.0), takeoff.com_velocity);
  const double h = 1e-4;
  for (double t : {0.3, 1.0, 1.7}) {
    const Eigen::Vector3d rate =
        (ballistic_com(takeoff, t + h) - ballistic_com(takeoff, t - h)) / (2 * h);
    EXPECT_LT((ballistic_com_velocity(takeoff, t) - rate).norm(), 1e-9);
    const Eigen::Vector3d acceleration =
        (ballistic_com_velocity(takeoff, t + h) - ballistic_com_velocity(takeoff, t - h)) / (2 * h);
    EXPECT_LT((acceleration - gravity()).norm(), 1e-9);
  }
  // The apex, where the vertical velocity vanishes, is at t = v_y / g.
  EXPECT_NEAR(ballistic_com_velocity(takeoff, 7.0 / kStandardGravity).y(), 0.0, 1e-12);
}

TEST(KeyframeRootTargets, PutTheKeyframePosesCentreOfMassOnTheParabola) {
  const BodyModel model = test::bundled_model();
  Motion motion = test::twist_motion(model);
  motion.keyframes[2].root_position = Eigen::Vector3d(0.5, 4.0, 0.1);  // given: used as it is
  const std::vector<Eigen::Vector3d> targets = keyframe_root_targets(motion, model);
  ASSERT_EQ(targets.size(), motion.keyframes.size());
  EXPECT_EQ(targets[2], *motion.keyframes[2].root_position);
  for (std::size_t i : {0u, 1u, 3u}) {
    const Keyframe& k = motion.keyframes[i];
    EXPECT_LT(
        (body_com(model, targets[i], k.rotations) - ballistic_com(motion.takeoff, k.time)).norm(),
        1e-12)
        << i;
  }
  EXPECT_LT((com_with_root_at_origin(model, motion.keyframes[1].rotations) -
             body_com(model, Eigen::Vector3d::Zero(), motion.keyframes[1].rotations))
                .norm(),
            1e-15);
}

TEST(InterpolateKeyframes, PassesThroughTheKeyframes) {
  const BodyModel model = test::bundled_model();
  for (const Motion& motion :
       {test::tuck_motion(model), test::pike_motion(model), test::twist_motion(model)}) {
    for (int k : {1, 2, 3}) {
      InterpolationOptions options;
      options.knots_per_interval = k;
      const Trajectory<double> t = interpolate_keyframes(motion, model, options);
      EXPECT_EQ(t.segment_count(), model.size());
      EXPECT_EQ(t.duration(), motion.flight_time());
      EXPECT_EQ(control_count(t.knots), (static_cast<int>(motion.keyframes.size()) - 1) * k + 3);
      for (const Keyframe& key : motion.keyframes)
        for (int s = 0; s < model.size(); ++s)
          EXPECT_LT(rotation_angle_between(t.rotations[s].evaluate(key.time).q, key.rotations[s]),
                    1e-6)
              << motion.name << " K=" << k << " t=" << key.time << " segment " << s;
    }
  }
}

/// Largest distance of the interpolated body's CoM (by inverse dynamics) from the parabola.
double com_off_parabola(const BodyModel& model, const Motion& motion, const Trajectory<double>& t) {
  double worst = 0.0;
  for (int i = 0; i <= 400; ++i) {
    const double time = motion.flight_time() * i / 400;
    std::vector<Eigen::Quaterniond> pose;
    for (const auto& r : t.rotations)
      pose.push_back(r.evaluate(time).q);
    const Eigen::Vector3d com = body_com(model, t.root_translation.evaluate(time).position, pose);
    worst = std::max(worst, (com - ballistic_com(motion.takeoff, time)).norm());
  }
  return worst;
}

TEST(InterpolateKeyframes, RootCurveIsTheLeastSquaresFitThatPutsTheComOnTheParabola) {
  // Eqs. 9-10: the root must be at s(t) − s'(t). A cubic curve on the keyframe knots can only
  // approximate that, by least squares over root_fit_samples_per_span samples per span: the
  // residual is orthogonal to every basis function (up to the fit's 1e-9 smoothness term), and
  // the CoM comes closer to the parabola as the knots are refined.
  const BodyModel model = test::bundled_model();
  for (const Motion& motion : {test::tuck_motion(model), test::twist_motion(model)}) {
    double previous = std::numeric_limits<double>::infinity();
    for (int k : {1, 2, 3, 4}) {
      SCOPED_TRACE(motion.name + " K=" + std::to_string(k));
      InterpolationOptions options;
      options.knots_per_interval = k;
      options.root_fit_samples_per_span = 10;
      const Trajectory<double> t = interpolate_keyframes(motion, model, options);
      const int n = control_count(t.knots);
      const int samples = (n - 3) * options.root_fit_samples_per_span + 1;
      std::vector<Eigen::Vector3d> normal(n, Eigen::Vector3d::Zero());
      double scale = 0.0;
      for (int i = 0; i < samples; ++i) {
        const double time = motion.flight_time() * i / (samples - 1);
        std::vector<Eigen::Quaterniond> pose;
        for (const auto& r : t.rotations)
          pose.push_back(r.evaluate(time).q);
        const Eigen::Vector3d target =
            ballistic_com(motion.takeoff, time) - body_com(model, Eigen::Vector3d::Zero(), pose);
        const Eigen::Vector3d residual = t.root_translation.evaluate(time).position - target;
        const SpanBasis<double> basis = cubic_basis(t.knots, time);
        for (int a = 0; a < 4; ++a)
          normal[basis.first_control() + a] += basis.value[0][a] * residual;
        scale = std::max(scale, residual.norm());
      }
      ASSERT_GT(scale, 1e-4) << "the fit must have something to do";
      for (int j = 0; j < n; ++j)
        EXPECT_LT(normal[j].norm(), 1e-6) << "control " << j;
      const double off = com_off_parabola(model, motion, t);
      EXPECT_LT(off, previous);
      previous = off;
    }
  }
}

// A root guide turns the root's curve the long way: the root keyed at 0 and 270 deg about the
// long axis y over 1 s turns -90 deg the short way; through guides at 90 and 180 deg it turns
// +270 deg, passing the guides and both keyframes.
TEST(InterpolateKeyframes, RootGuidesTurnTheRootTheirWayRound) {
  const BodyModel model = test::bundled_model();
  Motion motion = test::base_motion("spin");
  const auto about_y = [](double deg) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(deg / kDegreesPerRadian, Eigen::Vector3d::UnitY()));
  };
  for (const double t : {0.0, 1.0}) {
    Keyframe k;
    k.time = t;
    k.rotations.assign(model.size(), Eigen::Quaterniond::Identity());
    k.rotations[0] = about_y(270.0 * t);
    motion.keyframes.push_back(k);
  }
  const auto turn_about_y = [](const Trajectory<double>& trajectory, double t) {
    const Eigen::Quaterniond q = trajectory.rotations[0].evaluate(t).q;
    const double deg = 2.0 * std::atan2(q.y(), q.w()) * kDegreesPerRadian;  // q and -q: ±360
    return std::remainder(deg, 360.0);
  };
  InterpolationOptions options;
  options.knots_per_interval = 3;
  EXPECT_NEAR(turn_about_y(interpolate_keyframes(motion, model, options), 0.5), -45.0, 1.0);
  options.root_guides = {{1.0 / 3.0, about_y(90.0)}, {2.0 / 3.0, about_y(180.0)}};
  const Trajectory<double> guided = interpolate_keyframes(motion, model, options);
  EXPECT_NEAR(turn_about_y(guided, 0.5), 135.0, 5.0);
  for (const auto& [t, q] : options.root_guides)
    EXPECT_LT(guided.rotations[0].evaluate(t).q.angularDistance(q), 1e-6);
  EXPECT_LT(guided.rotations[0].evaluate(1.0).q.angularDistance(about_y(270.0)), 1e-6);
}

TEST(InterpolateKeyframes, SpansPerIntervalSplitEachKeyframeIntervalEvenly) {
  // subdivisions = {K_i}: interval i holds K_i equal knot spans, the curve still passes through
  // every keyframe, and all-equal subdivisions are exactly the uniform knots_per_interval.
  const BodyModel model = test::bundled_model();
  const Motion motion = test::tuck_motion(model);
  const std::vector<int> subdivisions = {1, 3, 2, 4};
  InterpolationOptions options;
  options.knots_per_interval = 2;  // ignored: the subdivisions replace it
  options.subdivisions = subdivisions;
  const Trajectory<double> t = interpolate_keyframes(motion, model, options);
  ASSERT_EQ(control_count(t.knots), 1 + 3 + 2 + 4 + 3);
  std::size_t knot = 3;  // the first breakpoint of the clamped cubic knots
  for (std::size_t i = 0; i < subdivisions.size(); ++i) {
    const double start = motion.keyframes[i].time, end = motion.keyframes[i + 1].time;
    for (int j = 0; j < subdivisions[i]; ++j, ++knot) {
      EXPECT_NEAR(t.knots[knot], start + (end - start) * j / subdivisions[i], 1e-15);
      EXPECT_NEAR(t.knots[knot + 1] - t.knots[knot], (end - start) / subdivisions[i], 1e-14);
    }
  }
  EXPECT_EQ(t.knots[knot], motion.flight_time());
  for (const Keyframe& key : motion.keyframes)
    for (int s = 0; s < model.size(); ++s)
      EXPECT_LT(rotation_angle_between(t.rotations[s].evaluate(key.time).q, key.rotations[s]), 1e-6)
          << "t=" << key.time << " segment " << s;

  InterpolationOptions uniform, listed;
  uniform.knots_per_interval = 3;
  listed.subdivisions.assign(motion.keyframes.size() - 1, 3);
  const Trajectory<double> a = interpolate_keyframes(motion, model, uniform);
  const Trajectory<double> b = interpolate_keyframes(motion, model, listed);
  EXPECT_EQ(a.knots, b.knots);
  EXPECT_EQ(a.root_translation.control(), b.root_translation.control());
  for (int s = 0; s < model.size(); ++s)
    for (std::size_t j = 0; j < a.rotations[s].control().size(); ++j)
      EXPECT_EQ(a.rotations[s].control()[j].coeffs(), b.rotations[s].control()[j].coeffs());

  options.subdivisions = {1, 2, 1};  // one short
  EXPECT_THROW(interpolate_keyframes(motion, model, options), std::invalid_argument);
  options.subdivisions = {1, 0, 1, 1};
  EXPECT_THROW(interpolate_keyframes(motion, model, options), std::invalid_argument);
}

TEST(RefitTrajectory, KeepsTheCurveOnItsOwnOrRefinedKnots) {
  // The cubic root translation lies in the space of its own knots and of any refinement of them,
  // so the least-squares refit gives it back up to the fit's 1e-9 smoothness term. A rotation
  // curve (cumulative quaternion form) is refitted in its own nonlinear form: on its own knots it
  // comes back to a thousandth of a degree; halved spans do not contain it exactly, yet stay
  // within a degree of it (the body turns by hundreds).
  const BodyModel model = test::bundled_model();
  for (const Motion& motion : {test::tuck_motion(model), test::twist_motion(model)}) {
    const Trajectory<double> coarse = interpolate_keyframes(motion, model);
    std::vector<double> times;
    for (const Keyframe& key : motion.keyframes)
      times.push_back(key.time);
    const std::vector<double> halved = clamped_cubic_knots(refine_breakpoints(times, 2));
    for (bool refined : {false, true}) {
      const std::vector<double>& knots = refined ? halved : coarse.knots;
      const Trajectory<double> fitted = refit_trajectory(coarse, knots);
      EXPECT_EQ(fitted.knots, knots);
      ASSERT_EQ(fitted.segment_count(), coarse.segment_count());
      double worst_root = 0.0, worst_angle = 0.0;
      for (int i = 0; i <= 500; ++i) {
        const double t = motion.flight_time() * i / 500;
        worst_root = std::max(worst_root, (fitted.root_translation.evaluate(t).position -
                                           coarse.root_translation.evaluate(t).position)
                                              .norm());
        for (int s = 0; s < model.size(); ++s)
          worst_angle =
              std::max(worst_angle, rotation_angle_between(fitted.rotations[s].evaluate(t).q,
                                                           coarse.rotations[s].evaluate(t).q));
      }
      SCOPED_TRACE(motion.name + (refined ? " on halved spans" : " on its own knots"));
      EXPECT_LT(worst_root, 1e-8);
      EXPECT_LT(worst_angle * kDegreesPerRadian, refined ? 1.0 : 1e-3);
    }
  }
}

TEST(InterpolateKeyframes, RejectsTooFewKeyframesOrKnots) {
  const BodyModel model = test::bundled_model();
  Motion motion = test::pike_motion(model);
  InterpolationOptions options;
  options.knots_per_interval = 0;
  EXPECT_THROW(interpolate_keyframes(motion, model, options), std::invalid_argument);
  motion.keyframes.resize(1);
  EXPECT_THROW(interpolate_keyframes(motion, model), std::invalid_argument);
}

TEST(StoredSpline, ReloadsTheTrajectoryExactlyAndTakesPrecedence) {
  const BodyModel model = test::bundled_model();
  Motion motion = test::tuck_motion(model);
  InterpolationOptions options;
  options.knots_per_interval = 2;
  const Trajectory<double> original = interpolate_keyframes(motion, model, options);
  const StoredSpline stored = to_stored_spline(original);
  const Trajectory<double> reloaded = trajectory_from_stored_spline(stored, model);
  for (double t : {0.0, 0.33, 1.21, 2.04}) {
    EXPECT_EQ(reloaded.root_translation.evaluate(t).position,
              original.root_translation.evaluate(t).position);
    for (int s = 0; s < model.size(); ++s)
      EXPECT_EQ(reloaded.rotations[s].evaluate(t).q.coeffs(),
                original.rotations[s].evaluate(t).q.coeffs());
  }
  // motion_trajectory: the stored spline when there is one, whatever the options say.
  EXPECT_EQ(motion_trajectory(motion, model).knots.size(), motion.keyframes.size() + 6);
  motion.spline = stored;
  EXPECT_EQ(motion_trajectory(motion, model).knots, original.knots);
  StoredSpline short_of_joints = stored;
  short_of_joints.joint_control.pop_back();
  EXPECT_THROW(trajectory_from_stored_spline(short_of_joints, model), std::invalid_argument);
}

}  // namespace
}  // namespace saltus
