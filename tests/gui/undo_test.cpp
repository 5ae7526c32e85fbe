// Work is never lost, in the real window: keyframe, mass and option edits undo and redo (Edit
// menu, Ctrl+Z, Ctrl+Shift+Z, also with the focus in the number field just typed into); a
// slider drag is one step; undoing an edit brings back the
// optimisation run it made stale; opening another motion with unsaved work asks first, and
// messages of the previous motion are gone once another one opens.

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLocale>
#include <QMenu>
#include <QMenuBar>
#include <QSlider>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>
#include <QUndoStack>
#include <cmath>

#include "app/edit_controller.h"
#include "app/file_controller.h"
#include "app/keyframe_panel.h"
#include "app/main_window.h"
#include "app/model_panel.h"
#include "app/optimize_panel.h"
#include "app/run_controller.h"
#include "app/scene_widget.h"
#include "gui/support/open_motion_fixture.h"
#include "gui_core/test_motion.h"

namespace saltus::gui {
namespace {

class UndoTest : public test::OpenMotionTest {
 protected:
  double average_force() const {
    return window_->document().evaluation(Stage::kBefore).metrics.avg_root_force;
  }
  const Motion& motion() const { return window_->document().file().motion; }
  QUndoStack* stack() { return window_->edits().undo_stack(); }

  /// The Edit menu's action whose text starts with `text`.
  QAction* edit_action(const QString& text) {
    for (QAction* menu : window_->menuBar()->actions())
      if (menu->text().remove('&') == "Edit")
        for (QAction* a : menu->menu()->actions())
          if (a->text().remove('&').startsWith(text)) return a;
    return nullptr;
  }
};

bool same_rotations(const Motion& a, const Motion& b) {
  if (a.keyframes.size() != b.keyframes.size()) return false;
  for (std::size_t k = 0; k < a.keyframes.size(); ++k) {
    if (a.keyframes[k].time != b.keyframes[k].time) return false;
    for (std::size_t j = 0; j < a.keyframes[k].rotations.size(); ++j)
      if (!a.keyframes[k].rotations[j].isApprox(b.keyframes[k].rotations[j], 1e-12)) return false;
  }
  return true;
}

TEST_F(UndoTest, ASliderDragIsOneStepThatUndoesAndRedoes) {
  const Motion original = motion();
  const double force = average_force();
  KeyframePanel* panel = window_->edits().keyframe_panel();
  panel->select(2, window_->document().file().model.joint_index("knee_l"));
  QSlider* slider = panel->findChildren<QSlider*>().front();
  // A drag: many small moves in quick succession.
  for (int step = 1; step <= 8; ++step) {
    slider->setValue(slider->value() - 50);
    QApplication::processEvents();
  }
  const Motion edited = motion();
  const double edited_force = average_force();
  EXPECT_FALSE(same_rotations(edited, original));
  EXPECT_EQ(stack()->count(), 1) << "a drag must be one undo step";
  EXPECT_TRUE(window_->workspace().motion_unsaved());
  EXPECT_NE(window_->windowTitle().indexOf("edited"), -1);

  // Edit > Undo: Ctrl+Z, labelled with what it undoes.
  QAction* undo = edit_action("Undo");
  ASSERT_NE(undo, nullptr);
  EXPECT_EQ(undo->shortcut(), QKeySequence::keyBindings(QKeySequence::Undo).front());
  EXPECT_NE(undo->text().indexOf("left knee"), -1) << undo->text().toStdString();
  undo->trigger();
  EXPECT_TRUE(same_rotations(motion(), original));
  EXPECT_DOUBLE_EQ(average_force(), force);
  EXPECT_FALSE(window_->workspace().motion_unsaved());
  EXPECT_EQ(window_->windowTitle().indexOf("edited"), -1);

  QAction* redo = edit_action("Redo");
  ASSERT_NE(redo, nullptr);
  EXPECT_TRUE(redo->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)));
  redo->trigger();
  EXPECT_TRUE(same_rotations(motion(), edited));
  EXPECT_DOUBLE_EQ(average_force(), edited_force);
}

TEST_F(UndoTest, CtrlZInTheViewUndoesAMassEdit) {
  const BodyModel& model = window_->document().file().model;
  const int thigh = model.segment_index("thigh_r");
  const double mass = model.total_mass();
  QString error;
  std::vector<double> factors(static_cast<std::size_t>(model.size()), 1.0);
  factors[static_cast<std::size_t>(thigh)] = 1.5;
  ASSERT_TRUE(window_->edits().set_mass_factors(factors, &error)) << error.toStdString();
  EXPECT_GT(window_->document().file().model.total_mass(), mass);
  EXPECT_TRUE(window_->workspace().model_unsaved());
  // As a user presses it with the 3D view focused.
  QApplication::setActiveWindow(window_.get());
  window_->view_widget()->setFocus();
  QTest::keyClick(window_->view_widget(), Qt::Key_Z, Qt::ControlModifier);
  EXPECT_DOUBLE_EQ(window_->document().file().model.total_mass(), mass);
  EXPECT_FALSE(window_->workspace().model_unsaved());
  QTest::keyClick(window_->view_widget(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
  EXPECT_GT(window_->document().file().model.total_mass(), mass);
}

TEST_F(UndoTest, OptionEditsUndoToo) {
  auto* samples = window_->runs().panel()->findChild<QSpinBox*>("samples");
  ASSERT_NE(samples, nullptr);
  const int before = samples->value();
  // Two arrow clicks in quick succession: one step.
  samples->stepUp();
  samples->stepUp();
  EXPECT_EQ(window_->runs().settings().integer("samples"), before + 2);
  EXPECT_EQ(stack()->count(), 1);
  EXPECT_NE(stack()->undoText().indexOf("samples"), -1) << stack()->undoText().toStdString();
  window_->edits().undo();
  EXPECT_EQ(samples->value(), before);
  window_->edits().redo();
  EXPECT_EQ(samples->value(), before + 2);
}

/// Focuses `field`, selects its text and types `text` (then Enter when `enter`), as a user does.
void type_into(QAbstractSpinBox* field, const QString& text, bool enter) {
  field->setFocus();
  QApplication::processEvents();
  ASSERT_TRUE(field->hasFocus());
  field->selectAll();
  QTest::keyClicks(field, text);
  if (enter) QTest::keyClick(field, Qt::Key_Return);
  QApplication::processEvents();
}

TEST_F(UndoTest, CtrlZInANumberFieldUndoesTheValueEnteredThere) {
  QApplication::setActiveWindow(window_.get());
  auto* samples = window_->runs().panel()->findChild<QSpinBox*>("samples");
  ASSERT_NE(samples, nullptr);
  const int before = samples->value();
  const int typed = before == 77 ? 79 : 77;
  type_into(samples, QString::number(typed), true);
  ASSERT_EQ(samples->value(), typed);
  ASSERT_EQ(stack()->count(), 1);
  // The focus is still in the box: the keys undo and redo the edit, as the Edit menu does.
  ASSERT_TRUE(samples->hasFocus());
  QTest::keyClick(samples, Qt::Key_Z, Qt::ControlModifier);
  EXPECT_EQ(samples->value(), before);
  EXPECT_EQ(window_->runs().settings().integer("samples"), before);
  EXPECT_EQ(stack()->index(), 0);
  QTest::keyClick(samples, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
  EXPECT_EQ(samples->value(), typed);
  EXPECT_EQ(stack()->index(), 1);

  // A keyframe's time, typed and entered: undone from its own field too.
  window_->findChild<QDockWidget*>("keyframe_dock")->raise();
  KeyframePanel* panel = window_->edits().keyframe_panel();
  panel->select(2, -1);
  QDoubleSpinBox* time = nullptr;
  for (QDoubleSpinBox* box : panel->findChildren<QDoubleSpinBox*>())
    if (box->decimals() == 3) time = box;
  ASSERT_NE(time, nullptr);
  const double t0 = motion().keyframes[2].time;
  const double t1 = std::round((t0 + 0.02) * 1000.0) / 1000.0;
  type_into(time, QLocale().toString(t1, 'f', 3), true);
  ASSERT_NEAR(motion().keyframes[2].time, t1, 1e-12);
  ASSERT_TRUE(time->hasFocus());
  QTest::keyClick(time, Qt::Key_Z, Qt::ControlModifier);
  EXPECT_DOUBLE_EQ(motion().keyframes[2].time, t0);
  QTest::keyClick(time, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
  EXPECT_NEAR(motion().keyframes[2].time, t1, 1e-12);
}

TEST_F(UndoTest, CtrlZWhileTypingUndoesTheTypingOnly) {
  QApplication::setActiveWindow(window_.get());
  auto* samples = window_->runs().panel()->findChild<QSpinBox*>("samples");
  ASSERT_NE(samples, nullptr);
  const QString shown = samples->text();
  type_into(samples, "9", false);  // not entered yet
  ASSERT_NE(samples->text(), shown);
  QTest::keyClick(samples, Qt::Key_Z, Qt::ControlModifier);
  EXPECT_EQ(samples->text(), shown);
  EXPECT_EQ(stack()->count(), 0) << "nothing was entered, so nothing is on the undo stack";
}

TEST_F(UndoTest, UndoingAnEditBringsBackTheRunItMadeStale) {
  OptimizeSettings s;
  s.set("max_iterations", 4);
  s.set("samples", 31);
  QString error;
  ASSERT_TRUE(window_->runs().start(s, &error)) << error.toStdString();
  ASSERT_TRUE(window_->runs().wait(300000));
  ASSERT_EQ(window_->workspace().runs().size(), 1);
  ASSERT_TRUE(window_->workspace().runs().showable(0));
  window_->runs().show_run(0);
  ASSERT_TRUE(window_->document().has_optimization());
  const double after = window_->document().optimization().after.metrics.avg_root_force;

  const int hip = window_->document().file().model.joint_index("hip_l");
  ASSERT_TRUE(window_->edits().set_keyframe_angles(1, hip, -40, 0, 0, &error))
      << error.toStdString();
  // The run belonged to the motion before the edit.
  EXPECT_TRUE(window_->workspace().runs().empty());
  EXPECT_FALSE(window_->document().has_optimization());
  EXPECT_EQ(window_->stage(), Stage::kBefore);

  window_->edits().undo();
  ASSERT_EQ(window_->workspace().runs().size(), 1);
  EXPECT_EQ(window_->workspace().shown_run(), 0);
  ASSERT_TRUE(window_->document().has_optimization());
  EXPECT_DOUBLE_EQ(window_->document().optimization().after.metrics.avg_root_force, after);
  EXPECT_EQ(window_->stage(), Stage::kAfter);
}

TEST_F(UndoTest, OpeningAnotherMotionAsksBeforeDroppingUnsavedWork) {
  int asked = 0;
  QString question;
  auto answer = FileController::DiscardAnswer::kCancel;
  window_->files().set_discard_prompt([&](const QString& q) {
    ++asked;
    question = q;
    return answer;
  });
  const QString other =
      QString(SALTUS_EXAMPLES_DIR) + "/motions/M2-tucked-back-somersault.motion.json";
  // Nothing edited: no question.
  QString error;
  ASSERT_TRUE(window_->open_motion(QString::fromStdString(test::gui_test_motion_path()), &error));
  EXPECT_EQ(asked, 0);

  const int knee = window_->document().file().model.joint_index("knee_r");
  ASSERT_TRUE(window_->edits().set_keyframe_angles(1, knee, 30, 0, 0, &error));
  const Motion edited = motion();
  EXPECT_FALSE(window_->open_motion(other, &error));
  EXPECT_EQ(asked, 1);
  EXPECT_NE(question.indexOf("keyframes were edited"), -1) << question.toStdString();
  EXPECT_TRUE(same_rotations(motion(), edited)) << "the edited motion was dropped";
  // The user says "discard": it opens.
  answer = FileController::DiscardAnswer::kDiscard;
  EXPECT_TRUE(window_->open_motion(other, &error)) << error.toStdString();
  EXPECT_EQ(asked, 2);
  EXPECT_NE(QString::fromStdString(window_->document().file().path).indexOf("M2-"), -1);
  // The new motion starts with nothing to undo.
  EXPECT_EQ(stack()->count(), 0);
}

TEST_F(UndoTest, MessagesOfThePreviousMotionGoWhenAnotherOpens) {
  ModelPanel* model_panel = window_->edits().model_panel();
  QTableWidget* table = model_panel->table();
  table->item(3, 2)->setText("abc");
  QApplication::processEvents();
  // Worded for people: the segment and what to type.
  const QString problem = model_panel->problem();
  EXPECT_NE(problem.indexOf("positive number"), -1) << problem.toStdString();
  EXPECT_EQ(problem.indexOf("scale_segment_mass"), -1) << problem.toStdString();
  EXPECT_EQ(problem.indexOf("nan"), -1) << problem.toStdString();
  EXPECT_NE(problem.indexOf("left upper arm"), -1) << problem.toStdString();
  QString error;
  ASSERT_TRUE(window_->open_motion(
      QString(SALTUS_EXAMPLES_DIR) + "/motions/M2-tucked-back-somersault.motion.json", &error));
  EXPECT_TRUE(model_panel->problem().isEmpty());
  EXPECT_TRUE(window_->edits().keyframe_panel()->problem().isEmpty());
  EXPECT_TRUE(window_->runs().panel()->message().startsWith("Ready"))
      << window_->runs().panel()->message().toStdString();
}

}  // namespace
}  // namespace saltus::gui
