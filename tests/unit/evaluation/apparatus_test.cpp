// The apparatus read off a flight: the bundled trampoline skill lands where it took off, the
// bundled platform dive starts from a 5 m platform and ends in the water at y = 0 (its motion
// file says so); the lowest body point of a standing body is its feet, found by hand here.

#include <gtest/gtest.h>

#include "saltus/evaluation/apparatus.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/formats/motion_file.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

struct Example {
  MotionFile file;
  MotionEvaluation evaluation;
};

Example evaluate_example(const std::string& name) {
  Example out{
      load_motion_file(std::string(SALTUS_EXAMPLES_DIR) + "/motions/" + name + ".motion.json"), {}};
  EvaluateOptions options;
  options.samples = 41;
  out.evaluation = evaluate_motion(out.file.motion, out.file.model, options);
  return out;
}

TEST(Apparatus, LowestPointOfAStandingBodyIsTheFootEnd) {
  const BodyModel model = test::bundled_model();
  BodyState<double> standing(model.size());
  standing.root_position = Eigen::Vector3d(0, 1.0, 0);
  const SampleRecord s = evaluate_states(model, {0.0}, {standing}).front();
  // By hand: down the chain abdomen -> pelvis -> thigh -> shank -> foot at the identity pose.
  double y = 1.0;
  int i = model.segment_index("foot_l");
  const double foot_end = model.segments[static_cast<std::size_t>(i)].shape.length;
  while (i > 0) {
    y += model.segments[static_cast<std::size_t>(i)].joint_position.y();
    i = model.segments[static_cast<std::size_t>(i)].parent;
  }
  EXPECT_NEAR(lowest_body_point(model, s), y + foot_end, 1e-12);
}

TEST(Apparatus, TheTrampolineSkillLandsWhereItTookOff) {
  const BodyModel model = test::bundled_model();
  const Example m1 = evaluate_example("M1-straight-back-somersault");
  const MotionEvaluation& e = m1.evaluation;
  const Apparatus a = apparatus_for(model, m1.file.motion.takeoff, e.samples);
  EXPECT_EQ(a.kind, ApparatusKind::kTrampoline);
  EXPECT_DOUBLE_EQ(a.landing_height, a.takeoff_height);
  EXPECT_NEAR(a.takeoff_height, lowest_body_point(model, e.samples.front()), 1e-12);
  // The bed lies along the way the athlete faces at take-off (+z at identity, docs/method.md), not
  // along the small drift of the take-off velocity (0.15, 10, 0.15).
  const Eigen::Vector3d facing =
      e.samples.front().segment_rotation.front() * Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(a.direction.dot(Eigen::Vector3d(facing.x(), 0, facing.z()).normalized()), 1.0, 1e-12);
  EXPECT_EQ(a.direction.y(), 0.0);
}

TEST(Apparatus, TheDiveStartsFromAFiveMetrePlatformAndEndsInTheWater) {
  const BodyModel model = test::bundled_model();
  const Example dive = evaluate_example("dive-5m-front-one-and-a-half-twists");
  const Apparatus a = apparatus_for(model, dive.file.motion.takeoff, dive.evaluation.samples);
  EXPECT_EQ(a.kind, ApparatusKind::kPlatform);
  EXPECT_NEAR(a.takeoff_height, 5.0, 0.25);
  // The motion ends when the hands reach the water at y = 0 (its description).
  EXPECT_NEAR(a.landing_height, 0.0, 0.1);
  // It leaves the platform along its take-off velocity (0, 4, -0.5): towards -z.
  EXPECT_NEAR(a.direction.z(), -1.0, 1e-9);
  EXPECT_NEAR(a.takeoff_point.z(), dive.file.motion.takeoff.com_position.z(), 1e-12);
}

}  // namespace
}  // namespace saltus
