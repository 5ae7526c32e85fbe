// The keyframe editor in the real window: moving a joint-angle slider re-evaluates the motion
// through the library and the root-force plot changes; bad edits show the library's message and
// change nothing; keyframes are added and deleted; the edited motion saves and loads back.

#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QListWidget>
#include <QSlider>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/chart_widget.h"
#include "app/compare_controller.h"
#include "app/edit_controller.h"
#include "app/file_controller.h"
#include "app/keyframe_panel.h"
#include "app/main_window.h"
#include "app/model_panel.h"
#include "app/plots_panel.h"
#include "app/run_controller.h"
#include "app/view_controller.h"
#include "gui/support/image_checks.h"
#include "gui/support/open_motion_fixture.h"
#include "gui_core/test_motion.h"
#include "support/cli_runner.h"

#include "saltus/base/input_error.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"

namespace saltus::gui {
namespace {

class KeyframeEditTest : public test::OpenMotionTest {
 protected:
  /// The root force plot (the chart titled so).
  ChartSpec force_chart() const {
    for (ChartWidget* chart : window_->findChildren<ChartWidget*>())
      if (chart->view().chart().title.rfind("Root force", 0) == 0) return chart->view().chart();
    return {};
  }
  const Motion& motion() const { return window_->document().file().motion; }

  /// Saves the window, with the dock holding `panel` raised, into the candidate folder (for a
  /// person to look at; nothing compares it).
  void save_with_panel_in_front(QWidget* panel, const char* name) {
    QWidget* dock = panel->parentWidget();
    while (dock && !dock->inherits("QDockWidget"))
      dock = dock->parentWidget();
    if (dock) dock->raise();
    QApplication::processEvents();
    QDir().mkpath(SALTUS_GUI_CANDIDATE_DIR);
    window_->grab_window().save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/" + name);
  }
};

TEST_F(KeyframeEditTest, MovingAnAngleSliderChangesTheRootForcePlot) {
  KeyframePanel* panel = window_->edits().keyframe_panel();
  ASSERT_NE(panel, nullptr);
  const int knee = window_->document().file().model.joint_index("knee_l");
  panel->select(2, knee);
  QApplication::processEvents();
  EXPECT_EQ(panel->selected_keyframe(), 2);
  EXPECT_EQ(panel->selected_segment(), knee);
  const ChartSpec before = force_chart();
  ASSERT_FALSE(before.lines.empty());
  EXPECT_NE(before.title.find("Root force"), std::string::npos) << before.title;
  const double force_before = window_->document().evaluation(Stage::kBefore).metrics.avg_root_force;

  // As a user drags: the X slider 40° further.
  QList<QSlider*> sliders = panel->findChildren<QSlider*>();
  ASSERT_EQ(sliders.size(), 3);
  sliders[0]->setValue(sliders[0]->value() - 400);
  QApplication::processEvents();

  EXPECT_TRUE(window_->workspace().motion_unsaved());
  EXPECT_TRUE(panel->problem().isEmpty()) << panel->problem().toStdString();
  const ChartSpec after = force_chart();
  ASSERT_EQ(after.lines.size(), before.lines.size());
  bool changed = false;
  for (std::size_t i = 0; i < after.lines.size(); ++i)
    changed = changed || after.lines[i].y != before.lines[i].y;
  EXPECT_TRUE(changed) << "the root force plot did not change";
  EXPECT_NE(window_->document().evaluation(Stage::kBefore).metrics.avg_root_force, force_before);
  EXPECT_NE(window_->windowTitle().indexOf("edited"), -1);
  // The selection survives the re-evaluation.
  EXPECT_EQ(panel->selected_keyframe(), 2);
  EXPECT_EQ(panel->selected_segment(), knee);
  // Left for a person to look at: the window with the Keyframes panel in front.
  save_with_panel_in_front(panel, "keyframe_editor.png");
}

TEST_F(KeyframeEditTest, BadEditsShowTheMessageAndChangeNothing) {
  const std::size_t n = motion().keyframes.size();
  const double t2 = motion().keyframes[2].time;
  QString error;
  EXPECT_FALSE(window_->edits().set_keyframe_time(1, t2, &error));
  EXPECT_NE(error.indexOf("before keyframe 3"), -1) << error.toStdString();
  EXPECT_EQ(window_->edits().keyframe_panel()->problem(), error);
  EXPECT_FALSE(window_->workspace().motion_unsaved());
  EXPECT_FALSE(window_->edits().delete_keyframe(0, &error));
  EXPECT_FALSE(window_->edits().add_keyframe(motion().keyframes[1].time, &error));
  EXPECT_EQ(motion().keyframes.size(), n);

  // Add one in the first interval, then delete it again.
  const double t = 0.5 * motion().keyframes[1].time;
  ASSERT_TRUE(window_->edits().add_keyframe(t, &error)) << error.toStdString();
  EXPECT_TRUE(window_->edits().keyframe_panel()->problem().isEmpty());
  ASSERT_EQ(motion().keyframes.size(), n + 1);
  EXPECT_DOUBLE_EQ(motion().keyframes[1].time, t);
  EXPECT_EQ(window_->edits().keyframe_panel()->selected_keyframe(), 1);
  EXPECT_EQ(window_->edits().keyframe_panel()->findChild<QListWidget*>()->count(),
            static_cast<int>(n + 1));
  ASSERT_TRUE(window_->edits().delete_keyframe(1, &error)) << error.toStdString();
  EXPECT_EQ(motion().keyframes.size(), n);
}

TEST_F(KeyframeEditTest, AnotherMotionOpensWithItsFirstKeyframeSelected) {
  KeyframePanel* panel = window_->edits().keyframe_panel();
  const int last = static_cast<int>(motion().keyframes.size()) - 1;
  panel->select(last, -1);
  ASSERT_EQ(panel->selected_keyframe(), last);
  QString error;
  ASSERT_TRUE(window_->open_motion(
      QString(SALTUS_EXAMPLES_DIR) + "/motions/M2-tucked-back-somersault.motion.json", &error))
      << error.toStdString();
  // The view shows t = 0: the panel shows the keyframe at t = 0, not the old selection.
  EXPECT_DOUBLE_EQ(window_->time(), 0.0);
  EXPECT_EQ(panel->selected_keyframe(), 0);
  EXPECT_EQ(panel->findChild<QListWidget*>()->currentRow(), 0);
}

TEST_F(KeyframeEditTest, EditedMotionSavesAndLoadsBack) {
  saltus::test::TempDir dir;
  const int hip = window_->document().file().model.joint_index("hip_r");
  QString error;
  ASSERT_TRUE(window_->edits().set_keyframe_angles(1, hip, -30.0, 5.0, 0.0, &error))
      << error.toStdString();
  const QString path = QString::fromStdString(dir / "edited.motion.json");
  // Saved next to nothing: the model is named as in the original ("zatsiorsky-66kg"), found
  // among the bundled models.
  ASSERT_TRUE(window_->files().save_motion(path, &error)) << error.toStdString();
  const Motion edited = motion();
  MainWindow second(false);
  ASSERT_TRUE(second.open_motion(path, &error)) << error.toStdString();
  const Motion& loaded = second.document().file().motion;
  ASSERT_EQ(loaded.keyframes.size(), edited.keyframes.size());
  EXPECT_TRUE(
      loaded.keyframes[1].rotations[hip].isApprox(edited.keyframes[1].rotations[hip], 1e-9));
  EXPECT_NEAR(second.document().evaluation(Stage::kBefore).metrics.avg_root_force,
              window_->document().evaluation(Stage::kBefore).metrics.avg_root_force, 1e-6);
}

TEST_F(KeyframeEditTest, AMotionSavedWithAnOpenedModelNamesItSoThatItLoadsBack) {
  // A model opened from a file (File > Open model) is named relative to where the motion is
  // saved; motion files may only name models in their own folder tree, so a motion saved
  // elsewhere is still written, loads with the model given, and the status bar says so.
  saltus::test::TempDir dir;
  const std::string model = dir / "my-model.json";
  std::filesystem::copy_file(
      std::string(SALTUS_EXAMPLES_DIR) + "/../resources/models/zatsiorsky-66kg.json", model);
  QString error;
  ASSERT_TRUE(window_->files().open_model(QString::fromStdString(model), &error))
      << error.toStdString();

  const std::string beside = dir / "beside.motion.json";
  ASSERT_TRUE(window_->files().save_motion(QString::fromStdString(beside), &error))
      << error.toStdString();
  EXPECT_EQ(read_motion_model_field(nlohmann::json::parse(std::ifstream(beside)), beside),
            "my-model.json");
  EXPECT_EQ(load_motion_file(beside).model.total_mass(),
            window_->document().file().model.total_mass());

  std::filesystem::create_directories(dir / "elsewhere");
  const std::string away = dir / "elsewhere/away.motion.json";
  ASSERT_TRUE(window_->files().save_motion(QString::fromStdString(away), &error))
      << error.toStdString();
  EXPECT_TRUE(window_->statusBar()->currentMessage().contains("File > Open model"))
      << window_->statusBar()->currentMessage().toStdString();
  EXPECT_THROW(load_motion_file(away), InputError);
  EXPECT_EQ(load_motion_file(away, model).motion.keyframes.size(), motion().keyframes.size());
}

TEST_F(KeyframeEditTest, MassTableScalesASegmentAndRejectsBadFactors) {
  ModelPanel* panel = window_->edits().model_panel();
  ASSERT_NE(panel, nullptr);
  const BodyModel& model = window_->document().file().model;
  const int thigh = model.segment_index("thigh_r");
  const double mass = model.total_mass();
  const double thigh_mass = model.segments[thigh].mass;
  const ChartSpec before = force_chart();
  QTableWidget* table = panel->table();
  ASSERT_EQ(table->rowCount(), model.size());

  // As a user types into the factor cell.
  table->item(thigh, 2)->setText("1.5");
  QApplication::processEvents();
  EXPECT_TRUE(panel->problem().isEmpty()) << panel->problem().toStdString();
  EXPECT_NEAR(window_->document().file().model.total_mass(), mass + 0.5 * thigh_mass, 1e-9);
  EXPECT_NEAR(table->item(thigh, 1)->text().toDouble(), 1.5 * thigh_mass, 1e-3);
  const ChartSpec after = force_chart();
  ASSERT_EQ(after.lines.size(), before.lines.size());
  bool changed = false;
  for (std::size_t i = 0; i < after.lines.size(); ++i)
    changed = changed || after.lines[i].y != before.lines[i].y;
  EXPECT_TRUE(changed);

  // A zero factor: the library's message, nothing changes.
  table->item(thigh, 2)->setText("0");
  QApplication::processEvents();
  EXPECT_NE(panel->problem().indexOf("positive"), -1) << panel->problem().toStdString();
  EXPECT_NEAR(window_->document().file().model.total_mass(), mass + 0.5 * thigh_mass, 1e-9);
  EXPECT_EQ(table->item(thigh, 2)->text(), "1.5");
  save_with_panel_in_front(panel, "model_editor.png");

  saltus::test::TempDir dir;
  QString error;
  const QString path = QString::fromStdString(dir / "heavy-thigh.json");
  ASSERT_TRUE(window_->files().save_model(path, &error)) << error.toStdString();
  const BodyModel saved = load_body_model(path.toStdString());
  EXPECT_EQ(saved.name, "heavy-thigh");
  EXPECT_NEAR(saved.segments[thigh].mass, 1.5 * thigh_mass, 1e-12);
}

}  // namespace
}  // namespace saltus::gui
