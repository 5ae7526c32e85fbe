// The teaching panel's "Is it a real flight?": each check is marked as the library judges it
// (judge_flight's tolerances), and the closing sentence says what holds for the motion shown,
// never that it passes while a check fails: the interpolated keyframes of M2 fail, the optimised
// motion's centre of mass stays within 1 mm of its parabola and the panel says all three hold. A
// picture of the panel is left in the candidate folder to look at.

#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QTest>
#include <memory>

#include "app/main_window.h"
#include "app/plots_panel.h"
#include "app/run_controller.h"
#include "app/teaching_panel.h"
#include "gui/support/open_motion_fixture.h"
#include "saltus/evaluation/flight_checks.h"

namespace saltus::gui {
namespace {

QString motion(const std::string& name) {
  return QString(SALTUS_EXAMPLES_DIR) + "/motions/" + QString::fromStdString(name);
}

class TeachingPanelTest : public test::EmptyWindowTest {
 protected:
  QString text() const { return window_->plots().teaching()->text(); }
  /// The panel's marks and sentence agree with the library's verdict on the stage shown.
  void expect_marks(Stage stage) {
    const FlightCheckVerdict verdict = judge_flight(window_->document().flight_checks(stage));
    const QString shown = text();
    EXPECT_EQ(shown.count(QStringLiteral("✗")), verdict.failed()) << shown.toStdString();
    EXPECT_EQ(shown.count(QStringLiteral("✓")), 3 - verdict.failed()) << shown.toStdString();
    EXPECT_EQ(shown.contains("All three hold"), verdict.failed() == 0) << shown.toStdString();
  }
};

TEST_F(TeachingPanelTest, TheChecksSayWhatHoldsForTheMotionShown) {
  QString error;
  ASSERT_TRUE(window_->open_motion(motion("M2-tucked-back-somersault.motion.json"), &error))
      << error.toStdString();
  QApplication::processEvents();
  const FlightChecks& before = window_->document().flight_checks(Stage::kBefore);
  // The interpolated keyframes are 2 cm off their parabola: not a free flight.
  EXPECT_GT(before.max_com_off_parabola_m, kFreeFlightComToleranceM);
  expect_marks(Stage::kBefore);
  EXPECT_TRUE(text().contains("no free flight moves like this")) << text().toStdString();
  EXPECT_FALSE(text().contains("makes a motion pass")) << "no promise beside a failing check";

  OptimizeSettings settings;
  ASSERT_TRUE(window_->runs().start(settings, &error)) << error.toStdString();
  ASSERT_TRUE(window_->runs().wait(300000));
  QApplication::processEvents();
  if (window_->stage() != Stage::kAfter) {
    ASSERT_TRUE(window_->runs().show_run(window_->workspace().runs().size() - 1, &error))
        << error.toStdString();
  }
  ASSERT_EQ(window_->stage(), Stage::kAfter);
  const FlightChecks& after = window_->document().flight_checks(Stage::kAfter);
  EXPECT_LT(after.max_com_off_parabola_m, 0.001) << "the optimised CoM is on its parabola";
  expect_marks(Stage::kAfter);
  // M2's optimised motion (measured: CoM 0.04 mm, L 0.2 %, flight time to 0.1 ms) passes all.
  EXPECT_TRUE(text().contains("All three hold")) << text().toStdString();
  window_->plots().setCurrentWidget(window_->plots().teaching());
  QApplication::processEvents();
  const QString dir = SALTUS_GUI_CANDIDATE_DIR;  // pictures to look at
  QDir().mkpath(dir);
  EXPECT_TRUE(window_->grab_window().save(dir + "/teaching_panel_M2_after.png"));
}

}  // namespace
}  // namespace saltus::gui
