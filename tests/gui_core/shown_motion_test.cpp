// The subject of the Twist and What if panels (core/shown_motion.h): the motion the 3D view
// shows, with the model and options to evaluate it, described as what the report is about, and
// keyed so that an edit or another motion is another subject.

#include "core/shown_motion.h"

#include <gtest/gtest.h>

#include <memory>

#include "saltus/formats/motion_file.h"
#include "saltus/motion/interpolate.h"
#include "support/temp_path.h"

namespace saltus::gui {
namespace {

std::string shown_motion_path(const std::string& name) {
  return std::string(SALTUS_EXAMPLES_DIR) + "/motions/" + name;
}

TEST(ShownMotion, TheInterpolatedKeyframesUntilARunIsShown) {
  for (SavedTrajectory saved : {SavedTrajectory::kFlown, SavedTrajectory::kReinterpolated}) {
    Workspace ws;
    EXPECT_FALSE(shown_motion_subject(ws, saved));
    ws.open(shown_motion_path("M1-straight-back-somersault.motion.json"), "", 41);
    const std::optional<ShownMotion> s = shown_motion_subject(ws, saved);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->description, "the interpolated keyframes");
    EXPECT_EQ(s->key.run, -1);
    EXPECT_EQ(s->options.samples, 41);
    EXPECT_EQ(s->motion.name, ws.document().file().motion.name);
    EXPECT_EQ(s->motion.keyframes.size(), ws.document().file().motion.keyframes.size());
    // Another motion (or an edit) is another subject, even with the same run.
    const ShownMotion::Key first = s->key;
    ws.open(shown_motion_path("M1-straight-back-somersault.motion.json"), "", 41);
    EXPECT_NE(shown_motion_subject(ws, saved)->key, first);
  }
}

TEST(ShownMotion, AnEditIsAnotherSubject) {
  Workspace ws;
  ws.open(shown_motion_path("M2-tucked-back-somersault.motion.json"));
  const std::optional<ShownMotion> first = shown_motion_subject(ws, SavedTrajectory::kFlown);
  ASSERT_TRUE(first);
  Motion edited = ws.document().file().motion;
  edited.keyframes[1].time += 0.01;
  ws.set_motion(edited);
  const std::optional<ShownMotion> second = shown_motion_subject(ws, SavedTrajectory::kFlown);
  ASSERT_TRUE(second);
  EXPECT_NE(second->key, first->key);
  EXPECT_EQ(second->motion.keyframes[1].time, edited.keyframes[1].time);
}

TEST(ShownMotion, ASavedTrajectoryIsCalledWhatTheReportMakesOfIt) {
  const std::string saved_path = saltus::test::temp_path("shown-saved.motion.json").string();
  MotionFile f = load_motion_file(shown_motion_path("M1-straight-back-somersault.motion.json"));
  f.motion.spline = to_stored_spline(interpolate_keyframes(f.motion, f.model, {}));
  save_motion_file(saved_path, f.motion, f.model);
  Workspace ws;
  ws.open(saved_path);
  const std::optional<ShownMotion> flown = shown_motion_subject(ws, SavedTrajectory::kFlown);
  ASSERT_TRUE(flown);
  ASSERT_TRUE(flown->motion.spline);
  EXPECT_EQ(flown->description, "the optimised trajectory, as saved");
  const std::optional<ShownMotion> redone =
      shown_motion_subject(ws, SavedTrajectory::kReinterpolated);
  ASSERT_TRUE(redone);
  EXPECT_EQ(redone->description, "the interpolated keyframes");
  EXPECT_EQ(redone->key, flown->key) << "the same motion, whatever the report makes of it";
}

}  // namespace
}  // namespace saltus::gui

namespace saltus::gui {
namespace {

TEST(MotionToSave, IsTheOptimisedMotionOfTheRunShownElseTheKeyframesWithTheirDescription) {
  Workspace ws;
  EXPECT_FALSE(motion_to_save(ws));
  ws.open(shown_motion_path("M7-double-front-one-and-a-half-twists.motion.json"), "", 21);
  const Motion given = ws.document().file().motion;
  ASSERT_FALSE(given.description.empty());
  std::optional<MotionToSave> save = motion_to_save(ws);
  ASSERT_TRUE(save);
  EXPECT_FALSE(save->optimised);
  EXPECT_EQ(save->what, "the keyframes as given");
  EXPECT_EQ(save->motion.description, given.description);
  EXPECT_EQ(save->file_name("M7"), "M7.motion.json");

  // A run whose optimised motion has other keyframe times and a spline of its own.
  auto result = std::make_shared<OptimizationResult>();
  result->solve.status = "solved";
  result->solve.solved = true;
  result->before = ws.document().evaluation(Stage::kBefore);
  result->after = result->before;
  result->after.metrics.avg_root_force = 0.2;
  result->optimized_motion = given;
  result->optimized_motion.keyframes[1].time += 0.01;
  result->optimized_motion.spline = to_stored_spline(
      interpolate_keyframes(result->optimized_motion, ws.document().file().model, {}));
  RunRecord run;
  run.result = result;
  ws.add_run(run);
  ASSERT_EQ(ws.stage(), Stage::kAfter);
  save = motion_to_save(ws);
  ASSERT_TRUE(save);
  EXPECT_TRUE(save->optimised);
  EXPECT_EQ(save->run_number, 1);
  EXPECT_EQ(save->what,
            "the optimised motion of run 1 (keyframes at their optimised times, with its spline)");
  EXPECT_EQ(save->motion.keyframes[1].time, given.keyframes[1].time + 0.01);
  ASSERT_TRUE(save->motion.spline);
  EXPECT_EQ(save->motion.spline->knots, result->optimized_motion.spline->knots);
  EXPECT_EQ(save->motion.description, given.description);
  EXPECT_EQ(save->file_name("M7"), "M7-run1-optimised.motion.json");
  // The given keyframes stay one choice away.
  EXPECT_EQ(given_keyframes_to_save(ws)->motion.keyframes[1].time, given.keyframes[1].time);
  // Before: the keyframes are on screen.
  ws.set_stage(Stage::kBefore);
  EXPECT_FALSE(motion_to_save(ws)->optimised);
  // Edited keyframes are called so.
  Motion edited = given;
  edited.keyframes[2].time += 0.01;
  ws.set_motion(edited);
  EXPECT_EQ(motion_to_save(ws)->what, "the keyframes as edited");
  EXPECT_EQ(motion_to_save(ws)->file_name("M7"), "M7-edited.motion.json");
}

}  // namespace
}  // namespace saltus::gui
