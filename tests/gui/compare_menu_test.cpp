// The Compare menu's entries, each triggered from the menu bar, its file dialog answered by the
// test: the compare window opens with the open motion and the second one chosen (another
// motion, another body model, a saved result folder, the optimised run), Close compare closes
// it, and With a new athlete… opens the athlete dialog.

#include <gtest/gtest.h>

#include <QApplication>
#include <QTest>
#include <filesystem>

#include "app/athlete_controller.h"
#include "app/compare_controller.h"
#include "app/compare_window.h"
#include "app/file_controller.h"
#include "app/main_window.h"
#include "app/new_athlete_dialog.h"
#include "app/run_controller.h"
#include "core/document.h"
#include "gui/support/menu_actions.h"
#include "gui/support/open_motion_fixture.h"
#include "saltus/body/body_model.h"
#include "saltus/formats/model_file.h"
#include "support/temp_path.h"

namespace saltus::gui {
namespace {

class CompareMenuTest : public test::OpenMotionTest {
 protected:
  QAction* entry(const QString& text) {
    QAction* a = test::menu_action(window_.get(), {"Compare", text});
    EXPECT_NE(a, nullptr) << text.toStdString();
    if (a) {
      EXPECT_TRUE(a->isEnabled()) << text.toStdString();
    }
    return a;
  }
  QString answer(const QString& text, const std::filesystem::path& path) {
    QAction* a = entry(text);
    if (!a) return {};
    const QString title =
        test::trigger_and_answer_file_dialog(a, QString::fromStdString(path.string()));
    QApplication::processEvents();
    return title;
  }
  /// Compare > Close compare; the window is gone.
  void close_compare() {
    entry("Close compare")->trigger();
    QApplication::processEvents();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    EXPECT_EQ(window_->compare().window(), nullptr);
  }
};

TEST_F(CompareMenuTest, AnotherMotionOpensTheCompareWindowAndCloseClosesIt) {
  EXPECT_EQ(window_->compare().window(), nullptr);
  const std::filesystem::path other = std::filesystem::path(SALTUS_EXAMPLES_DIR) / "motions" /
                                      "M2-tucked-back-somersault.motion.json";
  EXPECT_EQ(answer("With another motion…", other), "Compare with motion");
  CompareWindow* compare = window_->compare().window();
  ASSERT_NE(compare, nullptr);
  EXPECT_TRUE(compare->isVisible());
  close_compare();
}

TEST_F(CompareMenuTest, AnotherBodyModelOpensTheCompareWindow) {
  BodyModel heavy = scale_segment_mass(window_->document().file().model, "thigh_l", 1.5);
  heavy.name = "heavy thigh";
  const std::filesystem::path path = saltus::test::temp_path("compare-heavy.json");
  save_body_model_file(path.string(), heavy);
  EXPECT_EQ(answer("With another body model…", path), "Compare with body model");
  ASSERT_TRUE(window_->compare().wait(300000));
  ASSERT_NE(window_->compare().window(), nullptr);
  EXPECT_EQ(window_->compare().window()->run(1).document->file().model.name, "heavy thigh");
}

TEST_F(CompareMenuTest, ASavedResultFolderOpensTheCompareWindow) {
  const std::filesystem::path dir = saltus::test::temp_path("compare-saved");
  QString error;
  ASSERT_TRUE(window_->files().save_result(QString::fromStdString(dir.string()), &error))
      << error.toStdString();
  EXPECT_EQ(answer("With a saved result folder…", dir),
            "Compare with a `saltus optimize` result folder");
  ASSERT_NE(window_->compare().window(), nullptr);
  EXPECT_NE(window_->compare().window()->run(1).label.indexOf("compare-saved"), -1)
      << window_->compare().window()->run(1).label.toStdString();
}

TEST_F(CompareMenuTest, BeforeVsAfterComparesTheOptimisedRun) {
  OptimizeSettings s;
  s.set("max_iterations", 3);
  s.set("samples", 31);
  ASSERT_TRUE(window_->runs().start(s));
  ASSERT_TRUE(window_->runs().wait(300000));
  ASSERT_TRUE(window_->runs().show_run(0));
  entry("Before vs after optimisation")->trigger();
  QApplication::processEvents();
  ASSERT_NE(window_->compare().window(), nullptr);
  EXPECT_TRUE(window_->compare().window()->isVisible());
  close_compare();
}

TEST_F(CompareMenuTest, WithANewAthleteOpensTheAthleteDialog) {
  EXPECT_EQ(window_->athletes().dialog(), nullptr);
  entry("With a new athlete…")->trigger();
  QApplication::processEvents();
  NewAthleteDialog* dialog = window_->athletes().dialog();
  ASSERT_NE(dialog, nullptr);
  EXPECT_TRUE(dialog->isVisible());
  dialog->close();
}

}  // namespace
}  // namespace saltus::gui
