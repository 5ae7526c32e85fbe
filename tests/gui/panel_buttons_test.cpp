// The buttons and check boxes of the panels beside and under the 3D view, each pressed with the
// mouse and its effect read back: the Keyframes panel adds and deletes keyframes, the Model
// panel resets the masses and opens the athlete dialog, the timeline's buttons move the time and
// play, the Display panel's boxes switch the 3D view's options, the Optimise panel's switches
// change the run's settings, the plots' boxes redraw the root charts, and the toolbar's Compare…
// button drops down the Compare menu.

#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QDockWidget>
#include <QMenu>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>

#include "app/athlete_controller.h"
#include "app/chart_widget.h"
#include "app/edit_controller.h"
#include "app/keyframe_panel.h"
#include "app/main_window.h"
#include "app/model_panel.h"
#include "app/new_athlete_dialog.h"
#include "app/optimize_panel.h"
#include "app/playback_controller.h"
#include "app/plots_panel.h"
#include "app/run_controller.h"
#include "app/timeline_widget.h"
#include "app/view_controller.h"
#include "core/scene_options.h"
#include "gui/support/open_motion_fixture.h"
#include "saltus/optim/option_table.h"

namespace saltus::gui {
namespace {

class PanelButtonsTest : public test::OpenMotionTest {
 protected:
  /// The button of `parent` with `text`, enabled, clicked with the mouse.
  template <class Button>
  static void press(QWidget* parent, const QString& text) {
    for (Button* b : parent->findChildren<Button*>()) {
      if (b->text() == text) {
        ASSERT_TRUE(b->isEnabled()) << text.toStdString();
        QTest::mouseClick(b, Qt::LeftButton);
        QApplication::processEvents();
        return;
      }
    }
    FAIL() << "no button " << text.toStdString();
  }
  const Motion& motion() const { return window_->document().file().motion; }
};

TEST_F(PanelButtonsTest, KeyframesPanelAddsAndDeletesKeyframes) {
  KeyframePanel* panel = window_->edits().keyframe_panel();
  const std::size_t count = motion().keyframes.size();
  const double t = 0.5 * (motion().keyframes[0].time + motion().keyframes[1].time);
  window_->seek(t);
  press<QPushButton>(panel, "Add at current time");
  ASSERT_EQ(motion().keyframes.size(), count + 1);
  EXPECT_NEAR(motion().keyframes[1].time, t, 1e-9);

  panel->select(1, 0);
  press<QPushButton>(panel, "Delete");
  ASSERT_EQ(motion().keyframes.size(), count);
  EXPECT_GT(motion().keyframes[1].time, t);
}

TEST_F(PanelButtonsTest, ModelPanelResetsTheMassesAndOpensTheAthleteDialog) {
  const BodyModel& model = window_->document().file().model;
  const auto thigh = static_cast<std::size_t>(model.segment_index("thigh_r"));
  const double loaded = model.segments[thigh].mass;
  std::vector<double> factors(static_cast<std::size_t>(model.size()), 1.0);
  factors[thigh] = 2.0;
  QString error;
  ASSERT_TRUE(window_->edits().set_mass_factors(factors, &error)) << error.toStdString();
  ASSERT_NEAR(window_->document().file().model.segments[thigh].mass, 2 * loaded, 1e-9);
  ModelPanel* panel = window_->edits().model_panel();
  press<QPushButton>(panel, "Reset masses");
  EXPECT_NEAR(window_->document().file().model.segments[thigh].mass, loaded, 1e-9);

  ASSERT_EQ(window_->athletes().dialog(), nullptr);
  press<QPushButton>(panel, "New athlete…");
  ASSERT_NE(window_->athletes().dialog(), nullptr);
  EXPECT_TRUE(window_->athletes().dialog()->isVisible());
  window_->athletes().dialog()->close();
}

TEST_F(PanelButtonsTest, TimelineButtonsStepPlayAndLoop) {
  TimelineWidget* timeline = window_->playback().timeline();
  window_->seek(0.0);
  press<QToolButton>(timeline, "Step forward");
  const double stepped = window_->time();
  EXPECT_GT(stepped, 0.0);
  press<QToolButton>(timeline, "Step back");
  EXPECT_DOUBLE_EQ(window_->time(), 0.0);
  press<QToolButton>(timeline, "Play");
  EXPECT_TRUE(window_->playback().playing());
  window_->playback().seek(0.0);
  EXPECT_FALSE(window_->playback().playing());

  const bool loop = timeline->timeline().loop();
  press<QCheckBox>(timeline, "Loop");
  EXPECT_EQ(timeline->timeline().loop(), !loop);
}

TEST_F(PanelButtonsTest, DisplayPanelBoxesSwitchTheViewsOptions) {
  auto* display = window_->findChild<QDockWidget*>("display_dock");
  ASSERT_NE(display, nullptr);
  for (const SceneOptionInfo& info : scene_option_table()) {
    SCOPED_TRACE(info.label);
    QCheckBox* box = nullptr;
    for (QCheckBox* b : display->findChildren<QCheckBox*>())
      if (b->text() == QString(info.label).remove('&')) box = b;
    ASSERT_NE(box, nullptr);
    const bool was = window_->view().scene_options().*info.field;
    // On the box's square: a box as wide as the panel takes no click beside its label.
    QTest::mouseClick(box, Qt::LeftButton, Qt::NoModifier, QPoint(8, box->height() / 2));
    QApplication::processEvents();
    EXPECT_EQ(window_->view().scene_options().*info.field, !was);
  }
}

TEST_F(PanelButtonsTest, OptimisePanelSwitchesChangeTheRunsSettings) {
  int switches = 0;
  for (QCheckBox* box : window_->runs().panel()->findChildren<QCheckBox*>()) {
    const std::string name = box->objectName().toStdString();
    SCOPED_TRACE(name);
    ASSERT_EQ(option_spec(name).kind, OptionKind::kSwitch);
    if (!box->isEnabled()) continue;
    const bool was = window_->runs().settings().on(name);
    QTest::mouseClick(box, Qt::LeftButton);
    QApplication::processEvents();
    EXPECT_EQ(window_->runs().settings().on(name), !was);
    ++switches;
  }
  EXPECT_GT(switches, 0);
}

TEST_F(PanelButtonsTest, PlotsBoxesRedrawTheRootCharts) {
  ChartWidget* force = window_->plots().charts().front();
  QSignalSpy redrawn(force, &ChartWidget::chart_changed);
  int pressed = 0;
  for (const char* text : {"Components", "x", "y", "z"}) {
    SCOPED_TRACE(text);
    press<QCheckBox>(&window_->plots(), text);
    EXPECT_EQ(redrawn.count(), ++pressed);
  }
  // The log scale is for |F| and |M| (not the components) before and after: there once a run is
  // shown.
  press<QCheckBox>(&window_->plots(), "Components");
  OptimizeSettings s;
  s.set("max_iterations", 3);
  s.set("samples", 31);
  ASSERT_TRUE(window_->runs().start(s));
  ASSERT_TRUE(window_->runs().wait(300000));
  ASSERT_TRUE(window_->runs().show_run(0));
  QApplication::processEvents();
  const int before = redrawn.count();
  press<QCheckBox>(&window_->plots(), "Log scale");
  EXPECT_EQ(redrawn.count(), before + 1);
}

TEST_F(PanelButtonsTest, ToolbarCompareButtonDropsDownTheCompareMenu) {
  QToolButton* compare = nullptr;
  for (QToolButton* b : window_->findChild<QToolBar*>("main_toolbar")->findChildren<QToolButton*>())
    if (b->text() == "Compare…") compare = b;
  ASSERT_NE(compare, nullptr);
  QString shown;
  QTimer::singleShot(200, [&shown] {
    if (auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget())) {
      for (QAction* a : menu->actions())
        if (!a->isSeparator()) shown += a->text().remove('&') + ";";
      menu->close();
    }
  });
  QTest::mouseClick(compare, Qt::LeftButton);
  QApplication::processEvents();
  EXPECT_NE(shown.indexOf("With another motion…"), -1) << shown.toStdString();
}

}  // namespace
}  // namespace saltus::gui
