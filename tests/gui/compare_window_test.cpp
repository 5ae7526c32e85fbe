// Compare: the test motion against itself evaluated with heavier thighs (a second model file,
// as a user picks it), both 3D views drawn and the root force and moment overlaid; before vs
// after of an optimisation; closing; bad input; each of the window's buttons pressed with the
// mouse (the cameras, play / pause, the log scale, the timeline's, Close compare).

#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QTest>
#include <QToolBar>
#include <QToolButton>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>
#include "app/batch.h"
#include "app/compare_controller.h"
#include "app/compare_window.h"
#include "app/edit_controller.h"
#include "app/file_controller.h"
#include "app/main_window.h"
#include "app/plots_panel.h"
#include "app/run_controller.h"
#include "app/scene_widget.h"
#include "app/timeline_widget.h"
#include "app/view_controller.h"
#include "gui/support/image_checks.h"
#include "gui/support/open_motion_fixture.h"
#include "gui_core/test_motion.h"

#include "saltus/body/body_model.h"
#include "saltus/formats/model_file.h"
#include "support/cli_runner.h"

namespace saltus::gui {
namespace {

class CompareWindowTest : public test::OpenMotionTest {
 protected:
  /// The open motion's model with both thighs 50 % heavier, written as a model file.
  std::string scaled_model_file() {
    BodyModel scaled = window_->document().file().model;
    for (const char* thigh : {"thigh_l", "thigh_r"})
      scaled = scale_segment_mass(scaled, thigh, 1.5);
    scaled.name = "thighs x1.5";
    const std::string path = dir_ / "thighs-heavy.json";
    std::ofstream(path) << body_model_to_json(scaled).dump(2) << '\n';
    return path;
  }

  /// The compare window with that model beside the open one, shown at 1400×900 at t = 0.8 s;
  /// nullptr (and a failure) when it does not open.
  CompareWindow* open_side_by_side() {
    QString error;
    if (!window_->compare().compare_with_model(QString::fromStdString(scaled_model_file()),
                                               &error)) {
      ADD_FAILURE() << error.toStdString();
      return nullptr;
    }
    CompareWindow* compare = window_->compare().window();
    if (!compare) {
      ADD_FAILURE() << "no compare window";
      return nullptr;
    }
    compare->resize(1400, 900);
    if (!QTest::qWaitForWindowExposed(compare)) {
      ADD_FAILURE() << "the compare window is not shown";
      return nullptr;
    }
    compare->seek(0.8);
    QApplication::processEvents();
    return compare;
  }

  saltus::test::TempDir dir_;
};

void expect_drawn(const QImage& view, const char* name) {
  ASSERT_FALSE(view.isNull()) << name;
  EXPECT_GT(view.width(), 200) << name;
  const test::BlankCheck check = test::blank_check(view);
  EXPECT_GT(check.distinct_colours, 30) << name << " looks blank";
  EXPECT_GT(check.non_background, 0.05) << name << " looks blank";
}

TEST_F(CompareWindowTest, SameMotionWithAScaledModelSideBySide) {
  EXPECT_EQ(window_->compare().window(), nullptr);
  CompareWindow* compare = open_side_by_side();
  ASSERT_NE(compare, nullptr);
  EXPECT_DOUBLE_EQ(compare->time(), 0.8);

  // Both runs are the library's evaluations: the second uses the heavier model.
  EXPECT_EQ(compare->run(1).document->file().model.name, "thighs x1.5");
  EXPECT_GT(compare->run(1).document->file().model.total_mass(),
            compare->run(0).document->file().model.total_mass());

  const QImage first = compare->grab_view(0);
  const QImage second = compare->grab_view(1);
  expect_drawn(first, "first view");
  expect_drawn(second, "second view");

  // |F| of both runs, each named once by its athlete (and the take-off rule that carried the
  // motion over): the first dashed, the second solid, as before and after are in the main window.
  const ChartSpec& force = compare->force_chart();
  ASSERT_EQ(force.lines.size(), 2u);
  EXPECT_EQ(compare->moment_chart().lines.size(), 2u);
  EXPECT_EQ(force.lines[0].label, "zatsiorsky-66kg 1.70 m 65.5 kg");
  EXPECT_EQ(force.lines[1].label.rfind("thighs x1.5 1.70 m ", 0), 0u) << force.lines[1].label;
  EXPECT_NE(force.lines[1].label.find(", same take-off spin"), std::string::npos)
      << force.lines[1].label;
  EXPECT_TRUE(force.lines[0].dashed);
  EXPECT_FALSE(force.lines[1].dashed);
  EXPECT_NE(force.lines[0].y, force.lines[1].y);  // heavier thighs change the root force
  // The loads at a joint, for both runs: the right hip carries the heavier thigh.
  compare->show_joint(window_->document().file().model.joint_index("hip_r"));
  ASSERT_EQ(compare->joint_force_chart().lines.size(), 2u);
  EXPECT_NE(compare->joint_force_chart().title.find("right hip"), std::string::npos)
      << compare->joint_force_chart().title;
  EXPECT_NE(compare->joint_force_chart().lines[0].y, compare->joint_force_chart().lines[1].y);
  // One arrow scale for both views: the larger run's.
  const GlyphTypicals shared = compare->shared_glyph_typicals();
  for (int i = 0; i < 2; ++i) {
    const GlyphTypicals own = compare->run(i).document->glyph_typicals(compare->run(i).stage);
    EXPECT_GE(shared.residual_force, own.residual_force);
  }

  QDir().mkpath(SALTUS_GUI_CANDIDATE_DIR);
  compare->grab().toImage().save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/compare_window.png");

  window_->compare().close();
  EXPECT_EQ(window_->compare().window(), nullptr);
}

/// The button of `parent` showing `text` (mnemonics left out), enabled, clicked with the mouse.
template <class Button>
void click(QWidget* parent, const QString& text) {
  for (Button* b : parent->findChildren<Button*>()) {
    if (b->text().remove('&') == text) {
      ASSERT_TRUE(b->isEnabled()) << text.toStdString();
      // On a check box's square: a wide box takes no click beside its label.
      const QPoint at =
          qobject_cast<QCheckBox*>(b) ? QPoint(8, b->height() / 2) : b->rect().center();
      QTest::mouseClick(b, Qt::LeftButton, Qt::NoModifier, at);
      QApplication::processEvents();
      return;
    }
  }
  FAIL() << "no button " << text.toStdString();
}

TEST_F(CompareWindowTest, EachButtonOfTheWindowActsOnBothRuns) {
  CompareWindow* compare = open_side_by_side();
  ASSERT_NE(compare, nullptr);
  auto* bar = compare->findChild<QToolBar*>("compare_toolbar");
  ASSERT_NE(bar, nullptr);
  const QList<SceneWidget*> scenes = compare->findChildren<SceneWidget*>();
  ASSERT_EQ(scenes.size(), 2);

  // Each camera button sets both views' camera, and the views show it.
  QImage side;
  for (CameraPreset preset : camera_presets()) {
    const QString label = QString::fromStdString(camera_preset_label(preset));
    SCOPED_TRACE(label.toStdString());
    click<QToolButton>(bar, label);
    for (SceneWidget* s : scenes)
      EXPECT_EQ(s->scene().camera(), preset);
    if (preset == CameraPreset::kSide) side = compare->grab_view(0);
    if (preset == CameraPreset::kTop) {
      EXPECT_GT(test::block_difference(compare->grab_view(0), side), 0.02);
    }
  }

  // Play / pause in the toolbar and the timeline's own buttons drive the one timeline.
  auto* timeline = compare->findChild<TimelineWidget*>();
  ASSERT_NE(timeline, nullptr);
  click<QToolButton>(bar, "Play / pause");
  EXPECT_TRUE(timeline->playing());
  click<QToolButton>(bar, "Play / pause");
  EXPECT_FALSE(timeline->playing());
  compare->seek(0.0);
  click<QToolButton>(timeline, "Step forward");
  const double stepped = compare->time();
  EXPECT_GT(stepped, 0.0);
  click<QToolButton>(timeline, "Step back");
  EXPECT_DOUBLE_EQ(compare->time(), 0.0);
  click<QToolButton>(timeline, "Play");
  EXPECT_TRUE(timeline->playing());
  timeline->pause();
  const bool loop = timeline->timeline().loop();
  click<QCheckBox>(timeline, "Loop");
  EXPECT_EQ(timeline->timeline().loop(), !loop);

  // Log scale: |F| and |M| of both runs on a logarithmic axis, and back.
  EXPECT_FALSE(compare->force_chart().log_y);
  click<QCheckBox>(bar, "Log scale");
  EXPECT_TRUE(compare->force_chart().log_y);
  EXPECT_TRUE(compare->moment_chart().log_y);
  EXPECT_EQ(compare->force_chart().lines.size(), 2u);
  click<QCheckBox>(bar, "Log scale");
  EXPECT_FALSE(compare->force_chart().log_y);

  // Close compare closes the window and leaves the main window's motion open.
  click<QToolButton>(bar, "Close compare");
  QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
  EXPECT_EQ(window_->compare().window(), nullptr);
  EXPECT_TRUE(window_->workspace().loaded());
}

TEST_F(CompareWindowTest, AnotherModelIsOptimisedLikeTheRunShown) {
  // The paper's Fig. 8 explored: the optimised motion with the given masses against the
  // optimised motion with heavier thighs, the joint loads of both.
  OptimizeSettings s;
  s.set("max_iterations", 4);
  s.set("samples", 31);
  QString error;
  ASSERT_TRUE(window_->runs().start(s, &error)) << error.toStdString();
  ASSERT_TRUE(window_->runs().wait(300000));
  ASSERT_TRUE(window_->runs().show_run(0, &error)) << error.toStdString();
  ASSERT_TRUE(
      window_->compare().compare_with_model(QString::fromStdString(scaled_model_file()), &error))
      << error.toStdString();
  EXPECT_TRUE(window_->compare().optimising());
  ASSERT_TRUE(window_->compare().wait(300000));
  CompareWindow* compare = window_->compare().window();
  ASSERT_NE(compare, nullptr);
  EXPECT_EQ(compare->run(0).stage, Stage::kAfter);
  EXPECT_EQ(compare->run(1).stage, Stage::kAfter);
  ASSERT_TRUE(compare->run(1).document->has_optimization());
  // With the same settings as the run shown.
  EXPECT_EQ(compare->run(1).document->optimization_options().nlp.samples, 31);
  EXPECT_NE(compare->run(1).description.indexOf("optimised"), -1);
  EXPECT_EQ(compare->run(1).document->file().model.name, "thighs x1.5");
  compare->show_joint(window_->document().file().model.joint_index("hip_r"));
  ASSERT_EQ(compare->joint_force_chart().lines.size(), 2u);
  EXPECT_NE(compare->joint_force_chart().lines[0].y, compare->joint_force_chart().lines[1].y);
}

TEST_F(CompareWindowTest, BeforeAndAfterOfAnOptimisation) {
  QString error;
  EXPECT_FALSE(window_->compare().compare_before_after(&error));  // nothing optimised yet
  EXPECT_FALSE(error.isEmpty());
  OptimizeSettings s;
  s.set("max_iterations", 2);
  s.set("samples", 21);
  ASSERT_TRUE(window_->runs().start(s, &error)) << error.toStdString();
  ASSERT_TRUE(window_->runs().wait(300000));
  ASSERT_TRUE(window_->document().has_optimization());
  ASSERT_TRUE(window_->compare().compare_before_after(&error)) << error.toStdString();
  CompareWindow* compare = window_->compare().window();
  ASSERT_NE(compare, nullptr);
  EXPECT_EQ(compare->run(0).stage, Stage::kBefore);
  EXPECT_EQ(compare->run(1).stage, Stage::kAfter);
  ASSERT_EQ(compare->force_chart().lines.size(), 2u);
  // Before dashed, after solid: the main window's style.
  EXPECT_TRUE(compare->force_chart().lines[0].dashed);
  EXPECT_FALSE(compare->force_chart().lines[1].dashed);
  // Closing the compare window leaves the main window as it was.
  compare->close();
  QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
  EXPECT_EQ(window_->compare().window(), nullptr);
  EXPECT_TRUE(window_->document().has_optimization());
}

TEST_F(CompareWindowTest, ResultFolderAndBadInputShowTheLibrarysMessage) {
  // A `saltus optimize` folder, as a user would make it.
  const saltus::test::CliRun cli = saltus::test::run_cli(
      "optimize '" + test::gui_test_motion_path() + "' --max-iter 2 --samples 21 --quiet --out '" +
      (dir_ / "relaxed") + "'");
  ASSERT_TRUE(cli.status == 0 || cli.status == 3) << cli.output;
  QString error;
  ASSERT_TRUE(
      window_->compare().compare_with_folder(QString::fromStdString(dir_ / "relaxed"), &error))
      << error.toStdString();
  ASSERT_NE(window_->compare().window(), nullptr);
  EXPECT_EQ(window_->compare().window()->run(1).label, "relaxed (optimised)");
  // The folder's motion is the optimised one: said so, not "interpolated keyframes".
  EXPECT_NE(window_->compare().window()->run(1).description.indexOf("optimised"), -1);

  EXPECT_FALSE(
      window_->compare().compare_with_folder(QString::fromStdString(dir_ / "absent"), &error));
  EXPECT_NE(error.indexOf("absent"), -1) << error.toStdString();
  const std::string bad = dir_ / "bad.motion.json";
  std::ofstream(bad) << "{\"format\": \"saltus-motion/1\"}\n";
  EXPECT_FALSE(window_->compare().compare_with_motion(QString::fromStdString(bad), &error));
  EXPECT_NE(error.indexOf("bad.motion.json"), -1) << error.toStdString();
  // The window opened before is still there and unchanged.
  ASSERT_NE(window_->compare().window(), nullptr);
  EXPECT_EQ(window_->compare().window()->run(1).label, "relaxed (optimised)");
}

TEST_F(CompareWindowTest, BatchWritesTheCompareWindowAgainstAResultFolder) {
  const saltus::test::CliRun cli = saltus::test::run_cli(
      "optimize '" + test::gui_test_motion_path() + "' --max-iter 3 --samples 21 --quiet --out '" +
      (dir_ / "M1-opt") + "'");
  ASSERT_TRUE(cli.status == 0 || cli.status == 3) << cli.output;
  const QString png = QString::fromStdString(dir_ / "compare.png");
  EXPECT_EQ(write_compare_screenshot(*window_, QString::fromStdString(dir_ / "M1-opt"), 0.8,
                                     QSize(1400, 900), png),
            0);
  const QImage picture(png);
  ASSERT_EQ(picture.size(), QSize(1400, 900));
  EXPECT_GT(test::blank_check(picture).distinct_colours, 30);
  // Bad input: the library's message and status 2.
  EXPECT_EQ(write_compare_screenshot(*window_, QString::fromStdString(dir_ / "absent"), 0.8,
                                     QSize(1400, 900), png),
            2);
}

}  // namespace
}  // namespace saltus::gui
