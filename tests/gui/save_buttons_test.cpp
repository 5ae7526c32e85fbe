// The Keyframes panel's "Save motion…" and the Model panel's "Save model…" buttons, pressed as a
// user presses them: the save dialog (answered by the test) picks the file, the library's
// writers write it, and the file read back by the library holds the edited keyframes or masses.
// Cancelling the dialog writes nothing; a file that cannot be written is said in the status bar.

#include <gtest/gtest.h>

#include <QApplication>
#include <QPushButton>
#include <QStatusBar>
#include <QTest>
#include <filesystem>
#include <fstream>

#include "app/edit_controller.h"
#include "app/file_controller.h"
#include "app/keyframe_panel.h"
#include "app/main_window.h"
#include "app/model_panel.h"
#include "gui/support/open_motion_fixture.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "support/temp_path.h"

namespace saltus::gui {
namespace {

class SaveButtonsTest : public test::OpenMotionTest {
 protected:
  /// The dialog answered with `answer`; counts the questions and keeps the last title.
  void answer_save_dialog(const QString& answer) {
    window_->files().set_save_chooser(
        [this, answer](const QString& title, const QString&, const QString&) {
          ++asked_;
          title_ = title;
          return answer;
        });
  }
  /// The panel's button labelled `text`, pressed with the mouse.
  static void press(QWidget* panel, const QString& text) {
    for (QPushButton* b : panel->findChildren<QPushButton*>()) {
      if (b->text() == text) {
        ASSERT_TRUE(b->isEnabled()) << text.toStdString();
        QTest::mouseClick(b, Qt::LeftButton);
        QApplication::processEvents();
        return;
      }
    }
    FAIL() << "no button " << text.toStdString();
  }

  int asked_ = 0;
  QString title_;
};

TEST_F(SaveButtonsTest, SaveMotionWritesTheEditedMotionThroughTheDialog) {
  const Motion original = window_->document().file().motion;
  const int knee = window_->document().file().model.joint_index("knee_l");
  QString error;
  ASSERT_TRUE(window_->edits().set_keyframe_angles(2, knee, -95, 0, 0, &error))
      << error.toStdString();
  const Motion edited = window_->document().file().motion;
  ASSERT_TRUE(window_->workspace().motion_unsaved());

  const std::filesystem::path path = saltus::test::temp_path("saved.motion.json");
  answer_save_dialog(QString::fromStdString(path.string()));
  press(window_->edits().keyframe_panel(), "Save motion…");
  EXPECT_EQ(asked_, 1);
  EXPECT_EQ(title_, "Save the keyframes as edited");
  ASSERT_TRUE(std::filesystem::exists(path));

  // Read back by the library: the edited keyframes, not the ones opened.
  const MotionFile back = load_motion_file(path.string());
  ASSERT_EQ(back.motion.keyframes.size(), edited.keyframes.size());
  const auto k = static_cast<std::size_t>(2);
  const auto j = static_cast<std::size_t>(knee);
  EXPECT_TRUE(
      back.motion.keyframes[k].rotations[j].isApprox(edited.keyframes[k].rotations[j], 1e-12));
  EXPECT_FALSE(
      back.motion.keyframes[k].rotations[j].isApprox(original.keyframes[k].rotations[j], 1e-6));
  for (std::size_t i = 0; i < edited.keyframes.size(); ++i)
    EXPECT_DOUBLE_EQ(back.motion.keyframes[i].time, edited.keyframes[i].time);
  EXPECT_FALSE(window_->workspace().motion_unsaved());
  EXPECT_NE(window_->statusBar()->currentMessage().indexOf("saved.motion.json"), -1)
      << window_->statusBar()->currentMessage().toStdString();
}

TEST_F(SaveButtonsTest, SaveModelWritesTheEditedMassesThroughTheDialog) {
  const BodyModel& model = window_->document().file().model;
  const int thigh = model.segment_index("thigh_r");
  const double loaded_mass = model.segments[static_cast<std::size_t>(thigh)].mass;
  std::vector<double> factors(static_cast<std::size_t>(model.size()), 1.0);
  factors[static_cast<std::size_t>(thigh)] = 1.5;
  QString error;
  ASSERT_TRUE(window_->edits().set_mass_factors(factors, &error)) << error.toStdString();
  ASSERT_TRUE(window_->workspace().model_unsaved());

  const std::filesystem::path path = saltus::test::temp_path("heavy-thigh.json");
  answer_save_dialog(QString::fromStdString(path.string()));
  press(window_->edits().model_panel(), "Save model…");
  EXPECT_EQ(asked_, 1);
  EXPECT_EQ(title_, "Save body model");
  ASSERT_TRUE(std::filesystem::exists(path));
  const BodyModel back = load_body_model(path.string());
  ASSERT_EQ(back.size(), model.size());
  EXPECT_NEAR(back.segments[static_cast<std::size_t>(thigh)].mass, 1.5 * loaded_mass, 1e-9);
  EXPECT_EQ(back.name, "heavy-thigh");
  EXPECT_FALSE(window_->workspace().model_unsaved());
}

TEST_F(SaveButtonsTest, ACancelledDialogWritesNothingAndAFailureIsSaid) {
  const int knee = window_->document().file().model.joint_index("knee_r");
  QString error;
  ASSERT_TRUE(window_->edits().set_keyframe_angles(1, knee, -30, 0, 0, &error));
  answer_save_dialog(QString());
  press(window_->edits().keyframe_panel(), "Save motion…");
  EXPECT_EQ(asked_, 1);
  EXPECT_TRUE(window_->workspace().motion_unsaved());

  // A file Saltus did not write (the dialog's "replace?" answered yes): left as it was, the file
  // named in the status bar, as the command line's writers do.
  const std::filesystem::path folder = saltus::test::temp_path("foreign");
  std::filesystem::create_directories(folder);
  const std::filesystem::path foreign = folder / "m.motion.json";
  std::ofstream(foreign) << "my notes\n";
  answer_save_dialog(QString::fromStdString(foreign.string()));
  press(window_->edits().keyframe_panel(), "Save motion…");
  EXPECT_EQ(asked_, 2);
  std::ifstream kept(foreign);
  std::string line;
  std::getline(kept, line);
  EXPECT_EQ(line, "my notes");
  EXPECT_TRUE(window_->workspace().motion_unsaved());
  const QString said = window_->statusBar()->currentMessage();
  EXPECT_TRUE(said.startsWith("Not saved")) << said.toStdString();
  EXPECT_NE(said.indexOf("m.motion.json"), -1) << said.toStdString();
}

}  // namespace
}  // namespace saltus::gui
