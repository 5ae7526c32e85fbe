// The real main window under Xvfb: open the test motion, draw it, optimise it in the background
// with a few iterations (the window keeps processing events), compare the 3D view with the
// committed baselines, cancel, bad input, saving and exporting; one arrow scale before and after
// a run; a click on the timeline; display options that agree after a restart.

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QTabWidget>
#include <QTest>
#include <QTimer>
#include <QUrl>
#include <algorithm>
#include <filesystem>

#include "app/compare_controller.h"
#include "app/edit_controller.h"
#include "app/file_controller.h"
#include "app/main_window.h"
#include "app/optimization_runner.h"
#include "app/playback_controller.h"
#include "app/plots_panel.h"
#include "app/run_controller.h"
#include "app/scene_widget.h"
#include "app/strength_strips.h"
#include "app/timeline_widget.h"
#include "app/view_controller.h"
#include "core/joint_load_view.h"
#include "gui/support/image_checks.h"
#include "gui_core/test_motion.h"
#include "saltus/evaluation/apparatus.h"
#include "saltus/evaluation/clearance.h"
#include "support/cli_runner.h"

namespace saltus::gui {
namespace {

/// Fixed window size, and 3D view size for pictures compared with baselines (pinned so that
/// changes of the panels around it do not change the picture).
constexpr int kWidth = 1280;
constexpr int kHeight = 800;
constexpr int kViewWidth = 800;
constexpr int kViewHeight = 420;
/// The time shown in the baseline pictures: a third of the way up, body inverted.
constexpr double kShownTime = 0.8;

QString motion_path() {
  return QString::fromStdString(test::gui_test_motion_path());
}

QString baseline_name(const char* what) {
  return QString::fromStdString(test::gui_test_motion_stem()) + "_" + what;
}

/// A shown window of the fixed size with the test motion open.
class MainWindowTest : public ::testing::Test {
 protected:
  void SetUp() override {
    window_ = std::make_unique<MainWindow>(false);
    window_->resize(kWidth, kHeight);
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
    // Keyboard shortcuts need the active window (Xvfb has no window manager to activate it).
    QApplication::setActiveWindow(window_.get());
    QString error;
    ASSERT_TRUE(window_->open_motion(motion_path(), &error)) << error.toStdString();
    window_->set_camera(CameraPreset::kFollow);
    QApplication::processEvents();
  }
  void TearDown() override {
    window_->close();
    window_.reset();
  }

  OptimizeSettings few_iterations() const {
    OptimizeSettings s;
    s.set("max_iterations", 3);
    s.set("samples", 31);
    return s;
  }

  /// Drags `data` onto the window and drops it, as the window system would.
  void drop(QMimeData* data) {
    QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, data, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &enter);
    ASSERT_TRUE(enter.isAccepted()) << "the window refused the drag";
    QDropEvent drop_event(QPointF(50, 50), Qt::CopyAction, data, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &drop_event);
  }

  std::unique_ptr<MainWindow> window_;
};

TEST(MainWindowEmpty, StartsWithoutAMotionAndSaysWhatToDo) {
  MainWindow window(false);
  window.resize(kWidth, kHeight);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  EXPECT_FALSE(window.document().loaded());
  QString error;
  EXPECT_FALSE(window.files().save_result("/tmp/never-written", &error));
  EXPECT_FALSE(window.runs().start(OptimizeSettings{}, &error));
  EXPECT_FALSE(error.isEmpty());
  QTest::keyClick(&window, Qt::Key_Space);  // nothing to play: no crash
  const QImage picture = window.grab_window();
  EXPECT_GT(test::blank_check(picture).distinct_colours, 10);
  QDir().mkpath(SALTUS_GUI_CANDIDATE_DIR);
  picture.save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/empty_window.png");
}

TEST(MainWindowSettings, RemembersPanelValuesAndRecentFiles) {
  // Qt's test mode keeps these settings away from the user's own.
  QStandardPaths::setTestModeEnabled(true);
  QSettings().clear();
  {
    MainWindow first(true);
    // Its run is unsaved: closing asks; here the answer is "discard", as a user would click.
    first.files().set_discard_prompt(
        [](const QString&) { return FileController::DiscardAnswer::kDiscard; });
    first.show();
    ASSERT_TRUE(first.open_motion(motion_path()));
    OptimizeSettings s;
    s.set("max_iterations", 2);
    s.set("samples", 21);
    s.set("optimize_timing", false);
    ASSERT_TRUE(first.runs().start(s));
    ASSERT_TRUE(first.runs().wait(300000));
    first.close();
  }
  MainWindow second(true);
  EXPECT_EQ(second.runs().settings().integer("max_iterations"), 2);
  EXPECT_EQ(second.runs().settings().integer("samples"), 21);
  EXPECT_FALSE(second.runs().settings().on("optimize_timing"));
  const QStringList recent = QSettings().value("files/recent").toStringList();
  ASSERT_FALSE(recent.isEmpty());
  EXPECT_EQ(QFileInfo(recent.front()).fileName(), QFileInfo(motion_path()).fileName());
  QSettings().clear();
  QStandardPaths::setTestModeEnabled(false);
}

/// The View menu's entry labelled `label` (without its '&').
QAction* view_menu_action(MainWindow& window, const QString& label) {
  for (QAction* menu : window.menuBar()->actions())
    if (menu->text().remove('&') == "View")
      for (QAction* a : menu->menu()->actions())
        if (a->text().remove('&') == label) return a;
  return nullptr;
}

/// The Display panel's check box labelled `label`.
QCheckBox* display_box(MainWindow& window, const QString& label) {
  auto* dock = window.findChild<QDockWidget*>("display_dock");
  if (!dock) return nullptr;
  for (QCheckBox* box : dock->findChildren<QCheckBox*>())
    if (box->text() == label) return box;
  return nullptr;
}

TEST(MainWindowSettings, TheViewMenuAndTheDisplayPanelAgreeAfterARestart) {
  QStandardPaths::setTestModeEnabled(true);
  QSettings().clear();
  const QString ghosts = "Keyframe poses";
  const QString joints = "Joint force arrows";
  {
    MainWindow first(true);
    first.show();
    ASSERT_TRUE(first.open_motion(motion_path()));
    // One by the View menu, one by the Display panel; each control shows the other's change.
    QAction* ghosts_action = view_menu_action(first, ghosts);
    QCheckBox* joints_box = display_box(first, joints);
    ASSERT_NE(ghosts_action, nullptr);
    ASSERT_NE(joints_box, nullptr);
    ASSERT_FALSE(ghosts_action->isChecked());
    ASSERT_FALSE(joints_box->isChecked());
    ghosts_action->trigger();
    joints_box->click();
    EXPECT_TRUE(display_box(first, ghosts)->isChecked());
    EXPECT_TRUE(view_menu_action(first, joints)->isChecked());
    first.close();  // remembers the settings
  }
  MainWindow second(true);
  second.show();
  ASSERT_TRUE(second.open_motion(motion_path()));
  const SceneOptions drawn = second.view().scene()->scene().options();
  EXPECT_TRUE(drawn.ghosts);
  EXPECT_TRUE(drawn.joint_arrows);
  // Every option: the menu, the panel and the picture say the same.
  for (const SceneOptionInfo& info : scene_option_table()) {
    const QString label = QString(info.label).remove('&');
    QAction* action = view_menu_action(second, label);
    QCheckBox* box = display_box(second, label);
    ASSERT_NE(action, nullptr) << info.label;
    ASSERT_NE(box, nullptr) << info.label;
    EXPECT_EQ(action->isChecked(), drawn.*info.field) << info.label;
    EXPECT_EQ(box->isChecked(), drawn.*info.field) << info.label;
  }
  second.close();
  QSettings().clear();
  QStandardPaths::setTestModeEnabled(false);
}

TEST_F(MainWindowTest, AClickOnTheTimelineJumpsToTheTimeUnderTheMouse) {
  QSlider* slider = window_->playback().timeline()->findChild<QSlider*>();
  ASSERT_NE(slider, nullptr);
  const double duration = window_->document().duration();
  const double dt = duration / (window_->document().frame_count(window_->stage()) - 1);
  window_->seek(0.0);
  // The handle's centre runs from the groove's left plus half a handle to its right minus half.
  QStyleOptionSlider option;
  option.initFrom(slider);
  option.orientation = Qt::Horizontal;
  option.minimum = slider->minimum();
  option.maximum = slider->maximum();
  const QRect groove =
      slider->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderGroove, slider);
  const QRect handle =
      slider->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider);
  for (double fraction : {0.8, 0.3, 0.55}) {
    const int x = groove.left() + handle.width() / 2 +
                  static_cast<int>(std::lround(fraction * (groove.width() - handle.width())));
    QTest::mouseClick(slider, Qt::LeftButton, Qt::NoModifier, QPoint(x, slider->height() / 2));
    QApplication::processEvents();
    // Within two frames of the time under the mouse (a pixel is about a frame here).
    EXPECT_NEAR(window_->time(), fraction * duration, 2.0 * dt) << fraction;
  }
}

TEST_F(MainWindowTest, TheDivesClosestPassAndEntryAreFlaggedOnTheTimeline) {
  // The trampoline skill: one green flag, clear of the frame.
  TimelineWidget* timeline = window_->playback().timeline();
  ASSERT_EQ(timeline->flags().size(), 1u);
  EXPECT_EQ(timeline->flags()[0].kind, FlagKind::kClearance);
  // Named beside the strip, in full, without pointing at it.
  auto* legend = timeline->findChild<QLabel*>("timeline_flag_legend");
  ASSERT_NE(legend, nullptr);
  const auto expect_legend_shown_whole = [legend] {
    EXPECT_TRUE(legend->isVisible());
    EXPECT_GE(legend->width(), legend->sizeHint().width()) << "the legend is cut";
    EXPECT_GE(legend->height(), legend->fontMetrics().height()) << "the legend is cut";
  };
  EXPECT_EQ(timeline->flag_legend().toStdString(), "\u25B2 closest pass, clear");
  expect_legend_shown_whole();
  // The dive: the closest pass inside the platform's space and the entry, where the library
  // puts them for the samples shown.
  QString error;
  const std::string dive =
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/dive-5m-front-one-and-a-half-twists.motion.json";
  ASSERT_TRUE(window_->open_motion(QString::fromStdString(dive), &error)) << error.toStdString();
  QApplication::processEvents();
  const Document& d = window_->document();
  const std::vector<SampleRecord>& samples = d.evaluation(Stage::kBefore).samples;
  const Apparatus apparatus = apparatus_for(d.file().model, d.file().motion.takeoff, samples);
  const ApparatusClearance c = apparatus_clearance(d.file().model, apparatus, samples);
  const auto entry = dive_entry(d.file().model, apparatus, samples);
  ASSERT_TRUE(entry.has_value());
  const std::vector<TimelineFlag>& flags = timeline->flags();
  ASSERT_EQ(flags.size(), 2u);
  EXPECT_EQ(flags[0].kind, FlagKind::kCollision);
  EXPECT_DOUBLE_EQ(flags[0].time, c.time_s);
  EXPECT_EQ(flags[1].kind, FlagKind::kEntry);
  EXPECT_DOUBLE_EQ(flags[1].time, entry->time_s);
  // What a coach reads on pointing at them.
  auto* strip = timeline->findChild<TickStrip*>();
  ASSERT_NE(strip, nullptr);
  EXPECT_TRUE(strip->toolTip().contains("the body would strike the platform"))
      << strip->toolTip().toStdString();
  EXPECT_TRUE(strip->toolTip().contains("Entry at")) << strip->toolTip().toStdString();
  // And named beside it: both kinds, in the flags' order.
  EXPECT_EQ(timeline->flag_legend().toStdString(),
            "\u25B2 closest pass, inside   \u25B2 entry, vertical");
  expect_legend_shown_whole();
  // Drawn: red pixels (the collision) and blue ones (the vertical entry) on the strip.
  const QImage picture = strip->grab().toImage();
  int red = 0, blue = 0;
  for (int y = 0; y < picture.height(); ++y)
    for (int x = 0; x < picture.width(); ++x) {
      const QColor p = picture.pixelColor(x, y);
      red += p.red() > 180 && p.green() < 80 && p.blue() < 80;
      blue += p.blue() > 150 && p.red() < 60 && p.green() > 90 && p.green() < 150;
    }
  EXPECT_GT(red, 10);
  EXPECT_GT(blue, 10);
  // No flags, no legend.
  timeline->set_flags({});
  EXPECT_TRUE(timeline->flag_legend().isEmpty());
  EXPECT_FALSE(legend->isVisible());
}

TEST_F(MainWindowTest, ResidualArrowsKeepOneScaleBeforeAndAfterOptimisation) {
  OptimizeSettings s;
  s.set("max_iterations", 12);
  s.set("samples", 31);
  QString error;
  ASSERT_TRUE(window_->runs().start(s, &error)) << error.toStdString();
  ASSERT_TRUE(window_->runs().wait(300000));
  ASSERT_EQ(window_->workspace().runs().size(), 1);
  window_->runs().show_run(0);
  ASSERT_TRUE(window_->document().has_optimization());
  const Document& d = window_->document();
  BodyScene& scene = window_->view().scene()->scene();
  const double t = 0.5 * d.duration();

  window_->set_stage(Stage::kBefore);
  window_->seek(t);
  const double before_length = scene.residual_force_arrow_length();
  const double before_scale = scene.residual_force_full_scale();
  const double before_force = d.sample_at(Stage::kBefore, t).residual.head<3>().norm();
  const QImage before_view = window_->grab_view();
  window_->set_stage(Stage::kAfter);
  window_->seek(t);
  const double after_length = scene.residual_force_arrow_length();
  const double after_force = d.sample_at(Stage::kAfter, t).residual.head<3>().norm();
  const QImage after_view = window_->grab_view();
  QDir().mkpath(SALTUS_GUI_CANDIDATE_DIR);
  before_view.save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/arrows_before.png");
  after_view.save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/arrows_after.png");

  // One scale for the run: the same full scale, lengths in proportion to the forces (the
  // forces from the document's own samples, the lengths read off the drawn arrows).
  EXPECT_DOUBLE_EQ(scene.residual_force_full_scale(), before_scale);
  ASSERT_GT(before_length, 0.0);
  ASSERT_LT(before_length, 1.2) << "capped: the proportion below would not hold";
  EXPECT_NEAR(before_length / 0.6, before_force / before_scale, 1e-9);
  EXPECT_NEAR(after_length / 0.6, after_force / before_scale, 1e-9);
  // What remains after optimisation looks small beside what was there before.
  ASSERT_LT(after_force, 0.1 * before_force) << "the run did not reduce the residual enough";
  EXPECT_LT(after_length, 0.1 * before_length);
  std::string legend = scene.legend();
  std::replace(legend.begin(), legend.end(), '\n', ' ');  // wrapped to the view's width
  EXPECT_NE(legend.find("one scale before and after optimisation"), std::string::npos) << legend;
}

TEST_F(MainWindowTest, DrawsTheBodyWithLeftAndRightColours) {
  window_->seek(kShownTime);
  const QImage view = window_->grab_view();
  ASSERT_FALSE(view.isNull());
  EXPECT_GT(view.width(), 400);
  EXPECT_GT(view.height(), 200);
  const test::BlankCheck check = test::blank_check(view);
  EXPECT_GT(check.distinct_colours, 30);
  EXPECT_GT(check.non_background, 0.05);
  // Left limbs blue, right limbs orange (BodyScene's colours, lit: allow a range).
  EXPECT_GT(test::colour_fraction(view, QColor(64, 120, 224)), 0.0002);
  EXPECT_GT(test::colour_fraction(view, QColor(237, 115, 46)), 0.0002);
  EXPECT_DOUBLE_EQ(window_->time(), kShownTime);
  EXPECT_EQ(window_->stage(), Stage::kBefore);
}

TEST_F(MainWindowTest, OptimisesInTheBackgroundAndMatchesTheBaseline) {
  // The event loop must keep running during the optimisation: count the ticks of a 10 ms
  // timer that arrive while it runs; a blocked GUI thread would deliver none.
  int ticks = 0;
  QTimer timer;
  QObject::connect(&timer, &QTimer::timeout, [&] { ticks += window_->runs().running(); });
  timer.start(10);
  QElapsedTimer clock;
  clock.start();
  QString error;
  ASSERT_TRUE(window_->runs().start(few_iterations(), &error)) << error.toStdString();
  EXPECT_TRUE(window_->runs().running());
  EXPECT_FALSE(window_->runs().start(few_iterations(), &error));  // one at a time
  ASSERT_TRUE(window_->runs().wait(300000));
  const qint64 elapsed_ms = clock.elapsed();
  timer.stop();
  // Software OpenGL makes every repaint slow (the progress display repaints the window), so
  // only ask for the loop to have turned a few times; a blocked GUI thread turns it not at all.
  if (elapsed_ms > 150) {
    EXPECT_GE(ticks, 2) << "the GUI thread was blocked while optimising (" << elapsed_ms << " ms)";
  }

  ASSERT_TRUE(window_->document().has_optimization());
  const OptimizationResult& r = window_->document().optimization();
  EXPECT_LE(r.solve.iterations, 3);
  EXPECT_LT(r.after.metrics.avg_root_force, r.before.metrics.avg_root_force);
  EXPECT_EQ(window_->stage(), Stage::kAfter);

  window_->seek(kShownTime);
  window_->fix_view_size(QSize(kViewWidth, kViewHeight));
  const QImage view = window_->grab_view();
  ASSERT_EQ(view.size(), QSize(kViewWidth, kViewHeight));
  const test::Comparison c = test::compare_with_baseline(view, baseline_name("view_after"));
  EXPECT_TRUE(c.ok) << c.message;

  // The "before" stage is still there to compare with.
  window_->set_stage(Stage::kBefore);
  EXPECT_EQ(window_->stage(), Stage::kBefore);
}

TEST_F(MainWindowTest, CancelStopsTheOptimisationAtTheNextIteration) {
  OptimizeSettings many = few_iterations();
  many.set("max_iterations", 500);
  // Cancel from the run's own per-iteration progress report, once the solver has made its first
  // iteration: a cancel that did nothing would let the run go on to "solved" or its 500
  // iterations, and fail here.
  auto* runner = window_->runs().findChild<OptimizationRunner*>();
  ASSERT_NE(runner, nullptr);
  int cancelled_at = -1;
  QObject::connect(runner, &OptimizationRunner::progress, window_.get(),
                   [this, &cancelled_at](const ProgressInfo& info) {
                     if (cancelled_at >= 0 || info.iteration < 1) return;
                     cancelled_at = info.iteration;
                     window_->runs().cancel();
                   });
  ASSERT_TRUE(window_->runs().start(many));
  ASSERT_TRUE(window_->runs().wait(60000));
  ASSERT_GE(cancelled_at, 1) << "the run reported no iteration";
  // The run is kept in the list, with the iterate it reached, and says it was cancelled.
  const RunList& runs = window_->workspace().runs();
  ASSERT_EQ(runs.size(), 1);
  ASSERT_TRUE(runs.showable(0));
  const SolveReport& solve = runs.at(0).result->solve;
  EXPECT_EQ(solve.status, "cancelled");
  // Stopped within a few iterations of the cancel (the progress reports reach the window a
  // little after the solver made them), far below the maximum.
  EXPECT_LT(solve.iterations, cancelled_at + 20) << "cancelled at iteration " << cancelled_at;
}

TEST_F(MainWindowTest, BadMotionShowsTheLibrarysMessageAndKeepsTheOpenMotion) {
  saltus::test::TempDir dir;
  const std::string bad = dir / "bad.motion.json";
  saltus::test::write_text(
      bad,
      "{\"format\": \"saltus-motion/1\", \"model\": \"zatsiorsky-66kg\", "
      "\"takeoff\": {\"com_position\": [0, 1, 0], \"com_velocity\": [0, 10, 0]}, "
      "\"keyframes\": [{\"time\": \"soon\", \"rotations\": {}}, {\"time\": 1.0, "
      "\"rotations\": {}}]}");
  QString error;
  EXPECT_FALSE(window_->open_motion(QString::fromStdString(bad), &error));
  EXPECT_TRUE(error.contains("bad.motion.json")) << error.toStdString();
  EXPECT_TRUE(error.contains("/keyframes/0")) << error.toStdString();
  EXPECT_TRUE(window_->document().loaded());
  EXPECT_EQ(QFileInfo(QString::fromStdString(window_->document().file().path)).fileName(),
            QFileInfo(motion_path()).fileName());
}

TEST_F(MainWindowTest, SavesTheResultAndExportsPictures) {
  saltus::test::TempDir dir;
  QString error;
  ASSERT_TRUE(window_->files().save_result(QString::fromStdString(dir / "result"), &error))
      << error.toStdString();
  for (const char* file : {"result.json", "trajectory.csv", "model.json"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "result" / file)) << file;

  QStringList written;
  ASSERT_TRUE(
      window_->plots().export_figures(QString::fromStdString(dir / "plots"), &written, &error))
      << error.toStdString();
  EXPECT_EQ(written.size(), 5);  // root force, root moment, joint force, joint moment, rotation
  for (const QString& name : written) {
    const QImage plot(QString::fromStdString(dir / "plots") + "/" + name);
    ASSERT_FALSE(plot.isNull()) << name.toStdString();
    EXPECT_EQ(plot.width(), 1400);
    EXPECT_GT(test::blank_check(plot).distinct_colours, 8) << name.toStdString();
  }

  ASSERT_TRUE(
      window_->files().export_window_png(QString::fromStdString(dir / "window.png"), &error));
  const QImage window_png(QString::fromStdString(dir / "window.png"));
  EXPECT_EQ(window_png.width(), kWidth);
  EXPECT_EQ(window_png.height(), kHeight);
  EXPECT_GT(test::blank_check(window_png).distinct_colours, 30);
}

TEST_F(MainWindowTest, KeysStepPlayAndJump) {
  const int frames = window_->document().frame_count(window_->stage());
  const double dt = window_->document().duration() / (frames - 1);
  window_->seek(50 * dt);
  // Right / Left arrow: one frame of the sample grid forward / back.
  QTest::keyClick(window_.get(), Qt::Key_Right);
  EXPECT_NEAR(window_->time(), 51 * dt, 1e-9);
  QTest::keyClick(window_.get(), Qt::Key_Left);
  QTest::keyClick(window_.get(), Qt::Key_Left);
  EXPECT_NEAR(window_->time(), 49 * dt, 1e-9);
  // Space plays: time moves on while the event loop runs; Space again pauses.
  QTest::keyClick(window_.get(), Qt::Key_Space);
  QTest::qWait(300);
  QTest::keyClick(window_.get(), Qt::Key_Space);
  const double paused_at = window_->time();
  EXPECT_NE(paused_at, 49 * dt);
  QTest::qWait(100);
  EXPECT_DOUBLE_EQ(window_->time(), paused_at);
  QTest::keyClick(window_.get(), Qt::Key_Home);
  EXPECT_DOUBLE_EQ(window_->time(), 0.0);
  QTest::keyClick(window_.get(), Qt::Key_End);
  EXPECT_DOUBLE_EQ(window_->time(), window_->document().duration());
}

TEST_F(MainWindowTest, DisplayOptionsChangeThePicture) {
  window_->seek(kShownTime);
  const QImage plain = window_->grab_view();
  SceneOptions options;
  options.joint_arrows = true;
  window_->set_scene_options(options);
  const QImage with_joints = window_->grab_view();
  EXPECT_NE(plain, with_joints);
  QDir().mkpath(SALTUS_GUI_CANDIDATE_DIR);
  with_joints.save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/view_joint_arrows.png");
  for (CameraPreset preset : {CameraPreset::kSide, CameraPreset::kFront, CameraPreset::kTop}) {
    window_->set_camera(preset);
    const QImage view = window_->grab_view();
    EXPECT_NE(view, with_joints);
    EXPECT_GT(test::blank_check(view).distinct_colours, 20);
    view.save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/view_" +
              QString::fromStdString(camera_preset_name(preset)) + ".png");
  }
  options = SceneOptions{};
  options.ghosts = options.apparatus = options.floor_grid = options.parabola = false;
  window_->set_scene_options(options);
  EXPECT_NE(window_->grab_view(), plain);
}

TEST_F(MainWindowTest, PlotTabsShowJointLoadsAndRotation) {
  QTabWidget* tabs = &window_->plots();
  ASSERT_NE(tabs, nullptr);
  ASSERT_EQ(tabs->count(), 4);  // root, joint loads, strength, why it spins
  window_->seek(1.0);
  // Every tab and every rotation quantity draws something; the pictures are left next to the
  // build for a person to look at.
  QDir().mkpath(SALTUS_GUI_CANDIDATE_DIR);
  for (int tab = 0; tab < tabs->count(); ++tab) {
    tabs->setCurrentIndex(tab);
    QApplication::processEvents();
    auto* combo = tabs->currentWidget()->findChild<QComboBox*>();
    const int variants = combo ? combo->count() : 1;
    for (int v = 0; v < variants; ++v) {
      if (combo) combo->setCurrentIndex(v);
      QApplication::processEvents();
      const QImage picture = tabs->currentWidget()->grab().toImage();
      EXPECT_GT(test::blank_check(picture).distinct_colours, 8) << tab << "/" << v;
      picture.save(QString(SALTUS_GUI_CANDIDATE_DIR) + QString("/tab%1_%2.png").arg(tab).arg(v));
    }
  }
}

TEST_F(MainWindowTest, StrengthTabDrawsEachJointsShareAndAClickGoesToThatJointAndTime) {
  PlotsPanel& plots = window_->plots();
  StrengthStrips* strips = plots.strength();
  ASSERT_NE(strips, nullptr);
  plots.setCurrentWidget(strips);
  QApplication::processEvents();
  // A strip per joint with a strength curve: the library's shares of the motion shown.
  const Document& d = window_->document();
  const Stage stage = d.available(window_->stage());
  const std::vector<StrengthStrip> expected =
      strength_strips(d.file().model, d.plot_samples(stage), d.evaluation(stage).check);
  ASSERT_FALSE(expected.empty());
  ASSERT_EQ(strips->strips().size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(strips->strips()[i].segment, expected[i].segment);
    EXPECT_EQ(strips->strips()[i].shares, expected[i].shares);
  }
  // Each strip is drawn in the colour of its share: at the sample of its largest share, the
  // pixel in the middle of its row is that share's colour (red above 100 %).
  const QImage picture = strips->grab().toImage();
  const double duration = expected.front().times.back();
  for (const StrengthStrip& strip : strips->strips()) {
    SCOPED_TRACE(strip.joint);
    const QRect row = strips->row_rect(strip.segment);
    ASSERT_GT(row.height(), 2);
    const std::size_t top =
        std::max_element(strip.shares.begin(), strip.shares.end()) - strip.shares.begin();
    if (top + 1 >= strip.times.size()) continue;
    // The middle of the segment from that sample to the next, drawn with the larger share.
    const double t = 0.5 * (strip.times[top] + strip.times[top + 1]);
    const int x = row.left() + static_cast<int>(row.width() * t / duration);
    const Rgb want = strength_share_colour(std::max(strip.shares[top], strip.shares[top + 1]));
    // Samples may be closer than a pixel: the colour is within two pixels of there.
    bool found = false;
    for (int dx = -2; dx <= 2 && !found; ++dx) {
      const QColor got = picture.pixelColor(x + dx, row.center().y());
      found = std::abs(got.redF() - want.r) < 0.02 && std::abs(got.greenF() - want.g) < 0.02 &&
              std::abs(got.blueF() - want.b) < 0.02;
    }
    EXPECT_TRUE(found) << "share " << strip.shares[top] << " at x " << x;
  }
  // A click in the last strip at 40 % of the flight: that time, that joint, still this tab.
  const StrengthStrip& last = strips->strips().back();
  const QRect row = strips->row_rect(last.segment);
  QTest::mouseClick(strips, Qt::LeftButton, {},
                    QPoint(row.left() + static_cast<int>(0.4 * row.width()), row.center().y()));
  EXPECT_NEAR(window_->time(), 0.4 * duration, 2.0 * duration / row.width());
  EXPECT_EQ(plots.selected_joint(), last.segment);
  EXPECT_EQ(plots.currentWidget(), strips);
  // Its largest share in words under the strips.
  EXPECT_EQ(strips->chosen_words().toLower(), QString::fromStdString(last.peak_words).toLower());
  // A click on the first joint's name opens its loads.
  const StrengthStrip& first = strips->strips().front();
  QTest::mouseClick(strips, Qt::LeftButton, {},
                    QPoint(5, strips->row_rect(first.segment).center().y()));
  EXPECT_EQ(plots.selected_joint(), first.segment);
  EXPECT_NE(plots.currentWidget(), strips);
  EXPECT_NE(plots.joint_summary().indexOf("share of the athlete's strength"), -1)
      << plots.joint_summary().toStdString();
}

TEST_F(MainWindowTest, DroppedMotionFileOpensAndAModelFileIsUsed) {
  // Drop the bundled model: it becomes the model of this and later motions.
  const QString model = QString(SALTUS_EXAMPLES_DIR) + "/../resources/models/zatsiorsky-66kg.json";
  QMimeData model_data;
  model_data.setUrls({QUrl::fromLocalFile(QFileInfo(model).absoluteFilePath())});
  drop(&model_data);
  EXPECT_EQ(window_->document().model_override(),
            QFileInfo(model).absoluteFilePath().toStdString());

  // Drop a motion: it opens.
  saltus::test::TempDir dir;
  const std::string copy = dir / "dropped.motion.json";
  std::filesystem::copy_file(test::gui_test_motion_path(), copy);
  QMimeData motion_data;
  motion_data.setUrls({QUrl::fromLocalFile(QString::fromStdString(copy))});
  drop(&motion_data);
  EXPECT_EQ(QFileInfo(QString::fromStdString(window_->document().file().path)).fileName(),
            "dropped.motion.json");
  EXPECT_EQ(window_->document().model_override(),
            QFileInfo(model).absoluteFilePath().toStdString());
}

}  // namespace
}  // namespace saltus::gui
