// The result list in the real window: every run is kept, best first; a solved run stays shown
// when a later run is cancelled or stops worse; the user can pick any run with a result; Save
// writes the run shown. A run's message says what it asked of the joints. (The case: a
// cancelled run at 90 N replaced a solved 13.1 N one.)

#include <gtest/gtest.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QStatusBar>
#include <QTest>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/file_controller.h"
#include "app/main_window.h"
#include "app/optimize_panel.h"
#include "app/run_controller.h"
#include "gui/support/open_motion_fixture.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/use_cases/athlete_verdict.h"
#include "support/cli_runner.h"

namespace saltus::gui {
namespace {

class ResultListTest : public test::OpenMotionTest {
 protected:
  /// Runs to the end (or cancels after `cancel_after_ms`) and returns the run's index.
  int run(int max_iterations, int cancel_after_ms = -1) {
    OptimizeSettings s;
    s.set("max_iterations", max_iterations);
    s.set("samples", 31);
    QString error;
    EXPECT_TRUE(window_->runs().start(s, &error)) << error.toStdString();
    if (cancel_after_ms >= 0) {
      QElapsedTimer clock;
      clock.start();
      while (clock.elapsed() < cancel_after_ms && window_->runs().running())
        QApplication::processEvents(QEventLoop::AllEvents, 10);
      window_->runs().cancel();
    }
    EXPECT_TRUE(window_->runs().wait(300000));
    return window_->workspace().runs().size() - 1;
  }
  const RunList& runs() { return window_->workspace().runs(); }
};

TEST_F(ResultListTest, ASolvedRunStaysShownWhateverComesAfter) {
  const int solved = run(300);
  ASSERT_TRUE(runs().showable(solved));
  ASSERT_TRUE(runs().at(solved).result->solve.solved) << runs().at(solved).result->solve.status;
  EXPECT_EQ(window_->workspace().shown_run(), solved);
  const double best = runs().at(solved).result->after.metrics.avg_root_force;
  // Beside the root force, what the run asked of the joints, in the library's words.
  const OptimizationResult& solved_result = *runs().at(solved).result;
  const std::string joints = joint_load_verdict_words(largest_joint_load_rise(
      window_->document().file().model, solved_result.before.check, solved_result.after.check));
  EXPECT_NE(
      window_->runs().panel()->message().indexOf(QString::fromStdString(" Joints: " + joints)), -1)
      << window_->runs().panel()->message().toStdString();
  // And the one verdict `saltus optimize` prints: can this athlete land it, the optimised motion
  // against the athlete's strength (use_cases/athlete_verdict.h).
  const AthleteVerdict verdict = athlete_verdict(
      window_->document().file(), window_->document().evaluate_options(), solved_result);
  EXPECT_NE(window_->runs().panel()->message().indexOf(
                QString::fromStdString(" Can this athlete land it? " + verdict.headline + ".")),
            -1)
      << window_->runs().panel()->message().toStdString();
  // The status bar, where a long line is cut, gives it in a few words.
  EXPECT_NE(window_->statusBar()->currentMessage().indexOf(
                QString::fromStdString(" " + verdict.summary + " (Optimise panel).")),
            -1)
      << window_->statusBar()->currentMessage().toStdString();

  // A run that stops after one iteration: worse, not solved, listed but not shown.
  const int early = run(1);
  ASSERT_EQ(runs().size(), 2);
  EXPECT_FALSE(runs().at(early).result->solve.solved);
  EXPECT_EQ(window_->workspace().shown_run(), solved);
  EXPECT_DOUBLE_EQ(window_->document().optimization().after.metrics.avg_root_force, best);
  EXPECT_NE(window_->runs().panel()->message().indexOf("stays shown"), -1)
      << window_->runs().panel()->message().toStdString();

  // A cancelled run never replaces it either.
  const int cancelled = run(300, 0);
  ASSERT_EQ(runs().size(), 3);
  EXPECT_EQ(window_->workspace().shown_run(), solved);

  // The list shows every run plus "interpolation only", best first, the shown one selected and
  // called best; the cancelled run called so.
  OptimizePanel* panel = window_->runs().panel();
  QListWidget* list = panel->run_list();
  ASSERT_EQ(list->count(), 4);
  EXPECT_EQ(panel->row_of_run(solved), 1);
  EXPECT_EQ(list->currentRow(), 1);
  EXPECT_TRUE(list->item(1)->text().startsWith("Best · Run 1 · solved"))
      << list->item(1)->text().toStdString();
  EXPECT_NE(list->item(panel->row_of_run(cancelled))->text().indexOf("cancelled"), -1);

  // The user picks the early run: it is shown, and Save writes that one.
  list->setCurrentRow(panel->row_of_run(early));
  QApplication::processEvents();
  EXPECT_EQ(window_->workspace().shown_run(), early);
  EXPECT_EQ(window_->stage(), Stage::kAfter);
  saltus::test::TempDir dir;
  QString error;
  ASSERT_TRUE(window_->files().save_result(QString::fromStdString(dir / "early"), &error))
      << error.toStdString();
  const nlohmann::json result = nlohmann::json::parse(std::ifstream(dir / "early/result.json"));
  EXPECT_EQ(result["iterations"].get<int>(), runs().at(early).result->solve.iterations);
  EXPECT_NE(result["status"].get<std::string>(), "solved");
  // Picking "interpolated keyframes only" shows no run.
  list->setCurrentRow(0);
  QApplication::processEvents();
  EXPECT_FALSE(window_->workspace().shown_run());
  EXPECT_EQ(window_->stage(), Stage::kBefore);
}

TEST_F(ResultListTest, TheProgressShowsIterationsNotAShareOfTheLimit) {
  OptimizeSettings s;
  s.set("max_iterations", 300);
  s.set("samples", 31);
  ASSERT_TRUE(window_->runs().start(s));
  auto* bar = window_->runs().panel()->findChild<QProgressBar*>();
  ASSERT_NE(bar, nullptr);
  // Busy while running: a run that solves at 33 of 300 never looks 11 % done.
  EXPECT_EQ(bar->maximum(), 0);
  // While it goes: the stage in the library's words, the iteration, the time left and what the
  // objective means.
  OptimizePanel* panel = window_->runs().panel();
  QElapsedTimer waited;
  waited.start();
  while (window_->runs().running() && panel->progress().reports() < 6 && waited.elapsed() < 60000)
    QApplication::processEvents(QEventLoop::AllEvents, 5);
  ASSERT_TRUE(panel->progress().started());
  const ProgressInfo first = panel->progress().last();
  EXPECT_EQ(first.stage.kind, SolveStage::Kind::kLevel);
  std::string stage = solve_stage_words(first.stage);
  stage[0] = static_cast<char>(std::toupper(stage[0]));
  EXPECT_NE(panel->message().indexOf(QString::fromStdString(stage)), -1)
      << panel->message().toStdString();
  EXPECT_NE(panel->message().indexOf("iteration "), -1) << panel->message().toStdString();
  auto* time_left = panel->findChild<QLabel*>("optimise_time_left");
  auto* objective = panel->findChild<QLabel*>("optimise_objective");
  ASSERT_NE(time_left, nullptr);
  ASSERT_NE(objective, nullptr);
  EXPECT_TRUE(time_left->text().contains("left") || time_left->text().contains("estimating"))
      << time_left->text().toStdString();
  EXPECT_EQ(objective->text().toStdString(), objective_meaning_words(first.stage));
  panel->grab().save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/optimise_panel_running.png");
  ASSERT_TRUE(window_->runs().wait(300000));
  EXPECT_EQ(bar->value(), bar->maximum());
}

}  // namespace
}  // namespace saltus::gui
