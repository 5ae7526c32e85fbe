// The workspace: opening, edits that make runs stale, the run shown, what is unsaved, and
// snapshots that bring everything back (what undo relies on).

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "core/model_edit.h"
#include "core/motion_edit.h"
#include "core/workspace.h"
#include "gui_core/test_motion.h"

namespace saltus::gui {
namespace {

class WorkspaceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ws_.subscribe([this](WorkspaceChange c) { changes_.push_back(c); });
    ws_.open(test::gui_test_motion_path(), "", 21);
  }

  /// A finished run of the open motion whose "after" is the interpolation itself (exact and
  /// quick), with a chosen status and average root force.
  RunRecord run(const std::string& status, double after_force) const {
    auto result = std::make_shared<OptimizationResult>();
    result->solve.status = status;
    result->solve.solved = status == "solved";
    result->before = ws_.document().evaluation(Stage::kBefore);
    result->after = ws_.document().evaluation(Stage::kBefore);
    result->after.metrics.avg_root_force = after_force;
    RunRecord r;
    r.result = result;
    return r;
  }

  Workspace ws_;
  std::vector<WorkspaceChange> changes_;
};

TEST_F(WorkspaceTest, OpensCleanAndSaysSo) {
  ASSERT_TRUE(ws_.loaded());
  ASSERT_EQ(changes_.size(), 1u);
  EXPECT_EQ(changes_[0], WorkspaceChange::kOpened);
  EXPECT_FALSE(ws_.has_unsaved_work());
  EXPECT_EQ(ws_.unsaved_summary(), "");
  EXPECT_EQ(ws_.stage(), Stage::kBefore);
}

TEST_F(WorkspaceTest, ASolvedRunIsShownAndACancelledOneDoesNotReplaceIt) {
  const double before = ws_.document().evaluation(Stage::kBefore).metrics.avg_root_force;
  ws_.add_run(run("solved", 0.2 * before));
  EXPECT_EQ(ws_.shown_run(), 0);
  EXPECT_EQ(ws_.stage(), Stage::kAfter);
  EXPECT_TRUE(ws_.document().has_optimization());
  ws_.add_run(run("cancelled", 2.0 * before));
  EXPECT_EQ(ws_.shown_run(), 0);
  EXPECT_DOUBLE_EQ(ws_.document().optimization().after.metrics.avg_root_force, 0.2 * before);
  // The user may still look at it.
  ws_.show_run(1);
  EXPECT_EQ(ws_.shown_run(), 1);
  ws_.show_run(std::nullopt);
  EXPECT_FALSE(ws_.document().has_optimization());
  EXPECT_EQ(ws_.stage(), Stage::kBefore);
  EXPECT_EQ(ws_.unsaved_runs(), 2);
  EXPECT_EQ(ws_.unsaved_summary(), "2 optimisation runs were not saved");
}

TEST_F(WorkspaceTest, RunNumbersStartAtOneForEachMotionOpened) {
  const double before = ws_.document().evaluation(Stage::kBefore).metrics.avg_root_force;
  ws_.add_run(run("solved", 0.2 * before));
  ws_.add_run(run("solved", 0.3 * before));
  EXPECT_EQ(ws_.runs().at(1).number, 2);
  ws_.open(std::string(SALTUS_EXAMPLES_DIR) + "/motions/M2-tucked-back-somersault.motion.json", "",
           21);
  ws_.add_run(run("solved", 0.2 * before));
  EXPECT_EQ(ws_.runs().at(0).number, 1) << "numbers carried over from the other motion";
}

TEST_F(WorkspaceTest, AnEditDropsTheRunsAndASnapshotBringsThemBack) {
  const double before = ws_.document().evaluation(Stage::kBefore).metrics.avg_root_force;
  ws_.add_run(run("solved", 0.1 * before));
  const Workspace::Snapshot snapshot = ws_.snapshot();
  const int generation = ws_.generation();

  const MotionFile& f = ws_.document().file();
  const int knee = f.model.joint_index("knee_l");
  ws_.set_motion(with_joint_angles(f.motion, f.model, 1, knee, Eigen::Vector3d(40, 0, 0)));
  EXPECT_EQ(changes_.back(), WorkspaceChange::kEdited);
  EXPECT_TRUE(ws_.runs().empty());
  EXPECT_FALSE(ws_.shown_run());
  EXPECT_TRUE(ws_.motion_unsaved());
  EXPECT_NE(ws_.generation(), generation);
  EXPECT_NE(ws_.document().evaluation(Stage::kBefore).metrics.avg_root_force, before);
  EXPECT_EQ(ws_.unsaved_summary(), "the keyframes were edited");

  ws_.restore(snapshot);
  EXPECT_EQ(ws_.runs().size(), 1);
  EXPECT_EQ(ws_.shown_run(), 0);
  EXPECT_EQ(ws_.stage(), Stage::kAfter);
  EXPECT_FALSE(ws_.motion_unsaved());  // back to what is on disk
  EXPECT_DOUBLE_EQ(ws_.document().evaluation(Stage::kBefore).metrics.avg_root_force, before);
  EXPECT_NE(ws_.generation(), generation);  // a run started before belongs to no one now
}

TEST_F(WorkspaceTest, MassEditsAndSavingAreTracked) {
  const BodyModel& loaded = ws_.document().loaded_model();
  std::vector<double> factors(static_cast<std::size_t>(loaded.size()), 1.0);
  factors[static_cast<std::size_t>(loaded.segment_index("thigh_r"))] = 1.5;
  ws_.set_model(model_with_mass_factors(loaded, factors));
  EXPECT_TRUE(ws_.model_unsaved());
  EXPECT_FALSE(ws_.motion_unsaved());
  EXPECT_EQ(ws_.unsaved_summary(), "the masses were edited");
  ws_.mark_model_saved();
  EXPECT_FALSE(ws_.has_unsaved_work());
  EXPECT_EQ(changes_.back(), WorkspaceChange::kSaved);
}

TEST_F(WorkspaceTest, ARunWithoutAResultCannotBeShown) {
  RunRecord failed;
  failed.error = "the solver threw";
  ws_.add_run(failed);
  EXPECT_FALSE(ws_.shown_run());
  EXPECT_THROW(ws_.show_run(0), std::out_of_range);
  EXPECT_EQ(ws_.unsaved_runs(), 0);
}

}  // namespace
}  // namespace saltus::gui
