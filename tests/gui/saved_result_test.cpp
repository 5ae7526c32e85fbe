// A saved optimised result opened in the app (optimized.motion.json, written by `saltus
// optimize` with its stored spline): the view's title and the status line call it the
// optimised trajectory it is, not "interpolated keyframes (before optimisation)"; the motion
// it came from keeps that label.

#include <gtest/gtest.h>

#include <QApplication>
#include <QLabel>
#include <QStatusBar>
#include <QTest>
#include <filesystem>
#include <memory>

#include "app/main_window.h"
#include "app/scene_widget.h"
#include "gui_core/test_motion.h"
#include "scene/body_scene.h"
#include "support/cli_runner.h"

namespace saltus::gui {
namespace {

/// The status bar's permanent line (the motion, its model, its residual).
QString status_line(MainWindow& window) {
  for (const QLabel* label : window.statusBar()->findChildren<QLabel*>())
    if (label->text().contains("average root force")) return label->text();
  return {};
}

std::string opened_title(MainWindow& window, const std::string& path) {
  QString error;
  EXPECT_TRUE(window.open_motion(QString::fromStdString(path), &error)) << error.toStdString();
  window.seek(0.5);
  QApplication::processEvents();
  return window.view_widget()->scene().title();
}

TEST(SavedResult, IsLabelledAsTheOptimisedTrajectory) {
  saltus::test::TempDir dir;
  const saltus::test::CliRun cli =
      saltus::test::run_cli("optimize '" + test::gui_test_motion_path() +
                            "' --max-iter 5 --samples 31 --quiet --out '" + (dir / "opt") + "'");
  ASSERT_TRUE(cli.status == 0 || cli.status == 3) << cli.output;
  const std::string saved = (dir.path() / "opt" / "optimized.motion.json").string();
  ASSERT_TRUE(std::filesystem::exists(saved));

  MainWindow window(false);
  window.resize(1280, 800);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));

  const std::string title = opened_title(window, saved);
  EXPECT_NE(title.find("optimised trajectory, as saved"), std::string::npos) << title;
  EXPECT_EQ(title.find("before optimisation"), std::string::npos) << title;
  const QString status = status_line(window);
  EXPECT_TRUE(status.contains("optimised trajectory as saved")) << status.toStdString();
  EXPECT_FALSE(status.contains("before optimisation")) << status.toStdString();

  // The keyframed motion it came from is what "before optimisation" means.
  const std::string keyframed = opened_title(window, test::gui_test_motion_path());
  EXPECT_NE(keyframed.find("interpolated keyframes (before optimisation)"), std::string::npos)
      << keyframed;
  EXPECT_TRUE(status_line(window).contains("before optimisation"));
}

}  // namespace
}  // namespace saltus::gui
