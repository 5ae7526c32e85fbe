// A seeded family of athletes (support/athlete_family.h): de Leva's people from 1.2 to 2.0 m and
// 25 to 120 kg (a plausible body mass index, both sexes) and Yeadon's measured man with every
// measurement scaled by its own random factor in [0.9, 1.1]. Every model passes the model reader; a
// twisting free flight on each conserves angular momentum, L(t) computed here from the segments'
// masses, inertias and finite-differenced motion, not by the library's momentum code; and M1
// optimises to a true residual of at most 0.5 N on the smallest, the heaviest and a measured
// athlete; a twist that flies off on a light athlete is made again weighing the root moment, and
// its polish skips bounded tries once one lands far off; a twist on the heaviest man keeps his
// joints near what his own input needs.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "saltus/evaluation/joint_loads.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/optim/optimize.h"
#include "saltus/use_cases/athlete_models.h"
#include "support/athlete_family.h"

namespace saltus {
namespace {

using test::FamilyMember;

/// The family (support/athlete_family.h), with what its making must show checked on first use:
/// every de Leva person has the height and mass asked for, every perturbed Yeadon file scales
/// Yeadon's 95 measurements, and the reader refuses at most 6 of them, each naming the file and
/// the key.
const std::vector<FamilyMember>& family() {
  static const std::vector<FamilyMember>& members = [] {
    const test::AthleteFamily& made = test::athlete_family();
    for (const FamilyMember& member : made.members) {
      if (!member.size) continue;
      EXPECT_NEAR(standing_body(member.model).height(), member.size->height_m, 1e-9);
      EXPECT_NEAR(member.model.total_mass(), member.size->mass_kg, 1e-9);
    }
    for (const int scaled : made.scaled)
      EXPECT_EQ(scaled, 95) << "Yeadon's measurements";
    for (const test::RefusedMeasurements& refused : made.refused) {
      EXPECT_NE(refused.what.find(refused.measurements), std::string::npos) << refused.what;
      EXPECT_NE(refused.what.find("is too small for the width"), std::string::npos) << refused.what;
    }
    EXPECT_LE(made.refused.size(), 6u) << "of the perturbed Yeadon files";
    return made.members;
  }();
  return members;
}

std::string motion_path(const std::string& name) {
  return std::string(SALTUS_EXAMPLES_DIR) + "/motions/" + name;
}

/// Whole-body angular momentum about the CoM at sample k (interior), world, kg·m²/s: each
/// segment's spin R·I·Rᵀ·ω plus its CoM's moment of momentum, with ω and the CoM velocities by
/// central differences of the sampled rotations and positions.
Eigen::Vector3d angular_momentum_from_motion(const BodyModel& model,
                                             const std::vector<SampleRecord>& samples, int k) {
  const SampleRecord &prev = samples[k - 1], &here = samples[k], &next = samples[k + 1];
  const double dt = next.time - prev.time;
  auto com_of = [&](const SampleRecord& s, int i) {
    return Eigen::Vector3d(s.segment_position[i] + s.segment_rotation[i] * model.segments[i].com);
  };
  double mass = 0.0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero(), com_velocity = Eigen::Vector3d::Zero();
  for (int i = 0; i < model.size(); ++i) {
    const double m = model.segments[i].mass;
    mass += m;
    com += m * com_of(here, i);
    com_velocity += m * (com_of(next, i) - com_of(prev, i)) / dt;
  }
  com /= mass;
  com_velocity /= mass;
  Eigen::Vector3d l = Eigen::Vector3d::Zero();
  for (int i = 0; i < model.size(); ++i) {
    const Segment& s = model.segments[i];
    const Eigen::AngleAxisd turn(next.segment_rotation[i] * prev.segment_rotation[i].inverse());
    const Eigen::Vector3d omega = turn.axis() * turn.angle() / dt;
    const Eigen::Matrix3d r = here.segment_rotation[i].toRotationMatrix();
    const Eigen::Vector3d velocity = (com_of(next, i) - com_of(prev, i)) / dt;
    l += r * s.inertia * r.transpose() * omega +
         s.mass * (com_of(here, i) - com).cross(velocity - com_velocity);
  }
  return l;
}

TEST(AthleteFamily, EveryModelFliesATwistingSkillConservingAngularMomentum) {
  ASSERT_EQ(family().size(), 12u);
  for (const FamilyMember& member : family()) {
    SCOPED_TRACE(member.model.name);
    const MotionFile file = load_motion_for_athlete(
        motion_path("M5-front-somersault-one-and-a-half-twists.motion.json"), member.path,
        TakeoffRule::kSameSpin);
    EvaluateOptions options;
    options.samples = 1201;
    const SimulationResult flight = simulate_motion(file.motion, file.model, options);
    const Eigen::Vector3d takeoff = flight.angular_momentum;
    ASSERT_GT(takeoff.norm(), 1.0);
    double drift = 0.0, library_drift = 0.0;
    for (int k = 1; k + 1 < static_cast<int>(flight.samples.size()); ++k) {
      drift = std::max(
          drift, (angular_momentum_from_motion(file.model, flight.samples, k) - takeoff).norm());
      library_drift =
          std::max(library_drift, (flight.samples[k].angular_momentum - takeoff).norm());
    }
    EXPECT_LT(drift, 2e-4 * takeoff.norm()) << "|L| " << takeoff.norm();
    EXPECT_LT(library_drift, 1e-6 * takeoff.norm()) << "|L| " << takeoff.norm();
  }
}

TEST(AthleteFamily, M1IsMadePhysicalOnTheSmallestTheHeaviestAndAMeasuredAthlete) {
  const std::vector<FamilyMember>& members = family();
  auto by_mass = [](const FamilyMember& a, const FamilyMember& b) {
    return a.model.total_mass() < b.model.total_mass();
  };
  const std::vector<const FamilyMember*> chosen = {
      &*std::min_element(members.begin(), members.begin() + 8, by_mass),
      &*std::max_element(members.begin(), members.begin() + 8, by_mass), &members[8]};
  for (const FamilyMember* member : chosen) {
    SCOPED_TRACE(member->model.name);
    const MotionFile file =
        load_motion_for_athlete(motion_path("M1-straight-back-somersault.motion.json"),
                                member->path, TakeoffRule::kSameSpin);
    const OptimizationResult result = optimize_motion(file.motion, file.model, OptimizeOptions{});
    EXPECT_TRUE(result.solve.solved) << result.solve.status;
    EXPECT_LE(result.after.check.metrics.avg_root_force, 0.5)
        << "before " << result.before.check.metrics.avg_root_force << " N";
  }
}

/// M6 (a half twist into 1½ front) flown by `member`, its take-off by the same spin, as
/// `saltus optimize --model` flies it.
MotionFile m6_for(const FamilyMember& member) {
  return load_motion_for_athlete(motion_path("M6-half-twist-into-one-and-a-half-front.motion.json"),
                                 member.path, TakeoffRule::kSameSpin);
}

/// What a returned motion must show: its own free flight, run here, lands within the 3° bar, and
/// its true residual is at most 0.5 N.
void expect_lands_near_zero(const OptimizationResult& result, const BodyModel& model) {
  EXPECT_LE(simulate_motion(result.optimized_motion, model).landing_vs_motion_deg, 3.0);
  EXPECT_LE(result.after.check.metrics.avg_root_force, 0.5);
}

/// M6 (a half twist into 1½ front) on a 1.29 m, 36.9 kg girl: the levels of the paper's
/// objective end near zero root force but the motion's own free flight lands tens of degrees off
/// (its root moment, a few tenths of a N·m, turns this light body's twist). The levels then run
/// again weighing the root moment (kLandingRootMomentWeight) and that motion is kept: what is
/// returned lands within the 3° bar, by a free flight run here, at most 0.5 N. Least joint effort
/// is left out: only the levels are under test.
TEST(AthleteFamily, ATwistThatFliesOffIsMadeAgainWeighingTheRootMoment) {
  const FamilyMember& girl = family()[2];
  ASSERT_EQ(girl.model.name, "family-2");
  const MotionFile file = m6_for(girl);
  OptimizeOptions options;
  options.nlp.joint_load_weight = 0.0;
  const OptimizationResult result = optimize_motion(file.motion, file.model, options);
  ASSERT_TRUE(result.solve.solved) << result.solve.status;
  // The first pass (weight 1) ended off; a second (the landing weight) followed.
  double first_pass_best = 1e9, first_pass_force = 1e9;
  int weighed_levels = 0;
  for (const OptimizationResult::Level& level : result.levels) {
    if (level.root_moment_weight == 1.0 && level.avg_root_force < first_pass_force) {
      first_pass_force = level.avg_root_force;
      first_pass_best = level.landing_drift_deg;
    }
    weighed_levels += level.root_moment_weight == kLandingRootMomentWeight;
  }
  EXPECT_GT(first_pass_best, 3.0) << "the paper's objective alone";
  EXPECT_GT(weighed_levels, 0);
  const double flown = simulate_motion(result.optimized_motion, file.model).landing_vs_motion_deg;
  ASSERT_TRUE(result.landing_drift_deg);
  EXPECT_NEAR(*result.landing_drift_deg, flown, 0.01);
  EXPECT_LE(flown, 3.0);
  EXPECT_LE(result.after.check.metrics.avg_root_force, 0.5);
}

/// M6 on the same girl with least joint effort: the polish's first bounded try lands 120-143 deg
/// off, farther than the motion it would replace, so its other bounded steps are skipped and it
/// goes on to the unbounded one (kPolishHopelessDriftFactor). What is returned still lands
/// within 3 deg, and says what human joints would have cost: a bounded try that holds the root
/// force and every joint within 1.5x, whose free flight lands far from it.
TEST(AthleteFamily, OnALightAthleteThePolishSkipsBoundedTriesAfterOneLandsFarOff) {
  const FamilyMember& girl = family()[2];
  ASSERT_EQ(girl.model.name, "family-2");
  const MotionFile file = m6_for(girl);
  const OptimizationResult result = optimize_motion(file.motion, file.model, OptimizeOptions{});
  ASSERT_TRUE(result.solve.solved) << result.solve.status;
  ASSERT_TRUE(result.joint_load_polish);
  const JointLoadPolish& polish = *result.joint_load_polish;
  EXPECT_GT(polish.bounded_tries_skipped, 0);
  EXPECT_EQ(polish.attempts, kPolishAttempts);
  EXPECT_EQ(polish.joint_bound, 0.0) << "the last step is the unbounded one";
  expect_lands_near_zero(result, file.model);
  ASSERT_TRUE(polish.bounded_alternative);
  EXPECT_GT(polish.bounded_alternative->landing_drift_deg, 15.0);
  EXPECT_LE(polish.bounded_alternative->avg_root_force, 0.5);
  EXPECT_LE(polish.bounded_alternative->joint_rise, 1.5);
}

/// M6 on the 2.0 m, 120 kg man: the polish's bounded tries at the root moment weighed 100 and
/// 300 times landed 3.0-5.2 deg off (the 3 deg bar), and the fourth step, 1000 times, was the
/// first within it; since the end spans have six nodes the third step (300 times) was, and since
/// the second and third start from the try before, the fourth again (from the levels). What is
/// returned keeps every joint within 1.5x of the peak his own interpolated input needs there
/// (without those steps no try was kept and his left ankle stayed at 14x), lands within 3 deg
/// by a free flight run here, at most 0.5 N.
TEST(AthleteFamily, ATwistOnTheHeaviestManKeepsHisJointsNearWhatHisInputNeeds) {
  const FamilyMember& man = family()[1];
  ASSERT_EQ(man.model.name, "family-1");
  const MotionFile file = m6_for(man);
  const OptimizationResult result = optimize_motion(file.motion, file.model, OptimizeOptions{});
  ASSERT_TRUE(result.solve.solved) << result.solve.status;
  ASSERT_TRUE(result.joint_load_polish);
  const JointLoadPolish& polish = *result.joint_load_polish;
  EXPECT_TRUE(polish.kept);
  EXPECT_EQ(polish.joint_bound, kPolishJointBound);
  ASSERT_GE(polish.attempts, 1);
  ASSERT_LE(polish.attempts, kPolishAttempts);
  EXPECT_EQ(polish.root_moment_weight, kPolishTries[polish.attempts - 1].root_moment_weight);
  EXPECT_GE(polish.root_moment_weight, 3.0 * kPolishRootMomentWeight) << "a later bounded step";
  EXPECT_LE(largest_joint_load_rise(file.model, result.before.check, result.after.check).ratio(),
            1.5);
  expect_lands_near_zero(result, file.model);
}

MotionFile dive_for(const FamilyMember& athlete) {
  return load_motion_for_athlete(motion_path("dive-5m-front-one-and-a-half-twists.motion.json"),
                                 athlete.path, TakeoffRule::kSameSpin);
}

/// The 5 m dive on the same man: the levels buy their root force with a joint at 7x his input,
/// and no bounded try holds 0.5 N on the levels' knots. Which later step is kept (the best
/// bounded try solved again on finer knots on this machine; a bounded try up to 1 N over paying
/// joints on another CPU and BLAS, 0.57 N) follows the rounding, so the test holds what the
/// method guarantees whichever it is: a bounded try is kept, every joint within 1.5x, at most
/// 0.5 N on finer knots or 1 N on the levels' (the joints paid there), landing within 3 deg by a
/// free flight run here.
TEST(AthleteFamily, ADiveWhoseJointsPaidKeepsABoundedTry) {
  const FamilyMember& man = family()[1];
  ASSERT_EQ(man.model.name, "family-1");
  const MotionFile file = dive_for(man);
  const OptimizationResult result = optimize_motion(file.motion, file.model, OptimizeOptions{});
  ASSERT_TRUE(result.solve.solved) << result.solve.status;
  ASSERT_TRUE(result.joint_load_polish);
  const JointLoadPolish& polish = *result.joint_load_polish;
  EXPECT_TRUE(polish.kept);
  EXPECT_GT(polish.joint_bound, 0.0) << "a bounded try";
  EXPECT_GT(polish.joint_rise_before, kJointLoadRiseLimit);
  EXPECT_LE(largest_joint_load_rise(file.model, result.before.check, result.after.check).ratio(),
            kJointLoadRiseLimit);
  EXPECT_LE(simulate_motion(result.optimized_motion, file.model).landing_vs_motion_deg, 3.0);
  EXPECT_LE(result.after.check.metrics.avg_root_force,
            polish.knots_refined ? kPolishMaxRootForce : kPolishMaxRootForceOverPayingJoints);
  if (!polish.knots_refined) return;
  // Refined: on more spans than any level ended with.
  int level_spans = 0, returned_spans = 0;
  for (const OptimizationResult::Level& level : result.levels) {
    int spans_of_level = 0;
    for (const int spans : level.subdivisions)
      spans_of_level += spans;
    level_spans = std::max(level_spans, spans_of_level);
  }
  for (const int spans : result.subdivisions)
    returned_spans += spans;
  EXPECT_GT(returned_spans, level_spans) << "finer knots than the levels'";
}

/// The same dive at a resolution the user fixed, three spans an interval (the knots are the
/// user's, so none are refined): the levels pay with a joint at 3.7x, no bounded try holds 0.5 N,
/// and the one with the least root force, at most kPolishMaxRootForceOverPayingJoints, is kept
/// over the unbounded one: every joint within 1.5x, landing within 3 deg by a free flight run
/// here (measured 0.539 N, 1.30x).
TEST(AthleteFamily, AtAFixedResolutionADiveWhoseJointsPaidKeepsABoundedTryUpToOneNewton) {
  const FamilyMember& man = family()[1];
  const MotionFile file = dive_for(man);
  OptimizeOptions options;
  options.automatic_resolution = false;
  options.nlp.knots_per_interval = 3;
  const OptimizationResult result = optimize_motion(file.motion, file.model, options);
  ASSERT_TRUE(result.solve.solved) << result.solve.status;
  ASSERT_TRUE(result.joint_load_polish);
  const JointLoadPolish& polish = *result.joint_load_polish;
  EXPECT_TRUE(polish.kept);
  EXPECT_GT(polish.joint_bound, 0.0) << "a bounded try";
  EXPECT_FALSE(polish.knots_refined);
  EXPECT_GT(polish.joint_rise_before, kJointLoadRiseLimit);
  const double force = result.after.check.metrics.avg_root_force;
  EXPECT_GT(force, kPolishMaxRootForce) << "kept past the ordinary limit";
  EXPECT_LE(force, kPolishMaxRootForceOverPayingJoints);
  EXPECT_LE(largest_joint_load_rise(file.model, result.before.check, result.after.check).ratio(),
            kJointLoadRiseLimit);
  EXPECT_LE(simulate_motion(result.optimized_motion, file.model).landing_vs_motion_deg, 3.0);
}

}  // namespace
}  // namespace saltus
