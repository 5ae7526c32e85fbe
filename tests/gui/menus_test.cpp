// The View, Playback and Help menus' entries, each triggered from the menu bar as a user picks
// it, and its effect read back: the camera and display options the 3D view holds, the panels
// shown, the time, speed and loop of the timeline, the dialogs the Help entries open.

#include <gtest/gtest.h>

#include <QApplication>
#include <QDockWidget>
#include <QTest>
#include <QWheelEvent>

#include "app/main_window.h"
#include "app/playback_controller.h"
#include "app/scene_widget.h"
#include "app/timeline_widget.h"
#include "app/twist_panel.h"
#include "app/view_controller.h"
#include "app/what_if_panel.h"
#include "core/scene_options.h"
#include "gui/support/image_checks.h"
#include "gui/support/menu_actions.h"
#include "gui/support/open_motion_fixture.h"

namespace saltus::gui {
namespace {

class MenusTest : public test::OpenMotionTest {
 protected:
  /// The entry at `path`, enabled, triggered; fails when there is none.
  QAction* entry(const QStringList& path) {
    QAction* a = test::menu_action(window_.get(), path);
    EXPECT_NE(a, nullptr) << path.join(" > ").toStdString();
    if (a) {
      EXPECT_TRUE(a->isEnabled()) << path.join(" > ").toStdString();
    }
    return a;
  }
  void press(const QStringList& path) {
    if (QAction* a = entry(path)) a->trigger();
    QApplication::processEvents();
  }
  const Timeline& timeline() { return window_->playback().timeline()->timeline(); }
};

TEST_F(MenusTest, CameraEntriesSetTheCameraAndResetUndoesAZoom) {
  for (CameraPreset preset : camera_presets()) {
    const QString label = QString::fromStdString(camera_preset_label(preset)) + " camera";
    SCOPED_TRACE(label.toStdString());
    press({"View", label});
    EXPECT_EQ(window_->view().camera(), preset);
    EXPECT_TRUE(entry({"View", label})->isChecked());
  }
  press({"View", "Side camera"});
  window_->fix_view_size(QSize(600, 400));
  const QImage framed = window_->grab_view();
  SceneWidget* view = window_->view_widget();
  const QPoint at(300, 200);
  for (int i = 0; i < 4; ++i) {
    QWheelEvent wheel(at, view->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view, &wheel);
  }
  QApplication::processEvents();
  const QImage zoomed = window_->grab_view();
  EXPECT_GT(test::block_difference(zoomed, framed), 0.05);
  press({"View", "Reset camera"});
  EXPECT_LT(test::block_difference(window_->grab_view(), framed), 0.01);
}

TEST_F(MenusTest, TheInterpolatedEntryShowsTheMotionBeforeOptimisation) {
  window_->set_stage(Stage::kBefore);
  press({"View", "Show interpolated motion (before)"});
  EXPECT_EQ(window_->stage(), Stage::kBefore);
  EXPECT_TRUE(entry({"View", "Show interpolated motion (before)"})->isChecked());
}

TEST_F(MenusTest, EachDisplayOptionEntryTogglesItsOption) {
  for (const SceneOptionInfo& info : scene_option_table()) {
    SCOPED_TRACE(info.label);
    const bool was = window_->view().scene_options().*info.field;
    press({"View", QString(info.label).remove('&')});
    EXPECT_EQ(window_->view().scene_options().*info.field, !was);
    press({"View", QString(info.label).remove('&')});
    EXPECT_EQ(window_->view().scene_options().*info.field, was);
  }
}

TEST_F(MenusTest, EachPanelEntryHidesAndShowsItsPanel) {
  const QList<QDockWidget*> docks = window_->findChildren<QDockWidget*>();
  ASSERT_EQ(docks.size(), 9);
  for (QDockWidget* dock : docks) {
    const QString text = test::shown_text(dock->toggleViewAction());
    SCOPED_TRACE(text.toStdString());
    const bool hidden = dock->isHidden();
    press({"View", text});
    EXPECT_EQ(dock->isHidden(), !hidden);
    press({"View", text});
    EXPECT_EQ(dock->isHidden(), hidden);
  }
}

TEST_F(MenusTest, TheTwistAndWhatIfEntriesBringTheirPanelsToTheFront) {
  // A tabbed dock behind another is "visible" to Qt but has nothing on screen.
  const auto on_screen = [](const QWidget& w) { return !w.visibleRegion().isEmpty(); };
  ASSERT_FALSE(on_screen(window_->twist()));
  press({"View", "Where does the twist come from?"});
  EXPECT_TRUE(on_screen(window_->twist()));
  ASSERT_FALSE(on_screen(window_->what_if()));
  press({"View", "What if…"});
  EXPECT_TRUE(on_screen(window_->what_if()));
  EXPECT_FALSE(on_screen(window_->twist()));
}

TEST_F(MenusTest, PlaybackEntriesMoveTheTimeAndChangeSpeedAndLoop) {
  const double end = timeline().duration();
  press({"Playback", "Go to end"});
  EXPECT_DOUBLE_EQ(window_->time(), end);
  press({"Playback", "Step back"});
  EXPECT_LT(window_->time(), end);
  EXPECT_GT(window_->time(), 0.9 * end);
  press({"Playback", "Go to start"});
  EXPECT_DOUBLE_EQ(window_->time(), 0.0);
  press({"Playback", "Step forward"});
  EXPECT_GT(window_->time(), 0.0);
  EXPECT_LT(window_->time(), 0.1 * end);

  press({"Playback", "Play / pause"});
  EXPECT_TRUE(window_->playback().playing());
  press({"Playback", "Pause"});  // the entry names what it will do
  EXPECT_FALSE(window_->playback().playing());

  const double speed = timeline().speed();
  press({"Playback", "Slower"});
  EXPECT_LT(timeline().speed(), speed);
  press({"Playback", "Faster"});
  EXPECT_DOUBLE_EQ(timeline().speed(), speed);
  press({"Playback", "Faster"});
  EXPECT_GT(timeline().speed(), speed);

  const bool loop = timeline().loop();
  press({"Playback", "Loop"});
  EXPECT_EQ(timeline().loop(), !loop);
  EXPECT_EQ(entry({"Playback", "Loop"})->isChecked(), !loop);
}

TEST_F(MenusTest, HelpEntriesOpenTheirDialogs) {
  const test::SeenDialog keys =
      test::trigger_and_close_dialog(entry({"Help", "Keyboard and mouse"}));
  EXPECT_TRUE(keys.shown);
  EXPECT_EQ(keys.title, "Keyboard and mouse");
  EXPECT_NE(keys.text.indexOf("Ctrl+O open"), -1) << keys.text.toStdString();
  const test::SeenDialog about = test::trigger_and_close_dialog(entry({"Help", "About Saltus"}));
  EXPECT_TRUE(about.shown);
  EXPECT_EQ(about.title, "About Saltus");
  EXPECT_NE(about.text.indexOf("Saltus"), -1) << about.text.toStdString();
  EXPECT_EQ(QApplication::activeModalWidget(), nullptr);
}

}  // namespace
}  // namespace saltus::gui
