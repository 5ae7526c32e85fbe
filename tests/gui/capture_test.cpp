// A motion capture in the app: File > Import motion capture… (and a .bvh opened or dropped)
// imports it onto the model; the capture is drawn as a grey figure beside the athlete, its own
// residual is plotted, and keyframes are picked on its frames in the Capture panel (a click
// adds or removes one, undoable; "Pick automatically" is the library's rule); File > Export web
// page… puts the capture beside the athlete on the page, as `saltus export` does.

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QPushButton>
#include <QTest>
#include <QUndoStack>
#include <QUrl>
#include <fstream>

#include "app/capture_panel.h"
#include "app/chart_widget.h"
#include "app/edit_controller.h"
#include "app/file_controller.h"
#include "app/main_window.h"
#include "app/plots_panel.h"
#include "app/scene_widget.h"
#include "core/capture_keyframes.h"
#include "gui/support/image_checks.h"
#include "gui/support/open_motion_fixture.h"
#include "gui_core/test_motion.h"
#include "saltus/evaluation/force_metrics.h"
#include "saltus/evaluation/residual_measures.h"
#include "saltus/formats/flight_page.h"
#include "saltus/formats/motion_file.h"
#include "scene/chart_view.h"
#include "support/cli_runner.h"
#include "support/temp_path.h"

namespace saltus::gui {
namespace {

/// The test motion written as a BVH capture by the library (in the air throughout).
const QString& capture_path() {
  static const QString path = [] {
    const std::string out = saltus::test::temp_path("app-capture.bvh").string();
    export_motion_bvh(load_motion_file(test::gui_test_motion_path()), out, 30.0);
    return QString::fromStdString(out);
  }();
  return path;
}

class CaptureTest : public test::EmptyWindowTest {
 protected:
  void import() {
    QString error;
    ASSERT_TRUE(window_->open_motion(capture_path(), &error)) << error.toStdString();
    QApplication::processEvents();
    ASSERT_NE(window_->document().capture(), nullptr);
  }
  const Motion& motion() const { return window_->document().file().motion; }
  CapturePanel* panel() { return window_->edits().capture_panel(); }
  std::vector<int> picked() const {
    return capture_frames_in(motion(), *window_->document().capture());
  }
  /// The menu action under `menu` whose text starts with `text`.
  QAction* action(const QString& menu, const QString& text) {
    for (QAction* m : window_->menuBar()->actions())
      if (m->text().remove('&') == menu)
        for (QAction* a : m->menu()->actions())
          if (a->text().remove('&').startsWith(text)) return a;
    return nullptr;
  }
};

TEST_F(CaptureTest, FileMenuImportsACaptureAndThePanelSaysWhatItFound) {
  QAction* import_action = action("File", "Import motion capture");
  ASSERT_NE(import_action, nullptr);
  EXPECT_EQ(import_action->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_I));
  import();
  const CaptureFile& capture = *window_->document().capture();
  // The panel's words carry the import's numbers.
  const QString summary = panel()->summary();
  EXPECT_TRUE(summary.contains("app-capture.bvh")) << summary.toStdString();
  EXPECT_TRUE(summary.contains(QString::number(capture.import.source_frames) + " frames"));
  EXPECT_TRUE(summary.contains("no ground contact")) << summary.toStdString();
  const double residual = force_metrics(window_->document().capture_plot_samples()).avg_root_force;
  EXPECT_TRUE(summary.contains(QString::number(residual, 'g', 3) + " N")) << summary.toStdString();
  EXPECT_EQ(panel()->strip()->frame_count(),
            static_cast<int>(capture.import.captured.keyframes.size()));
  EXPECT_TRUE(panel()->pick_text().startsWith(QString("%1 of %2 flight frames are keyframes")
                                                  .arg(picked().size())
                                                  .arg(capture.import.captured.keyframes.size())))
      << panel()->pick_text().toStdString();
  // A motion file afterwards: no capture, the panel says so.
  ASSERT_TRUE(window_->open_motion(QString::fromStdString(test::gui_test_motion_path())));
  EXPECT_EQ(window_->document().capture(), nullptr);
  EXPECT_TRUE(panel()->summary().startsWith("No motion capture"));
  EXPECT_FALSE(panel()->strip()->isEnabled());
}

TEST_F(CaptureTest, TheCapturesResidualIsPlottedBesideTheMotions) {
  import();
  const ChartSpec& force = window_->plots().force_chart()->view().chart();
  const LineSpec* capture_line = nullptr;
  for (const LineSpec& line : force.lines)
    if (line.label == "|F| capture") capture_line = &line;
  ASSERT_NE(capture_line, nullptr);
  const std::vector<double> expected =
      root_force_magnitudes(window_->document().capture_plot_samples());
  EXPECT_EQ(capture_line->y, expected);
  const ChartSpec& moment = window_->plots().moment_chart()->view().chart();
  EXPECT_EQ(moment.lines.front().label, "|M| capture");
}

TEST_F(CaptureTest, TheCaptureIsDrawnBesideTheAthleteOnlyWhenThereIsOne) {
  import();
  window_->fix_view_size(QSize(800, 450));
  window_->seek(0.5 * window_->document().duration());
  SceneOptions options;
  options.capture_figure = true;
  window_->set_scene_options(options);
  const QImage with = window_->grab_view();
  options.capture_figure = false;
  window_->set_scene_options(options);
  const QImage without = window_->grab_view();
  // The grey figure fills a good part of the view beside the athlete.
  EXPECT_GT(test::block_difference(with, without), 0.02);
  // A motion without a capture looks the same either way.
  ASSERT_TRUE(window_->open_motion(QString::fromStdString(test::gui_test_motion_path())));
  window_->seek(0.5 * window_->document().duration());
  options.capture_figure = true;
  window_->set_scene_options(options);
  const QImage plain_with = window_->grab_view();
  options.capture_figure = false;
  window_->set_scene_options(options);
  EXPECT_LT(test::block_difference(plain_with, window_->grab_view()), 0.001);
  window_->fix_view_size(QSize());
}

TEST_F(CaptureTest, AClickOnAFrameAddsOrRemovesItAndUndoBringsItBack) {
  import();
  const CaptureFile& capture = *window_->document().capture();
  const std::vector<int> start = picked();
  // The first interior frame that is not a keyframe yet.
  int frame = 1;
  while (std::find(start.begin(), start.end(), frame) != start.end())
    ++frame;
  ASSERT_LT(frame, panel()->strip()->frame_count() - 1);
  QUndoStack* stack = window_->edits().undo_stack();
  QTest::mouseClick(panel()->strip(), Qt::LeftButton, Qt::NoModifier,
                    panel()->strip()->cell_centre(frame));
  QApplication::processEvents();
  std::vector<int> now = picked();
  EXPECT_EQ(now.size(), start.size() + 1);
  EXPECT_NE(std::find(now.begin(), now.end(), frame), now.end());
  EXPECT_EQ(stack->count(), 1);
  // The click also showed that frame.
  EXPECT_NEAR(window_->time(),
              capture.import.captured.keyframes[static_cast<std::size_t>(frame)].time, 1e-9);
  EXPECT_TRUE(window_->workspace().motion_unsaved());
  // A second click removes it again.
  QTest::mouseClick(panel()->strip(), Qt::LeftButton, Qt::NoModifier,
                    panel()->strip()->cell_centre(frame));
  QApplication::processEvents();
  EXPECT_EQ(picked(), start);
  // Ctrl+Z undoes the removal, Ctrl+Shift+Z redoes it.
  QApplication::setActiveWindow(window_.get());
  window_->view_widget()->setFocus();
  QTest::keyClick(window_->view_widget(), Qt::Key_Z, Qt::ControlModifier);
  QApplication::processEvents();
  EXPECT_EQ(picked().size(), start.size() + 1);
  QTest::keyClick(window_->view_widget(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
  QApplication::processEvents();
  EXPECT_EQ(picked(), start);
  // The flight's ends stay: a click there changes nothing and says why.
  const int count_before = stack->count();
  QTest::mouseClick(panel()->strip(), Qt::LeftButton, Qt::NoModifier,
                    panel()->strip()->cell_centre(0));
  QApplication::processEvents();
  EXPECT_EQ(picked(), start);
  EXPECT_EQ(stack->count(), count_before);
  EXPECT_TRUE(panel()->problem().contains("first and last frames"))
      << panel()->problem().toStdString();
}

TEST_F(CaptureTest, EveryFrameThenPickAutomaticallyIsTheLibrarysPickAndUndoes) {
  import();
  const CaptureFile& capture = *window_->document().capture();
  const std::vector<int> start = picked();
  QPushButton* every = nullptr;
  QPushButton* automatic = nullptr;
  for (QPushButton* b : panel()->findChildren<QPushButton*>()) {
    if (b->text() == "Every frame") every = b;
    if (b->text() == "Pick automatically") automatic = b;
  }
  ASSERT_TRUE(every && automatic);
  QTest::mouseClick(every, Qt::LeftButton);
  QApplication::processEvents();
  EXPECT_EQ(picked().size(), capture.import.captured.keyframes.size());
  EXPECT_EQ(motion().keyframes.size(), capture.import.captured.keyframes.size());
  QTest::mouseClick(automatic, Qt::LeftButton);
  QApplication::processEvents();
  EXPECT_EQ(picked(), pick_keyframes(capture.import.captured, capture.model).frames);
  window_->edits().undo();
  EXPECT_EQ(picked().size(), capture.import.captured.keyframes.size());
  window_->edits().undo();
  EXPECT_EQ(picked(), start);
}

TEST_F(CaptureTest, TheAdvicesFixIsOneClickAwayAndTheSettingsDialogHasEveryFlagItNames) {
  // The CMU backflip (MASS's copy) states 0.00833 s per frame, under which its flight does not
  // fall at g: the library suggests a frame time, and the panel offers it as a button.
  const QString cmu = SALTUS_EXAMPLES_DIR "/captures/mass-backflip.bvh";
  QString error;
  ASSERT_TRUE(window_->open_motion(cmu, &error)) << error.toStdString();
  QApplication::processEvents();
  const CaptureFile* first = window_->document().capture();
  ASSERT_NE(first, nullptr);
  ASSERT_TRUE(first->import.suggested_frame_time);
  const double suggested = *first->import.suggested_frame_time;
  ASSERT_EQ(panel()->fix_buttons().size(), 1u);
  QPushButton* fix = panel()->fix_buttons().front();
  EXPECT_TRUE(fix->text().startsWith("Re-import at ")) << fix->text().toStdString();
  fix->click();
  QApplication::processEvents();
  // Imported again at that frame time: the flight now falls at g, and the advice is gone.
  const CaptureFile* fixed = window_->document().capture();
  ASSERT_NE(fixed, nullptr);
  EXPECT_DOUBLE_EQ(fixed->import.frame_time, suggested);
  EXPECT_NEAR(fixed->import.implied_gravity, 9.81, 0.2 * 9.81);
  EXPECT_EQ(window_->document().capture_options().import.frame_time, suggested);
  EXPECT_TRUE(panel()->fix_buttons().empty());

  // Import settings…: the dialog (answered here) starts from the options in use, and the
  // capture is imported again with what it returns: 8 keyframes.
  std::optional<double> seen_frame_time;
  window_->files().set_capture_settings_chooser(
      [&](const QString&, const CaptureFileOptions& current, double,
          std::optional<double>) -> std::optional<CaptureFileOptions> {
        seen_frame_time = current.import.frame_time;
        CaptureFileOptions chosen = current;
        chosen.import.keyframe_count = 8;
        return chosen;
      });
  panel()->settings_button()->click();
  QApplication::processEvents();
  EXPECT_EQ(seen_frame_time, suggested);
  EXPECT_EQ(motion().keyframes.size(), 8u);
  EXPECT_DOUBLE_EQ(window_->document().capture()->import.frame_time, suggested);
}

TEST_F(CaptureTest, ABvhDroppedOnTheWindowIsImported) {
  QMimeData data;
  data.setUrls({QUrl::fromLocalFile(capture_path())});
  QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
  window_->files().drag_enter(&enter);
  EXPECT_TRUE(enter.isAccepted());
  QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
  window_->files().drop(&drop);
  QApplication::processEvents();
  ASSERT_NE(window_->document().capture(), nullptr);
  EXPECT_EQ(window_->document().file().path, capture_path().toStdString());
}

TEST_F(CaptureTest, ABrokenCaptureSaysWhichFileAndLineAndKeepsTheMotion) {
  ASSERT_TRUE(window_->open_motion(QString::fromStdString(test::gui_test_motion_path())));
  const std::string bad = saltus::test::temp_path("broken-app.bvh").string();
  {
    std::ofstream out(bad);
    out << "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 zero 0\n";
  }
  QString error;
  EXPECT_FALSE(window_->open_motion(QString::fromStdString(bad), &error));
  EXPECT_TRUE(error.contains("broken-app.bvh")) << error.toStdString();
  EXPECT_TRUE(error.contains("line")) << error.toStdString();
  EXPECT_EQ(window_->document().capture(), nullptr);
  EXPECT_EQ(window_->document().file().path, test::gui_test_motion_path());
}

TEST_F(CaptureTest, TheWebPageDrawsTheCaptureBesideTheAthlete) {
  import();
  saltus::test::TempDir dir;
  const std::string page = dir / "capture.html";
  QString error;
  ASSERT_TRUE(window_->files().export_web_page(QString::fromStdString(page), &error))
      << error.toStdString();
  const nlohmann::json data = read_flight_page_data(page);
  ASSERT_TRUE(data.contains("capture")) << "the capture the motion came from is on the page";
  const nlohmann::json& capture = data["capture"];
  EXPECT_GE(capture["t"].size(), 2u);
  // Its residual against `saltus import` of the same file, the model unchanged.
  const auto run = saltus::test::run_cli("import " + capture_path().toStdString() +
                                         " --quiet --out " + (dir / "imported"));
  ASSERT_EQ(run.status, 0) << run.output;
  const double imported =
      saltus::test::read_json(dir / "imported/result.json")["capture"]["residual"]["avg_root_force"]
          .get<double>();
  EXPECT_NEAR(capture["residual"]["avg_root_force"].get<double>(), imported, 1e-9 * imported);

  // A motion file has no capture to draw.
  ASSERT_TRUE(window_->open_motion(QString::fromStdString(test::gui_test_motion_path())));
  const std::string plain = dir / "motion.html";
  ASSERT_TRUE(window_->files().export_web_page(QString::fromStdString(plain), &error))
      << error.toStdString();
  EXPECT_FALSE(read_flight_page_data(plain).contains("capture"));
}

}  // namespace
}  // namespace saltus::gui
