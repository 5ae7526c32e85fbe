// The main window on a laptop screen (1366×768, and usable at 1024×700) and a large one
// (1920×1080), with a motion
// capture open (the most crowded case: six panels, capture curves, keyframes given and
// optimised): the Optimise panel's run list and status in view, the 3D view most of the width,
// every tab's title whole, no chart cut off, the legends in a row above the charts, and log
// axes labelled a decade at a time. Pictures are left in the candidate folder to look at.

#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QStatusBar>
#include <QTabBar>
#include <QTest>
#include <memory>

#include "app/chart_widget.h"
#include "app/legend_strip.h"
#include "app/main_window.h"
#include "app/optimize_panel.h"
#include "app/plots_panel.h"
#include "app/run_controller.h"
#include "app/scene_widget.h"

namespace saltus::gui {
namespace {

QString capture_path() {
  return QString(SALTUS_EXAMPLES_DIR) + "/captures/deepmimic-backflip.bvh";
}

std::unique_ptr<MainWindow> window_at(int width, int height) {
  auto window = std::make_unique<MainWindow>(false);
  window->resize(width, height);
  window->show();
  EXPECT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  QString error;
  EXPECT_TRUE(window->open_motion(capture_path(), &error)) << error.toStdString();
  window->seek(0.3);
  QApplication::processEvents();
  return window;
}

/// The widget's rectangle in the window's coordinates.
QRect in_window(const QWidget* widget, const QWidget* window) {
  return QRect(widget->mapTo(window, QPoint(0, 0)), widget->size());
}

/// Shown whole: visible, inside the window, and not cut by the panels or scroll areas around it.
void expect_whole(const QWidget* widget, const QWidget* window, const char* what) {
  ASSERT_NE(widget, nullptr) << what;
  EXPECT_TRUE(widget->isVisible()) << what << " is hidden";
  EXPECT_TRUE(window->rect().contains(in_window(widget, window)))
      << what << " lies outside the window";
  EXPECT_EQ(widget->visibleRegion().boundingRect(), widget->rect()) << what << " is cut off";
}

/// QTabBar's own measure of the room a tab's title and margins need (protected in Qt).
struct MeasuredTabBar : QTabBar {
  using QTabBar::tabSizeHint;
};

/// Every tab of every tab bar gets the room its title asks for (less, and Qt elides the title:
/// "Optim… Keyfra…"), along the bar (a tab bar on the window's edge runs down, titles turned).
void expect_tab_titles_whole(const QWidget* window) {
  int bars = 0;
  for (const QTabBar* bar : window->findChildren<QTabBar*>()) {
    if (!bar->isVisible()) continue;
    ++bars;
    for (int i = 0; i < bar->count(); ++i) {
      const QRect got = bar->tabRect(i);
      const QSize need = static_cast<const MeasuredTabBar*>(bar)->tabSizeHint(i);
      const bool down =
          bar->shape() == QTabBar::RoundedEast || bar->shape() == QTabBar::RoundedWest;
      EXPECT_GE(down ? got.height() : got.width(), down ? need.height() : need.width())
          << "tab \"" << bar->tabText(i).toStdString() << "\" is elided";
      EXPECT_TRUE(bar->rect().contains(got))
          << "tab \"" << bar->tabText(i).toStdString() << "\" runs out of its bar";
    }
  }
  EXPECT_GE(bars, 2) << "the panels' tabs and the plots' tabs";
}

void save_candidate(MainWindow& window, const QString& name) {
  const QString dir = SALTUS_GUI_CANDIDATE_DIR;
  QDir().mkpath(dir);
  window.grab_window().save(dir + "/" + name);
}

/// `view_share`: the least share of the width the 3D view keeps (the panels' column keeps its
/// width on a narrow screen).
void check_layout(MainWindow& window, double view_share = 0.7) {
  // The Optimise panel in front: Run, its status and the list of runs are in view.
  window.findChild<QDockWidget*>("optimise_dock")->raise();
  QApplication::processEvents();
  OptimizePanel* panel = window.runs().panel();
  expect_whole(panel->run_list(), &window, "the run list");
  expect_whole(panel->findChild<QLabel*>("optimise_status"), &window, "the optimisation status");
  expect_whole(window.statusBar(), &window, "the status bar");
  expect_tab_titles_whole(&window);
  // Nothing asks for more height than the screen has (else Qt cuts the window's bottom off).
  EXPECT_LE(window.minimumSizeHint().height(), window.height());
  EXPECT_LE(window.minimumSizeHint().width(), window.width());

  // The 3D view keeps most of the width; the panels a quarter at most.
  const QRect view = in_window(window.view_widget(), &window);
  EXPECT_GE(view.width(), view_share * window.width()) << view.width() << " of " << window.width();
  EXPECT_GE(view.height(), 0.4 * window.height()) << view.height() << " of " << window.height();

  // No chart cut off, each tall enough to read, its legend above it rather than over it.
  for (ChartWidget* chart : window.plots().charts()) {
    if (!chart->isVisible()) continue;
    expect_whole(chart, &window, "a chart");
    EXPECT_GE(chart->height(), 140);
    const auto* strip = chart->parentWidget()->findChild<LegendStrip*>("legend_strip");
    ASSERT_NE(strip, nullptr);
    EXPECT_TRUE(strip->isVisible());
    EXPECT_LE(in_window(strip, &window).bottom(), in_window(chart, &window).top());
  }
}

TEST(LaptopLayout, FitsA1366x768Screen) {
  auto window = window_at(1366, 768);
  ASSERT_EQ(window->size(), QSize(1366, 768)) << "the window does not fit 1366×768";
  save_candidate(*window, "laptop_1366x768.png");
  check_layout(*window);
}

TEST(LaptopLayout, FitsA1280x720Screen) {
  auto window = window_at(1280, 720);
  ASSERT_EQ(window->size(), QSize(1280, 720)) << "the window does not fit 1280×720";
  check_layout(*window);
}

TEST(LaptopLayout, UsableAt1024x700) {
  auto window = window_at(1024, 700);
  ASSERT_EQ(window->size(), QSize(1024, 700)) << "the window does not fit 1024×700";
  save_candidate(*window, "laptop_1024x700.png");
  check_layout(*window, 0.6);
}

TEST(LaptopLayout, StillRightAt1920x1080) {
  auto window = window_at(1920, 1080);
  save_candidate(*window, "laptop_1920x1080.png");
  check_layout(*window);
  // A big screen gives the room to the 3D view and the plots, not to the panels.
  const QRect dock = in_window(window->findChild<QDockWidget*>("optimise_dock"), window.get());
  EXPECT_LE(dock.width(), 0.25 * window->width());
}

TEST(LaptopLayout, ChartLegendsAreAboveThePlotsNotInside) {
  auto window = window_at(1366, 768);
  ChartWidget* force = window->plots().charts().front();
  const auto* strip = force->parentWidget()->findChild<LegendStrip*>("legend_strip");
  ASSERT_NE(strip, nullptr);
  // The capture's curve, the keyframes' and both kinds of keyframe lines are named.
  const QStringList labels = strip->labels();
  EXPECT_TRUE(labels.contains("|F| capture")) << labels.join(", ").toStdString();
  EXPECT_TRUE(labels.contains("keyframes (given)")) << labels.join(", ").toStdString();
  // The chart itself draws no legend box over its curves; its figure keeps one.
  EXPECT_TRUE(force->view().chart().legend);
  EXPECT_FALSE(force->view().legend_drawn());
}

}  // namespace
}  // namespace saltus::gui
