// The subject of the Twist and What if panels (core/shown_motion.h): the motion the 3D view
// shows, with the model and options to evaluate it, described as what the report is about, and
// keyed so that an edit or another motion is another subject.

#include "core/shown_motion.h"

#include <gtest/gtest.h>

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
