// A convergence study run from the app: the `saltus` program runs it in a process of its own,
// the progress dialog follows its cases, Stop keeps the finished cases, and running it again
// with Resume completes the same study folder the command line writes.

#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QLabel>
#include <QProgressDialog>
#include <QStatusBar>
#include <filesystem>

#include "app/edit_controller.h"
#include "app/main_window.h"
#include "app/study_controller.h"
#include "gui/support/image_checks.h"
#include "gui/support/open_motion_fixture.h"
#include "support/cli_runner.h"

namespace saltus::gui {
namespace {

namespace fs = std::filesystem;

/// A small design: 1 mass error × `timing` timing errors × (relaxed + strict at ε = 500).
QStringList design(const QStringList& timing) {
  return QStringList{"--epsilons", "500", "--mass-errors", "0", "--timing-errors"} + timing +
         QStringList{"--samples", "31", "--max-iter", "60", "--jobs", "2"};
}

class StudyTest : public test::OpenMotionTest {
 protected:
  StudyController& studies() {
    StudyController& s = window_->studies();
    s.set_program(SALTUS_CLI_PATH);
    return s;
  }
  /// Keeps the event loop running until the study has recorded `cases` cases.
  bool wait_for_cases(int cases, int timeout_ms) {
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < timeout_ms) {
      QApplication::processEvents(QEventLoop::AllEvents, 50);
      const auto& p = window_->studies().progress();
      if (p && p->done >= cases) return true;
      if (!window_->studies().running()) return false;
    }
    return false;
  }
};

TEST_F(StudyTest, RunsAConvergenceStudyWithReadableProgress) {
  saltus::test::TempDir dir;
  const std::string out = dir / "study";
  QString error;
  ASSERT_TRUE(studies().start(QString::fromStdString(out), design({"0", "0.05"}), false, &error))
      << error.toStdString();
  ASSERT_TRUE(wait_for_cases(1, 120000)) << studies().outcome().toStdString();
  // The dialog says what a person wants to know: how far, what failed, how long still.
  QProgressDialog* dialog = studies().dialog();
  ASSERT_NE(dialog, nullptr);
  EXPECT_TRUE(dialog->isVisible());
  EXPECT_EQ(dialog->maximum(), 4);
  const QString label = dialog->findChild<QLabel*>()->text();
  EXPECT_TRUE(label.contains("of 4 cases")) << label.toStdString();
  EXPECT_TRUE(label.contains("failed")) << label.toStdString();
  EXPECT_TRUE(label.contains("left")) << label.toStdString();
  QDir().mkpath(SALTUS_GUI_CANDIDATE_DIR);
  const QImage picture = dialog->grab().toImage();
  EXPECT_GT(test::blank_check(picture).distinct_colours, 8);
  picture.save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/study_progress.png");

  ASSERT_TRUE(studies().wait(300000));
  ASSERT_TRUE(studies().progress().has_value());
  EXPECT_EQ(studies().progress()->done, 4);
  EXPECT_EQ(studies().progress()->total, 4);
  EXPECT_FALSE(dialog->isVisible());
  EXPECT_TRUE(fs::exists(out + "/convergence.csv"));
  EXPECT_TRUE(fs::exists(out + "/convergence.md"));
  EXPECT_FALSE(fs::exists(out + ".partial"));
  EXPECT_TRUE(studies().outcome().contains("4 of 4 cases")) << studies().outcome().toStdString();
  EXPECT_TRUE(window_->statusBar()->currentMessage().contains("convergence.md"));
}

TEST_F(StudyTest, StopKeepsTheFinishedCasesAndResumeCompletesTheStudy) {
  saltus::test::TempDir dir;
  const std::string out = dir / "study";
  const QStringList six = design({"0", "0.05", "0.1"});
  QString error;
  ASSERT_TRUE(studies().start(QString::fromStdString(out), six, false, &error))
      << error.toStdString();
  ASSERT_TRUE(wait_for_cases(1, 120000)) << studies().outcome().toStdString();
  studies().cancel();
  ASSERT_TRUE(studies().wait(60000));
  const int kept = studies().progress()->done;
  EXPECT_TRUE(studies().outcome().contains("Resume")) << studies().outcome().toStdString();
  EXPECT_FALSE(fs::exists(out));
  ASSERT_TRUE(fs::exists(out + ".partial/cases"));

  ASSERT_TRUE(studies().start(QString::fromStdString(out), six, true, &error))
      << error.toStdString();
  ASSERT_TRUE(studies().wait(300000));
  ASSERT_TRUE(studies().progress().has_value());
  EXPECT_EQ(studies().progress()->total, 6);
  EXPECT_EQ(studies().progress()->done, 6);
  EXPECT_GE(kept, 1);
  EXPECT_TRUE(fs::exists(out + "/convergence.csv"));
  EXPECT_FALSE(fs::exists(out + ".partial"));
}

TEST_F(StudyTest, AnEditedMotionMustBeSavedFirst) {
  QString error;
  const int hip = window_->document().file().model.joint_index("hip_r");
  ASSERT_TRUE(window_->edits().set_keyframe_angles(1, hip, -30.0, 5.0, 0.0, &error));
  saltus::test::TempDir dir;
  EXPECT_FALSE(studies().start(QString::fromStdString(dir / "study"), {}, false, &error));
  EXPECT_TRUE(error.contains("save")) << error.toStdString();
  EXPECT_FALSE(studies().running());
}

}  // namespace
}  // namespace saltus::gui
