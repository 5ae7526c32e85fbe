// The GUI's document: loading, exact samples at any time, stages, glyph scales, saving.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "core/document.h"
#include "gui_core/test_motion.h"
#include "saltus/base/input_error.h"
#include "saltus/formats/model_file.h"
#include "saltus/motion/interpolate.h"
#include "saltus/use_cases/athlete_models.h"
#include "support/temp_path.h"

namespace saltus::gui {
namespace {

namespace fs = std::filesystem;

TEST(Document, ASomersaultNotYetTurnedIsNamedByTheWholeFlightsDirection) {
  // M2 at take-off: "0.00 somersaults backward", as it turns, not "forward" from the sign of 0.
  EXPECT_EQ(somersault_direction(0.0, -1.0), "backward");
  EXPECT_EQ(somersault_direction(0.004, -1.0), "backward");
  EXPECT_EQ(somersault_direction(-0.3, -1.0), "backward");
  EXPECT_EQ(somersault_direction(0.0, 2.0), "forward");
  // Once it shows, its own sign (a flight may turn back a little at first).
  EXPECT_EQ(somersault_direction(0.01, -1.0), "forward");
  Document m2;
  m2.load(std::string(SALTUS_EXAMPLES_DIR) + "/motions/M2-tucked-back-somersault.motion.json");
  const std::vector<RotationSample>& turns = m2.rotation(Stage::kBefore);
  const double forward = forward_somersault_sign(m2.plot_samples(Stage::kBefore).front());
  EXPECT_EQ(
      somersault_direction(forward * turns.front().somersaults, forward * turns.back().somersaults),
      "backward");
}

TEST(Document, LoadsAndEvaluatesTheMotion) {
  Document d;
  EXPECT_FALSE(d.loaded());
  d.load(test::gui_test_motion_path(), "", 101);
  ASSERT_TRUE(d.loaded());
  EXPECT_FALSE(d.has_optimization());
  EXPECT_EQ(d.frame_count(Stage::kBefore), 101);
  EXPECT_EQ(d.available(Stage::kAfter), Stage::kBefore);
  EXPECT_DOUBLE_EQ(d.duration(), d.file().motion.flight_time());
  // Plots and teaching read the dense grid, which ends where the flight does.
  EXPECT_EQ(d.rotation(Stage::kBefore).size(),
            static_cast<std::size_t>(plot_samples_for(d.duration())));
  EXPECT_EQ(d.plot_samples(Stage::kBefore).size(),
            static_cast<std::size_t>(plot_samples_for(d.duration())));
  EXPECT_DOUBLE_EQ(d.plot_samples(Stage::kBefore).back().time, d.duration());
}

TEST(Document, SampleAtAGridTimeEqualsTheEvaluatedSample) {
  Document d;
  d.load(test::gui_test_motion_path(), "", 51);
  const SampleRecord& grid = d.evaluation(Stage::kBefore).samples[17];
  const SampleRecord exact = d.sample_at(Stage::kBefore, grid.time);
  EXPECT_LT((exact.com - grid.com).norm(), 1e-12);
  EXPECT_LT((exact.root_wrench - grid.root_wrench).norm(), 1e-9);
  for (std::size_t i = 0; i < grid.segment_position.size(); ++i)
    EXPECT_LT((exact.segment_position[i] - grid.segment_position[i]).norm(), 1e-12);
  // Interpolation puts the CoM on the parabola (paper §5.3) at any time, up to the least-squares
  // fit of the root translation spline (millimetres).
  const double t = 0.7777;
  EXPECT_LT((d.sample_at(Stage::kBefore, t).com - ballistic_com(d.file().motion.takeoff, t)).norm(),
            0.01);
  // Out-of-range times are clamped to the flight.
  EXPECT_DOUBLE_EQ(d.sample_at(Stage::kBefore, 99.0).time, d.duration());
}

TEST(Document, RotationAtInterpolatesCountsAndIsExactOtherwise) {
  Document d;
  d.load(test::gui_test_motion_path(), "", 51);
  const auto& series = d.rotation(Stage::kBefore);
  const double t = 0.5 * (series[10].time + series[11].time);
  const RotationSample r = d.rotation_at(Stage::kBefore, t);
  EXPECT_NEAR(r.somersaults, 0.5 * (series[10].somersaults + series[11].somersaults), 1e-12);
  const RotationSample at_grid = d.rotation_at(Stage::kBefore, series[10].time);
  EXPECT_NEAR(at_grid.somersault_inertia, series[10].somersault_inertia, 1e-9);
  EXPECT_NEAR(at_grid.somersaults, series[10].somersaults, 1e-12);
  // M1 is a backward somersault: about one turn backwards by the end.
  EXPECT_LT(series.back().somersaults, -0.7);
  EXPECT_GT(series.back().somersaults, -1.3);
}

TEST(Document, GlyphScalesCoverTheTypicalMagnitudesOfTheStageShown) {
  Document d;
  d.load(test::gui_test_motion_path(), "", 51);
  std::vector<double> forces;
  for (const SampleRecord& s : d.evaluation(Stage::kBefore).samples)
    forces.push_back(s.residual.head<3>().norm());
  std::sort(forces.begin(), forces.end());
  const GlyphScale force(d.glyph_typicals(Stage::kBefore).residual_force, 1.0);
  // Full scale covers 90 % of the samples, and is at most one 1-2-5 step above them.
  EXPECT_GE(force.full_scale(), forces[45]);
  EXPECT_LE(force.full_scale(), 2.5 * forces[45]);
  EXPECT_GT(d.glyph_typicals(Stage::kBefore).residual_moment, 0.0);
  EXPECT_GT(d.glyph_typicals(Stage::kBefore).joint_force, 0.0);
}

TEST(Document, BeforeAndAfterOfARunShareTheLargerStagesArrowScale) {
  Document d;
  d.load(test::gui_test_motion_path(), "", 31);
  // Without a run: the interpolated motion's sizes.
  const GlyphTypicals alone = d.arrow_typicals();
  EXPECT_EQ(alone.residual_force, d.glyph_typicals(Stage::kBefore).residual_force);
  OptimizeOptions options;
  options.nlp.samples = 31;
  options.solver.max_iterations = 15;
  d.set_optimization(optimize_motion(d.file().motion, d.file().model, options), options);
  const GlyphTypicals before = d.glyph_typicals(Stage::kBefore);
  const GlyphTypicals after = d.glyph_typicals(Stage::kAfter);
  EXPECT_LT(after.residual_force, 0.5 * before.residual_force);
  // One scale for both stages, the larger's: what remains after optimisation is drawn short,
  // not blown up to full scale on a scale of its own.
  const GlyphTypicals shared = d.arrow_typicals();
  EXPECT_EQ(shared.residual_force, std::max(before.residual_force, after.residual_force));
  EXPECT_EQ(shared.residual_moment, std::max(before.residual_moment, after.residual_moment));
  EXPECT_EQ(shared.joint_force, std::max(before.joint_force, after.joint_force));
  EXPECT_EQ(shared.residual_force, before.residual_force);
}

TEST(Document, KeyframePosesAreAtTheKeyframeTimes) {
  Document d;
  d.load(test::gui_test_motion_path(), "", 51);
  const auto poses = d.keyframe_poses(Stage::kBefore);
  ASSERT_EQ(poses.size(), d.file().motion.keyframes.size());
  for (std::size_t i = 0; i < poses.size(); ++i)
    EXPECT_DOUBLE_EQ(poses[i].time, d.file().motion.keyframes[i].time);
}

TEST(Document, BadFileThrowsInputErrorAndKeepsTheOldMotion) {
  Document d;
  d.load(test::gui_test_motion_path(), "", 21);
  const fs::path bad = saltus::test::temp_path("saltus_gui_bad.motion.json");
  {
    std::ofstream out(bad);
    out << "{ \"format\": \"saltus-motion/1\", \"model\": \"zatsiorsky-66kg\", \"keyframes\": 3 }";
  }
  EXPECT_THROW(d.load(bad.string()), InputError);
  EXPECT_TRUE(d.loaded());
  EXPECT_EQ(d.frame_count(Stage::kBefore), 21);
  EXPECT_THROW(d.load("/nonexistent/x.motion.json"), InputError);
  fs::remove(bad);
}

TEST(Document, AnotherAthleteFliesTheMotionByTheClisTakeoffRule) {
  // The CLI's `--model` with its default --takeoff: the same whole-body spin at take-off.
  Document own;
  own.load(test::gui_test_motion_path(), "", 21);
  EXPECT_FALSE(own.file().takeoff_adaptation);
  BodyModel heavy = own.file().model;
  for (const char* thigh : {"thigh_l", "thigh_r"})
    heavy = scale_segment_mass(heavy, thigh, 1.5);
  const std::string model = saltus::test::temp_path("saltus_gui_heavy_thighs.json").string();
  std::ofstream(model) << body_model_to_json(heavy).dump(2) << '\n';
  Document d;
  d.load(test::gui_test_motion_path(), model, 21);
  const MotionFile cli =
      load_motion_for_athlete(test::gui_test_motion_path(), model, TakeoffRule::kSameSpin);
  ASSERT_TRUE(d.file().takeoff_adaptation);
  EXPECT_EQ(d.file().takeoff_adaptation->rule, "same spin");
  ASSERT_TRUE(d.file().motion.takeoff.angular_momentum);
  EXPECT_EQ(*d.file().motion.takeoff.angular_momentum, *cli.motion.takeoff.angular_momentum);
  // Heavier thighs: more inertia, so more angular momentum for the same spin.
  EXPECT_GT(d.file().motion.takeoff.angular_momentum->norm(),
            own.file().motion.takeoff.angular_momentum->norm() * 1.01);
}

TEST(Document, SavesAnEvaluationLikeTheCli) {
  Document d;
  d.load(test::gui_test_motion_path(), "", 21);
  const fs::path out = saltus::test::temp_path("saltus_gui_document_save");
  fs::remove_all(out);
  d.save_result(out.string());
  EXPECT_TRUE(fs::exists(out / "result.json"));
  EXPECT_TRUE(fs::exists(out / "trajectory.csv"));
  EXPECT_TRUE(fs::exists(out / "model.json"));
  fs::remove_all(out);
}

}  // namespace
}  // namespace saltus::gui
