// The Optimise menu's Run and Cancel entries and the Optimise panel's buttons of the same names,
// pressed as a user presses them: a run starts with the panel's settings and ends in the run
// list, a cancelled run stops before its iteration limit, and View > Show optimised motion
// (after), enabled by the run, shows it.

#include <gtest/gtest.h>

#include <QApplication>
#include <QPushButton>
#include <QTest>

#include "app/main_window.h"
#include "app/optimize_panel.h"
#include "app/run_controller.h"
#include "gui/support/menu_actions.h"
#include "gui/support/open_motion_fixture.h"

namespace saltus::gui {
namespace {

class OptimiseMenuTest : public test::OpenMotionTest {
 protected:
  void SetUp() override {
    test::OpenMotionTest::SetUp();
    if (HasFatalFailure()) return;
    set_iterations(3);
  }
  void set_iterations(int iterations) {
    OptimizeSettings s = window_->runs().settings();
    s.set("max_iterations", iterations);
    // A long run (fine samples), cancelled as soon as it starts: on an idle machine M1 solves
    // in well under a second, and a cancel after a wait could come after it ended.
    s.set("samples", iterations > 100 ? 301 : 31);
    window_->runs().panel()->set_settings(s);
  }
  QAction* entry(const QStringList& path) {
    QAction* a = test::menu_action(window_.get(), path);
    EXPECT_NE(a, nullptr) << path.join(" > ").toStdString();
    return a;
  }
  QPushButton* button(const QString& text) {
    for (QPushButton* b : window_->runs().panel()->findChildren<QPushButton*>())
      if (b->text() == text) return b;
    ADD_FAILURE() << "no button " << text.toStdString();
    return nullptr;
  }
  const SolveReport& last_solve() const {
    const RunList& runs = window_->workspace().runs();
    return runs.at(runs.size() - 1).result->solve;
  }
  int last_iterations() const { return last_solve().iterations; }
};

TEST_F(OptimiseMenuTest, RunEntryOptimisesAndAfterEntryShowsTheResult) {
  QAction* after = entry({"View", "Show optimised motion (after)"});
  ASSERT_NE(after, nullptr);
  EXPECT_FALSE(after->isEnabled());
  QAction* run = entry({"Optimise", "Run optimisation"});
  ASSERT_NE(run, nullptr);
  ASSERT_TRUE(run->isEnabled());
  run->trigger();
  EXPECT_TRUE(window_->runs().running());
  ASSERT_TRUE(window_->runs().wait(300000));
  ASSERT_EQ(window_->workspace().runs().size(), 1);
  EXPECT_LE(last_iterations(), 3);

  ASSERT_TRUE(after->isEnabled());
  window_->set_stage(Stage::kBefore);
  after->trigger();
  QApplication::processEvents();
  EXPECT_EQ(window_->stage(), Stage::kAfter);
  EXPECT_TRUE(after->isChecked());
}

TEST_F(OptimiseMenuTest, CancelEntryStopsTheRun) {
  set_iterations(500);
  entry({"Optimise", "Run optimisation"})->trigger();
  ASSERT_TRUE(window_->runs().running());
  QAction* cancel = entry({"Optimise", "Cancel optimisation"});
  ASSERT_TRUE(cancel->isEnabled());
  cancel->trigger();
  ASSERT_TRUE(window_->runs().wait(60000));
  ASSERT_EQ(window_->workspace().runs().size(), 1);
  EXPECT_LT(last_iterations(), 500);
  EXPECT_EQ(last_solve().status, "cancelled");
}

TEST_F(OptimiseMenuTest, PanelButtonsRunAndCancel) {
  QPushButton* run = button("Run optimisation");
  ASSERT_NE(run, nullptr);
  QTest::mouseClick(run, Qt::LeftButton);
  EXPECT_TRUE(window_->runs().running());
  ASSERT_TRUE(window_->runs().wait(300000));
  ASSERT_EQ(window_->workspace().runs().size(), 1);

  set_iterations(500);
  QTest::mouseClick(run, Qt::LeftButton);
  ASSERT_TRUE(window_->runs().running());
  QPushButton* cancel = button("Cancel");
  ASSERT_NE(cancel, nullptr);
  ASSERT_TRUE(cancel->isEnabled());
  QTest::mouseClick(cancel, Qt::LeftButton);
  ASSERT_TRUE(window_->runs().wait(60000));
  ASSERT_EQ(window_->workspace().runs().size(), 2);
  EXPECT_LT(last_iterations(), 500);
  EXPECT_EQ(last_solve().status, "cancelled");
}

}  // namespace
}  // namespace saltus::gui
