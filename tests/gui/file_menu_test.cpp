// The File menu's entries, each triggered from the menu bar: its file dialog (answered by the
// test with a path in a temporary folder) picks what to open or where to write, and the effect
// is read back: the motion, capture or body model open, the files written and readable (PNG
// pictures, a web page, a result folder, the motion in each export format), the window closed by
// Quit.

#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QImage>
#include <QStandardPaths>
#include <QTest>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/file_controller.h"
#include "app/main_window.h"
#include "app/run_controller.h"
#include "gui/support/image_checks.h"
#include "gui/support/menu_actions.h"
#include "gui/support/open_motion_fixture.h"
#include "gui_core/test_motion.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/use_cases/captures.h"
#include "saltus/use_cases/motion_exports.h"
#include "support/temp_path.h"

namespace saltus::gui {
namespace {

class FileMenuTest : public test::OpenMotionTest {
 protected:
  QAction* entry(const QString& text) {
    QAction* a = test::menu_action(window_.get(), {"File", text});
    EXPECT_NE(a, nullptr) << text.toStdString();
    if (a) {
      EXPECT_TRUE(a->isEnabled()) << text.toStdString();
    }
    return a;
  }
  /// The entry triggered, its file dialog answered with `path`; returns the dialog's title.
  QString answer(const QString& text, const std::filesystem::path& path) {
    QAction* a = entry(text);
    if (!a) return {};
    const QString title =
        test::trigger_and_answer_file_dialog(a, QString::fromStdString(path.string()));
    QApplication::processEvents();
    return title;
  }
  static std::string read(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  static void expect_picture(const std::filesystem::path& path) {
    const QImage image(QString::fromStdString(path.string()));
    ASSERT_FALSE(image.isNull()) << path;
    EXPECT_GT(test::blank_check(image).distinct_colours, 4) << path;
  }
};

TEST_F(FileMenuTest, OpenMotionOpensTheChosenFile) {
  const std::filesystem::path other = std::filesystem::path(SALTUS_EXAMPLES_DIR) / "motions" /
                                      "M2-tucked-back-somersault.motion.json";
  EXPECT_EQ(answer("Open motion…", other), "Open motion");
  EXPECT_EQ(std::filesystem::path(window_->document().file().path).filename(), other.filename());
  // Cancelled: the motion stays.
  EXPECT_EQ(answer("Open motion…", {}), "Open motion");
  EXPECT_EQ(std::filesystem::path(window_->document().file().path).filename(), other.filename());
}

TEST_F(FileMenuTest, OpenRecentReopensAMotionAndClearListEmptiesIt) {
  const std::filesystem::path other = std::filesystem::path(SALTUS_EXAMPLES_DIR) / "motions" /
                                      "M2-tucked-back-somersault.motion.json";
  QString error;
  ASSERT_TRUE(window_->open_motion(QString::fromStdString(other.string()), &error))
      << error.toStdString();
  ASSERT_TRUE(window_->open_motion(QString::fromStdString(test::gui_test_motion_path()), &error))
      << error.toStdString();
  const QString name = QString::fromStdString(other.filename().string());
  QAction* recent = test::menu_action(window_.get(), {"File", "Open recent", name});
  ASSERT_NE(recent, nullptr);
  recent->trigger();
  QApplication::processEvents();
  EXPECT_EQ(std::filesystem::path(window_->document().file().path).filename(), other.filename());

  QAction* clear = test::menu_action(window_.get(), {"File", "Open recent", "Clear list"});
  ASSERT_NE(clear, nullptr);
  clear->trigger();
  QApplication::processEvents();
  EXPECT_EQ(test::menu_action(window_.get(), {"File", "Open recent", name}), nullptr);
  EXPECT_FALSE(test::menu_action(window_.get(), {"File", "Open recent"})->isEnabled());
}

TEST_F(FileMenuTest, ImportMotionCaptureOpensTheCaptureBesideTheMotion) {
  const std::filesystem::path bvh = saltus::test::temp_path("menu-capture.bvh");
  export_motion_bvh(load_motion_file(test::gui_test_motion_path()), bvh.string(), 30.0);
  ASSERT_EQ(window_->document().capture(), nullptr);
  EXPECT_EQ(answer("Import motion capture…", bvh), "Import motion capture");
  EXPECT_NE(window_->document().capture(), nullptr);
}

TEST_F(FileMenuTest, SaveAndOpenBodyModelRoundTripTheMasses) {
  const BodyModel& model = window_->document().file().model;
  const auto thigh = static_cast<std::size_t>(model.segment_index("thigh_r"));
  const double loaded = model.segments[thigh].mass;
  const std::filesystem::path path = saltus::test::temp_path("menu-model.json");
  window_->files().set_save_chooser([&path](const QString&, const QString&, const QString&) {
    return QString::fromStdString(path.string());
  });
  entry("Save body model as…")->trigger();
  ASSERT_TRUE(std::filesystem::exists(path));
  BodyModel heavy = load_body_model(path.string());
  EXPECT_NEAR(heavy.segments[thigh].mass, loaded, 1e-9);

  // A heavier thigh in the file, opened with File > Open model….
  heavy.segments[thigh].mass = 2 * loaded;
  const std::filesystem::path changed = saltus::test::temp_path("menu-heavy-model.json");
  save_body_model_file(changed.string(), heavy);
  EXPECT_EQ(answer("Open model…", changed), "Open body model");
  EXPECT_NEAR(window_->document().file().model.segments[thigh].mass, 2 * loaded, 1e-9);
}

TEST_F(FileMenuTest, SaveMotionWritesTheMotion) {
  const std::filesystem::path path = saltus::test::temp_path("menu.motion.json");
  QString asked;
  window_->files().set_save_chooser(
      [&path, &asked](const QString& title, const QString&, const QString&) {
        asked = title;
        return QString::fromStdString(path.string());
      });
  entry("Save motion as…")->trigger();
  // The dialog says which motion it writes.
  EXPECT_EQ(asked, "Save the keyframes as given");
  ASSERT_TRUE(std::filesystem::exists(path));
  const MotionFile saved = load_motion_file(path.string());
  EXPECT_EQ(saved.motion.keyframes.size(), window_->document().file().motion.keyframes.size());
  EXPECT_EQ(saved.motion.description, window_->document().file().motion.description);
  // Without a run, Save given keyframes would write the same: not offered.
  EXPECT_FALSE(test::menu_action(window_.get(), {"File", "Save given keyframes as…"})->isEnabled());
}

TEST_F(FileMenuTest, AfterARunSaveMotionWritesTheOptimisedMotionAndGivenKeyframesTheKeyframes) {
  OptimizeSettings s;
  s.set("max_iterations", 5);
  s.set("samples", 31);
  ASSERT_TRUE(window_->runs().start(s));
  ASSERT_TRUE(window_->runs().wait(300000));
  ASSERT_TRUE(window_->runs().show_run(0));
  QApplication::processEvents();
  ASSERT_EQ(window_->stage(), Stage::kAfter);
  const OptimizationResult& run = window_->document().optimization();
  const std::filesystem::path optimised = saltus::test::temp_path("menu-optimised.motion.json");
  const std::filesystem::path given = saltus::test::temp_path("menu-given.motion.json");
  std::filesystem::path next = optimised;
  QString asked;
  window_->files().set_save_chooser([&](const QString& title, const QString&, const QString&) {
    asked = title;
    return QString::fromStdString(next.string());
  });
  // The motion on screen: the run's optimised motion, keyframes at their optimised times, the
  // spline the result holds, the description kept; evaluated again it is the run's "after".
  entry("Save optimised motion (run 1) as…")->trigger();
  EXPECT_EQ(asked,
            "Save the optimised motion of run 1 (keyframes at their optimised times, with its "
            "spline)");
  const MotionFile saved = load_motion_file(optimised.string());
  ASSERT_TRUE(saved.motion.spline);
  EXPECT_EQ(saved.motion.description, window_->document().file().motion.description);
  ASSERT_EQ(saved.motion.keyframes.size(), run.optimized_motion.keyframes.size());
  for (std::size_t i = 0; i < saved.motion.keyframes.size(); ++i)
    EXPECT_DOUBLE_EQ(saved.motion.keyframes[i].time, run.after.keyframe_times[i]) << i;
  EvaluateOptions grid;
  grid.samples = 31;
  EXPECT_NEAR(evaluate_motion(saved.motion, saved.model, grid).metrics.avg_root_force,
              run.after.metrics.avg_root_force, 1e-6 * run.after.metrics.avg_root_force + 1e-9);
  // Save given keyframes: the keyframes at their given times, no spline.
  next = given;
  entry("Save given keyframes as…")->trigger();
  EXPECT_EQ(asked, "Save the keyframes as given");
  const MotionFile keyframes = load_motion_file(given.string());
  EXPECT_FALSE(keyframes.motion.spline);
  for (std::size_t i = 0; i < keyframes.motion.keyframes.size(); ++i)
    EXPECT_EQ(keyframes.motion.keyframes[i].time,
              window_->document().file().motion.keyframes[i].time);
}

TEST_F(FileMenuTest, SaveResultFolderWritesWhatTheCommandLineWrites) {
  const std::filesystem::path dir = saltus::test::temp_path("menu-result");
  EXPECT_EQ(answer("Save result folder…", dir), "Save result folder (created or replaced)");
  for (const char* file : {"result.json", "trajectory.csv", "model.json"})
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
}

TEST_F(FileMenuTest, ExportEntriesWriteTheirFiles) {
  const std::filesystem::path view = saltus::test::temp_path("menu-view.png");
  EXPECT_EQ(answer("Export 3D view as PNG…", view), "Export 3D view");
  expect_picture(view);

  const std::filesystem::path shot = saltus::test::temp_path("menu-window.png");
  EXPECT_EQ(answer("Export window screenshot…", shot), "Export window");
  expect_picture(shot);

  const std::filesystem::path page = saltus::test::temp_path("menu-flight.html");
  EXPECT_EQ(answer("Export web page…", page), "Export web page");
  EXPECT_NE(read(page).find("<html"), std::string::npos);

  const std::filesystem::path plots = saltus::test::temp_path("menu-plots");
  std::filesystem::create_directories(plots);
  EXPECT_EQ(answer("Export plots as figures…", plots), "Export plots into folder");
  int pictures = 0;
  for (const auto& f : std::filesystem::directory_iterator(plots)) {
    ASSERT_EQ(f.path().extension(), ".png") << f.path();
    expect_picture(f.path());
    ++pictures;
  }
  EXPECT_EQ(pictures, 5);  // root force, root moment, joint force, joint moment, rotation
}

TEST_F(FileMenuTest, ExportMotionAsWritesEveryFormatOfTheLibrary) {
  int formats = 0;
  for (const ExportFormat& format : export_formats()) {
    if (!format.sampled) continue;
    const QString title = QString::fromStdString(format.title);
    QAction* a = test::menu_action(window_.get(), {"File", "Export motion as", title + "…"});
    ASSERT_NE(a, nullptr) << format.title;
    EXPECT_TRUE(a->isEnabled());
    const std::filesystem::path out =
        saltus::test::temp_path("menu-flight-" + format.name + format.extension);
    EXPECT_EQ(test::trigger_and_answer_file_dialog(a, QString::fromStdString(out.string())),
              "Export motion as " + title);
    QApplication::processEvents();
    // The library's files for the motion shown at the default rate, byte for byte: the app
    // holds no format of its own.
    const MotionFile& shown = window_->document().file();
    const std::vector<ExportFile> expected =
        export_files(shown, format.name, default_export_fps(shown.motion), shown.path);
    if (format.extension.empty()) {
      ASSERT_TRUE(std::filesystem::is_directory(out)) << out;
      for (const ExportFile& f : expected)
        EXPECT_TRUE(read(out / f.name) == f.contents) << format.name << ": " << f.name;
    } else {
      ASSERT_EQ(expected.size(), 1u) << format.name;
      EXPECT_TRUE(read(out) == expected[0].contents) << out;
    }
    ++formats;
  }
  EXPECT_EQ(formats, 4) << "BVH, MuJoCo, glTF, OpenSim";
}

TEST_F(FileMenuTest, ExportAnimationWritesTheVideoWithTheChosenSize) {
  if (QStandardPaths::findExecutable("ffmpeg").isEmpty())
    GTEST_SKIP() << "ffmpeg is not installed (tools/bootstrap.sh installs it)";
  const std::filesystem::path gif = saltus::test::temp_path("menu-animation.gif");
  QString asked;
  const int answered = test::trigger_and_answer_dialogs(
      entry("Export animation (MP4 or GIF)…"),
      {[&](QDialog* d) {
         asked = d->windowTitle();
         auto* files = qobject_cast<QFileDialog*>(d);
         ASSERT_NE(files, nullptr);
         test::type_file_name(files, QString::fromStdString(gif.string()));
         static_cast<QDialog*>(files)->accept();
       },
       [&](QDialog* d) {
         EXPECT_EQ(d->windowTitle(), "Animation");
         auto* size = d->findChild<QComboBox*>();
         ASSERT_NE(size, nullptr);
         size->setCurrentIndex(size->findData(QSize(640, 640)));
         for (QDoubleSpinBox* box : d->findChildren<QDoubleSpinBox*>())
           if (box->suffix().contains("real time")) box->setValue(4.0);  // a short file
         d->accept();
       }});
  EXPECT_EQ(answered, 2);
  EXPECT_EQ(asked, "Export animation");
  const QImage first(QString::fromStdString(gif.string()), "GIF");
  ASSERT_FALSE(first.isNull()) << gif;
  EXPECT_EQ(first.size(), QSize(640, 640));
}

TEST_F(FileMenuTest, QuitClosesTheWindow) {
  ASSERT_TRUE(window_->isVisible());
  entry("Quit")->trigger();
  QApplication::processEvents();
  EXPECT_FALSE(window_->isVisible());
}

}  // namespace
}  // namespace saltus::gui
