// Baseline pictures (F3D style: a committed picture per case and a tolerance; a missing or
// different one leaves the candidate and a difference picture in the build tree): the main
// window at the sizes users have (1280×720; 1024×700, 1366×768 and 1920×1080 with each panel
// tab raised in turn), the compare window, and the exported figures of the app and of
// `saltus-gui --export-figures`. The interpolated motion is shown (the optimiser is improved in
// parallel; the interpolation changes only with the motion).

#include <gtest/gtest.h>

#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QTest>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/compare_controller.h"
#include "app/compare_window.h"
#include "app/main_window.h"
#include "app/plots_panel.h"
#include "app/twist_panel.h"
#include "app/what_if_panel.h"
#include "gui/support/image_checks.h"
#include "gui_core/test_motion.h"
#include "saltus/formats/model_file.h"
#include "support/cli_runner.h"

namespace saltus::gui {
namespace {

/// Charts and windows hold text and thin lines: a little more room than the 3D view alone.
constexpr double kWindowTolerance = 0.04;

QString name(const char* what) {
  return QString::fromStdString(test::gui_test_motion_stem()) + "_" + what;
}

std::unique_ptr<MainWindow> window_at(int width, int height) {
  auto window = std::make_unique<MainWindow>(false);
  window->resize(width, height);
  window->show();
  EXPECT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  QString error;
  EXPECT_TRUE(window->open_motion(QString::fromStdString(test::gui_test_motion_path()), &error))
      << error.toStdString();
  window->seek(0.8);
  QApplication::processEvents();
  return window;
}

TEST(Baseline, MainWindowAt1280x720) {
  auto window = window_at(1280, 720);
  const QImage picture = window->grab_window();
  ASSERT_EQ(picture.size(), QSize(1280, 720)) << "the window does not fit 1280×720";
  const test::Comparison c =
      test::compare_with_baseline(picture, name("window_1280x720"), kWindowTolerance);
  EXPECT_TRUE(c.ok) << c.message;
}

/// The tabs of the panel column (MainWindow::build_docks), by dock and picture name. The Study
/// panel is left out: it is hidden until a study runs, and study_test looks at it then.
struct PanelTab {
  const char* dock;
  const char* picture;
};
constexpr PanelTab kPanelTabs[] = {{"optimise_dock", "optimise"}, {"keyframe_dock", "keyframes"},
                                   {"capture_dock", "capture"},   {"model_dock", "model"},
                                   {"display_dock", "display"},   {"history_dock", "history"},
                                   {"twist_dock", "twist"},       {"what_if_dock", "what_if"}};

/// The window at `width`×`height` with each panel tab raised in turn, each against its baseline
/// ("window_1366x768_model").
void expect_panels_like_baselines(int width, int height) {
  auto window = window_at(width, height);
  const QString size = QString("%1x%2").arg(width).arg(height);
  for (const PanelTab& tab : kPanelTabs) {
    SCOPED_TRACE(tab.picture);
    auto* dock = window->findChild<QDockWidget*>(tab.dock);
    ASSERT_NE(dock, nullptr);
    dock->raise();
    QApplication::processEvents();
    // The Twist and What if panels work out their result once raised (busy says so only then).
    const auto busy = [&window, &tab] {
      const QString raised = tab.dock;
      return (raised == "twist_dock" && window->twist().busy()) ||
             (raised == "what_if_dock" && window->what_if().busy());
    };
    QElapsedTimer waited;
    waited.start();
    while (busy() && waited.elapsed() < 60000)
      QApplication::processEvents(QEventLoop::AllEvents, 20);
    ASSERT_FALSE(busy());
    QApplication::processEvents();
    const QImage picture = window->grab_window();
    ASSERT_EQ(picture.size(), QSize(width, height))
        << "the window does not fit " << width << "x" << height << " with this panel";
    const test::Comparison c = test::compare_with_baseline(
        picture, name("window_") + size + "_" + tab.picture, kWindowTolerance);
    EXPECT_TRUE(c.ok) << c.message;
  }
}

TEST(Baseline, MainWindowPanelsAt1366x768) {
  expect_panels_like_baselines(1366, 768);
}

TEST(Baseline, MainWindowPanelsAt1024x700) {
  expect_panels_like_baselines(1024, 700);
}

TEST(Baseline, MainWindowPanelsAt1920x1080) {
  expect_panels_like_baselines(1920, 1080);
}

TEST(Baseline, CompareWindowWithHeavierThighs) {
  auto window = window_at(1280, 800);
  saltus::test::TempDir dir;
  BodyModel heavy = window->document().file().model;
  for (const char* thigh : {"thigh_l", "thigh_r"})
    heavy = scale_segment_mass(heavy, thigh, 1.5);
  heavy.name = "thighs x1.5";
  const std::string path = dir / "heavy.json";
  std::ofstream(path) << body_model_to_json(heavy).dump(2) << '\n';
  QString error;
  ASSERT_TRUE(window->compare().compare_with_model(QString::fromStdString(path), &error))
      << error.toStdString();
  CompareWindow* compare = window->compare().window();
  ASSERT_NE(compare, nullptr);
  compare->resize(1400, 900);
  ASSERT_TRUE(QTest::qWaitForWindowExposed(compare));
  compare->seek(0.8);
  QApplication::processEvents();
  const test::Comparison c =
      test::compare_with_baseline(compare->grab_window(), name("compare_window"), kWindowTolerance);
  EXPECT_TRUE(c.ok) << c.message;
}

TEST(Baseline, FiguresExportedFromTheApp) {
  auto window = window_at(1280, 800);
  saltus::test::TempDir dir;
  QStringList written;
  QString error;
  ASSERT_TRUE(
      window->plots().export_figures(QString::fromStdString(dir / "figures"), &written, &error))
      << error.toStdString();
  ASSERT_EQ(written.size(), 5);
  for (const QString& file : written) {
    const QImage figure(QString::fromStdString(dir / "figures") + "/" + file);
    ASSERT_FALSE(figure.isNull()) << file.toStdString();
    const test::Comparison c = test::compare_with_baseline(
        figure, "app_figure_" + QString(file).remove(".png"), kWindowTolerance);
    EXPECT_TRUE(c.ok) << c.message;
  }
}

TEST(Baseline, FiguresExportedFromAResultFolder) {
  saltus::test::TempDir dir;
  // A short, fixed run: the same iterations give the same curves.
  const saltus::test::CliRun cli =
      saltus::test::run_cli("optimize '" + test::gui_test_motion_path() +
                            "' --max-iter 5 --samples 31 --quiet --out '" + (dir / "M1-opt") + "'");
  ASSERT_TRUE(cli.status == 0 || cli.status == 3) << cli.output;
  const saltus::test::CliRun run =
      saltus::test::run_command(std::string(SALTUS_GUI_PATH) + " --export-figures '" +
                                (dir / "figures") + "' '" + (dir / "M1-opt") + "'");
  ASSERT_EQ(run.status, 0) << run.output;
  for (const char* file :
       {"M1-opt_root_force", "M1-opt_root_moment", "M1-opt_keyframe_times", "average_root_force"}) {
    const QImage figure(QString::fromStdString((dir.path() / "figures").string()) + "/" + file +
                        ".png");
    ASSERT_FALSE(figure.isNull()) << file;
    const test::Comparison c =
        test::compare_with_baseline(figure, QString("folder_figure_") + file, 0.05);
    EXPECT_TRUE(c.ok) << c.message;
  }
}

}  // namespace
}  // namespace saltus::gui
