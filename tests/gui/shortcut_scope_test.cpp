// Shortcuts act where they belong: Up/Down, Left/Right, Space, digits and B/A drive playback and
// the camera in the 3D view, the timeline and the plots, and never steal keys from an input
// field (the case: Up/Down in the Samples box changed the playback speed).

#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QLineEdit>
#include <QSpinBox>
#include <QTest>

#include "app/chart_widget.h"
#include "app/main_window.h"
#include "app/optimize_panel.h"
#include "app/playback_controller.h"
#include "app/plots_panel.h"
#include "app/run_controller.h"
#include "app/scene_widget.h"
#include "app/timeline_widget.h"
#include "app/view_controller.h"
#include "gui/support/open_motion_fixture.h"

namespace saltus::gui {
namespace {

class ShortcutScopeTest : public test::OpenMotionTest {
 protected:
  void SetUp() override {
    test::OpenMotionTest::SetUp();
    if (HasFatalFailure()) return;
    QApplication::setActiveWindow(window_.get());
    window_->set_camera(CameraPreset::kFollow);
    window_->seek(0.5);
  }
  double speed() const { return window_->playback().timeline()->timeline().speed(); }

  /// Focuses `widget` and types `key` into it, as a user would.
  void press(QWidget* widget, Qt::Key key) {
    widget->setFocus();
    QApplication::processEvents();
    ASSERT_TRUE(widget->hasFocus());
    QTest::keyClick(widget, key);
    QApplication::processEvents();
  }
};

TEST_F(ShortcutScopeTest, KeysInTheSamplesBoxStayInTheBox) {
  auto* samples = window_->runs().panel()->findChild<QSpinBox*>("samples");
  ASSERT_NE(samples, nullptr);
  const int value = samples->value();
  const double speed_before = speed();
  const double time_before = window_->time();
  press(samples, Qt::Key_Up);
  EXPECT_EQ(samples->value(), value + 1) << "Up did not reach the box";
  EXPECT_DOUBLE_EQ(speed(), speed_before) << "Up changed the playback speed";
  press(samples, Qt::Key_Down);
  EXPECT_EQ(samples->value(), value);
  press(samples, Qt::Key_Right);
  press(samples, Qt::Key_Space);
  press(samples, Qt::Key_Home);
  EXPECT_DOUBLE_EQ(window_->time(), time_before) << "a key in the box moved the time";
  EXPECT_FALSE(window_->playback().playing());
  // Digits and letters are typed, not taken as camera or stage keys.
  press(samples, Qt::Key_3);
  EXPECT_EQ(window_->view().camera(), CameraPreset::kFollow);
  auto* epsilon = window_->runs().panel()->findChild<QLineEdit*>("max_joint_turn");
  ASSERT_NE(epsilon, nullptr);
  press(epsilon, Qt::Key_B);
  press(epsilon, Qt::Key_R);
  EXPECT_EQ(window_->view().camera(), CameraPreset::kFollow);
  // The joint list in the plots: Down picks the next joint, playback stays as it was.
  window_->plots().setCurrentIndex(1);
  auto* joints = window_->plots().widget(1)->findChild<QComboBox*>();
  ASSERT_NE(joints, nullptr);
  const int joint = joints->currentIndex();
  press(joints, Qt::Key_Down);
  EXPECT_EQ(joints->currentIndex(), joint + 1);
  EXPECT_DOUBLE_EQ(speed(), speed_before);
}

TEST_F(ShortcutScopeTest, TheSameKeysDrivePlaybackAndCameraInTheView) {
  SceneWidget* view = window_->view_widget();
  const double speed_before = speed();
  press(view, Qt::Key_Up);
  EXPECT_GT(speed(), speed_before);
  press(view, Qt::Key_Down);
  EXPECT_DOUBLE_EQ(speed(), speed_before);
  const double t = window_->time();
  press(view, Qt::Key_Right);
  EXPECT_GT(window_->time(), t);
  press(view, Qt::Key_1);
  EXPECT_EQ(window_->view().camera(), CameraPreset::kSide);
  press(view, Qt::Key_4);
  EXPECT_EQ(window_->view().camera(), CameraPreset::kFollow);
  // And on the timeline.
  TimelineWidget* timeline = window_->playback().timeline();
  press(timeline, Qt::Key_End);
  EXPECT_DOUBLE_EQ(window_->time(), window_->document().duration());
  press(timeline, Qt::Key_Home);
  EXPECT_DOUBLE_EQ(window_->time(), 0.0);
  // And in a plot.
  ChartWidget* chart = window_->plots().force_chart();
  press(chart, Qt::Key_Right);
  EXPECT_GT(window_->time(), 0.0);
}

}  // namespace
}  // namespace saltus::gui
