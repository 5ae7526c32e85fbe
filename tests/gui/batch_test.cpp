// saltus-gui as a program: batch screenshots, paper figures from `saltus optimize` folders,
// bad usage. Runs the built executables (under the same Xvfb display as this test).

#include <gtest/gtest.h>

#include <QImage>
#include <QProcess>
#include <QStandardPaths>
#include <filesystem>
#include <map>

#include "core/video_plan.h"
#include "gui/support/image_checks.h"
#include "gui_core/test_motion.h"
#include "saltus/formats/motion_file.h"
#include "support/cli_runner.h"

namespace saltus::gui {
namespace {

saltus::test::CliRun run_gui(const std::string& arguments) {
  return saltus::test::run_command(std::string(SALTUS_GUI_PATH) + " " + arguments);
}

void expect_sane_png(const std::string& path, int min_width, int min_height) {
  const QImage image(QString::fromStdString(path));
  ASSERT_FALSE(image.isNull()) << path << " missing or not a PNG";
  EXPECT_GE(image.width(), min_width) << path;
  EXPECT_GE(image.height(), min_height) << path;
  EXPECT_GT(std::filesystem::file_size(path), 10000u) << path;
  const test::BlankCheck check = test::blank_check(image);
  EXPECT_GT(check.distinct_colours, 8) << path << " looks blank";
  EXPECT_GT(check.non_background, 0.01) << path << " looks blank";
}

TEST(GuiBatch, OptimisesAndWritesAScreenshotWithoutInteraction) {
  saltus::test::TempDir dir;
  const saltus::test::CliRun run =
      run_gui("'" + test::gui_test_motion_path() +
              "' --optimize --max-iter 2 --samples 31 --time 1.0 --size 1280x800 --screenshot '" +
              (dir / "shot.png") + "' --screenshot-view '" + (dir / "view.png") +
              "' --save-result '" + (dir / "result") + "'");
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("optimised:"), std::string::npos) << run.output;
  const QImage shot(QString::fromStdString(dir / "shot.png"));
  EXPECT_EQ(shot.width(), 1280);
  EXPECT_EQ(shot.height(), 800);
  expect_sane_png(dir / "shot.png", 1280, 800);
  expect_sane_png(dir / "view.png", 400, 200);
  for (const char* file : {"result.json", "trajectory_before.csv", "trajectory_after.csv",
                           "optimized.motion.json", "model.json"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "result" / file)) << file;
}

TEST(GuiBatch, PanelFlagBringsTheTwistTeachingAndStrengthPanelsToTheFront) {
  saltus::test::TempDir dir;
  const std::string m5 = std::string(SALTUS_EXAMPLES_DIR) +
                         "/motions/M5-front-somersault-one-and-a-half-twists.motion.json";
  std::map<std::string, QImage> shots;
  for (const std::string panel : {"", "twist", "teaching", "strength"}) {
    const std::string png = dir / ("shot-" + (panel.empty() ? "none" : panel) + ".png");
    const saltus::test::CliRun run =
        run_gui("'" + m5 + "' --time 1.0 --size 1366x768 " +
                (panel.empty() ? "" : "--panel " + panel + " ") + "--screenshot '" + png + "'");
    ASSERT_EQ(run.status, 0) << run.output;
    expect_sane_png(png, 1366, 768);
    shots[panel] = QImage(QString::fromStdString(png));
  }
  // The twist panel fills the right-hand dock, the teaching view the plots under the 3D view.
  const auto changed = [](const QImage& a, const QImage& b, const QRect& area) {
    int differ = 0;
    for (int y = area.top(); y <= area.bottom(); ++y)
      for (int x = area.left(); x <= area.right(); ++x)
        differ += a.pixel(x, y) != b.pixel(x, y);
    return static_cast<double>(differ) / (area.width() * area.height());
  };
  const QRect dock(1000, 100, 300, 500), plots(0, 560, 900, 200);
  EXPECT_GT(changed(shots[""], shots["twist"], dock), 0.05);
  EXPECT_GT(changed(shots[""], shots["teaching"], plots), 0.05);
  EXPECT_GT(changed(shots[""], shots["strength"], plots), 0.05);
  EXPECT_GT(changed(shots["teaching"], shots["strength"], plots), 0.05);
  EXPECT_EQ(run_gui("'" + m5 + "' --panel nope --screenshot '" + (dir / "x.png") + "'").status, 2);
}

TEST(GuiBatch, CompareFlagWritesTheCompareWindow) {
  saltus::test::TempDir dir;
  const std::string other =
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/M2-tucked-back-somersault.motion.json";
  const saltus::test::CliRun run =
      run_gui("'" + test::gui_test_motion_path() + "' --compare '" + other +
              "' --time 0.5 --size 1200x700 --screenshot '" + (dir / "compare.png") + "'");
  ASSERT_EQ(run.status, 0) << run.output;
  const QImage shot(QString::fromStdString(dir / "compare.png"));
  EXPECT_EQ(shot.width(), 1200);
  EXPECT_EQ(shot.height(), 700);
  expect_sane_png(dir / "compare.png", 1200, 700);
  // Not the main window's picture of the same motion at the same size.
  const saltus::test::CliRun main =
      run_gui("'" + test::gui_test_motion_path() + "' --time 0.5 --size 1200x700 --screenshot '" +
              (dir / "main.png") + "'");
  ASSERT_EQ(main.status, 0) << main.output;
  EXPECT_GT(test::block_difference(shot, QImage(QString::fromStdString(dir / "main.png"))), 0.2);
  // Bad input: a missing second motion, status 2, no picture.
  const saltus::test::CliRun bad =
      run_gui("'" + test::gui_test_motion_path() + "' --compare '" + (dir / "absent.json") +
              "' --screenshot '" + (dir / "bad.png") + "'");
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.png"));
}

TEST(GuiBatch, CompareFlagTakesABodyModelFile) {
  // The README's two athletes: the motion on its own model and on a junior made by the CLI.
  saltus::test::TempDir dir;
  const saltus::test::CliRun made = saltus::test::run_cli(
      "model new --height 1.45 --mass 38 --sex female --name junior --quiet --out '" +
      (dir / "junior.model.json") + "'");
  ASSERT_EQ(made.status, 0) << made.output;
  const saltus::test::CliRun run =
      run_gui("'" + test::gui_test_motion_path() + "' --compare '" + (dir / "junior.model.json") +
              "' --time 0 --size 1200x700 --screenshot '" + (dir / "two.png") + "'");
  ASSERT_EQ(run.status, 0) << run.output;
  expect_sane_png(dir / "two.png", 1200, 700);
  // Two athletes drawn, at take-off (arms up, every limb in view): the left limbs' blue in each
  // 3D view (the top half; the plots below have blue lines of their own), less of it for the
  // junior on the views' one scale.
  const QImage shot(QString::fromStdString(dir / "two.png"));
  const int half = shot.width() / 2;
  const int views = shot.height() / 2;
  const QColor blue(64, 120, 224);
  const double adult = test::colour_fraction(shot.copy(0, 0, half, views), blue);
  const double junior = test::colour_fraction(shot.copy(half, 0, half, views), blue);
  EXPECT_GT(adult, 0.001);
  EXPECT_GT(junior, 0.0005);
  EXPECT_LT(junior, 0.9 * adult) << "junior " << junior << ", adult " << adult;
}

TEST(GuiBatch, ExportVideoFlagWritesThePlannedFrames) {
  if (QStandardPaths::findExecutable("ffmpeg").isEmpty() ||
      QStandardPaths::findExecutable("ffprobe").isEmpty())
    GTEST_SKIP() << "ffmpeg is not installed (tools/bootstrap.sh installs it)";
  saltus::test::TempDir dir;
  const std::string gif = dir / "flight.gif";
  const saltus::test::CliRun run = run_gui("'" + test::gui_test_motion_path() +
                                           "' --export-video '" + gif + "' --fps 10 --speed 2");
  ASSERT_EQ(run.status, 0) << run.output;
  const double duration = load_motion_file(test::gui_test_motion_path()).motion.flight_time();
  const VideoPlan plan = plan_video(duration, 10.0, 2.0);
  QProcess p;
  p.start("ffprobe", {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                      "stream=nb_read_frames", "-of", "default=noprint_wrappers=1:nokey=1",
                      QString::fromStdString(gif)});
  p.waitForFinished(60000);
  EXPECT_EQ(QString::fromLocal8Bit(p.readAllStandardOutput()).trimmed().toInt(), plan.frames())
      << run.output;
  const saltus::test::CliRun bad =
      run_gui("'" + test::gui_test_motion_path() + "' --export-video '" + (dir / "v.avi") + "'");
  EXPECT_EQ(bad.status, 2) << bad.output;
}

TEST(GuiBatch, ExportsPaperFiguresFromCliOutputFolders) {
  saltus::test::TempDir dir;
  // Two `saltus optimize` runs, as a user would make them (few iterations: a smoke test).
  for (const char* name : {"relaxed", "fixed-times"}) {
    const std::string extra = std::string(name) == "fixed-times" ? " --no-timing" : "";
    const saltus::test::CliRun cli = saltus::test::run_cli(
        "optimize '" + test::gui_test_motion_path() +
        "' --max-iter 3 --samples 31 --quiet --out '" + (dir / name) + "'" + extra);
    ASSERT_TRUE(cli.status == 0 || cli.status == 3) << cli.output;  // 3: not converged yet
  }
  const saltus::test::CliRun run = run_gui("--export-figures '" + (dir / "figures") + "' '" +
                                           (dir / "relaxed") + "' '" + (dir / "fixed-times") + "'");
  ASSERT_EQ(run.status, 0) << run.output;
  for (const char* file :
       {"relaxed_root_force.png", "relaxed_root_moment.png", "relaxed_keyframe_times.png",
        "relaxed_root_force_components.png", "relaxed_root_moment_components.png",
        "fixed-times_root_force.png", "fixed-times_root_moment.png",
        "fixed-times_keyframe_times.png", "average_root_force.png"})
    expect_sane_png((dir.path() / "figures" / file).string(), 1200, 600);
}

TEST(GuiBatch, ExportsTheMassStudyLoadsFigureNextToOptimizeFigures) {
  saltus::test::TempDir dir;
  // `saltus study mass` as a user runs it (Fig. 8: Table 2 against heavier thighs), few samples
  // and iterations to stay quick, and one `saltus optimize` folder in the same call.
  const saltus::test::CliRun study =
      saltus::test::run_cli("study mass '" + test::gui_test_motion_path() +
                            "' --samples 41 --max-iter 3 --out '" + (dir / "mass-M1") + "'");
  ASSERT_TRUE(study.status == 0 || study.status == 3) << study.output;
  const saltus::test::CliRun optimize = saltus::test::run_cli(
      "optimize '" + test::gui_test_motion_path() + "' --max-iter 2 --samples 31 --quiet --out '" +
      (dir / "relaxed") + "'");
  ASSERT_TRUE(optimize.status == 0 || optimize.status == 3) << optimize.output;
  const saltus::test::CliRun run = run_gui("--export-figures '" + (dir / "figures") + "' '" +
                                           (dir / "mass-M1") + "' '" + (dir / "relaxed") + "'");
  ASSERT_EQ(run.status, 0) << run.output;
  // Two load segments by default: a 2 × 2 grid of 900 × 480 panels.
  expect_sane_png((dir.path() / "figures" / "mass-M1_loads.png").string(), 1800, 960);
  for (const char* file :
       {"relaxed_root_force.png", "relaxed_root_moment.png", "average_root_force.png"})
    expect_sane_png((dir.path() / "figures" / file).string(), 1200, 600);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "figures" / "mass-M1_root_force.png"));
}

TEST(GuiBatch, ExportsTheTwistFigureOfAnAnalyseTwistFolder) {
  saltus::test::TempDir dir;
  const saltus::test::CliRun twist = saltus::test::run_cli(
      "analyse twist '" + std::string(SALTUS_EXAMPLES_DIR) +
      "/motions/full-twisting-back-somersault-from-the-arms.motion.json' -q --out '" +
      (dir / "aerial") + "'");
  ASSERT_EQ(twist.status, 0) << twist.output;
  const saltus::test::CliRun run =
      run_gui("--export-figures '" + (dir / "figures") + "' '" + (dir / "aerial") + "'");
  ASSERT_EQ(run.status, 0) << run.output;
  expect_sane_png((dir.path() / "figures" / "aerial_twist.png").string(), 1200, 600);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "figures" / "aerial_root_force.png"));
  // A twist folder without its twist.csv: exit 2 naming the file, no figure.
  std::filesystem::remove(dir.path() / "aerial" / "twist.csv");
  const saltus::test::CliRun broken =
      run_gui("--export-figures '" + (dir / "again") + "' '" + (dir / "aerial") + "'");
  EXPECT_EQ(broken.status, 2) << broken.output;
  EXPECT_NE(broken.output.find("twist.csv"), std::string::npos) << broken.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "again" / "aerial_twist.png"));
}

TEST(GuiBatch, WithoutADisplayItSaysToUseXvfbRunAndDoesNotAbort) {
  // No DISPLAY at all, and a DISPLAY with no X server behind it (Qt would abort, status 134).
  for (const std::string& env : {std::string("env -u DISPLAY -u WAYLAND_DISPLAY "),
                                 std::string("env -u WAYLAND_DISPLAY DISPLAY=:97 ")}) {
    const saltus::test::CliRun run = saltus::test::run_command(env + SALTUS_GUI_PATH + " '" +
                                                               test::gui_test_motion_path() + "'");
    EXPECT_EQ(run.status, 1) << env << run.output;
    EXPECT_NE(run.output.find("xvfb-run -a saltus-gui"), std::string::npos) << run.output;
  }
}

TEST(GuiBatch, UnderTheOffscreenPlatformItRunsWithAnXServerAndAdvisesWithoutOne) {
  // QT_QPA_PLATFORM=offscreen draws Qt's windows without a screen; the 3D view still draws
  // through X. With this test's X server the picture is taken.
  saltus::test::TempDir dir;
  const std::string motion = " '" + test::gui_test_motion_path() + "'";
  const saltus::test::CliRun run = saltus::test::run_command(
      std::string("env QT_QPA_PLATFORM=offscreen ") + SALTUS_GUI_PATH + motion +
      " --time 0.5 --size 1280x800 --screenshot-view '" + (dir / "view.png") + "'");
  EXPECT_EQ(run.status, 0) << run.output;
  expect_sane_png((dir.path() / "view.png").string(), 600, 300);
  // Without one (none set, or none answering): the advice and status 1, never an abort (134),
  // and no picture; the window alike.
  for (const std::string& env :
       {std::string("env -u DISPLAY -u WAYLAND_DISPLAY QT_QPA_PLATFORM=offscreen "),
        std::string("env -u WAYLAND_DISPLAY DISPLAY=:97 QT_QPA_PLATFORM=offscreen ")}) {
    for (const std::string& batch :
         {" --screenshot-view '" + (dir / "none.png") + "'", std::string()}) {
      const saltus::test::CliRun refused =
          saltus::test::run_command(env + SALTUS_GUI_PATH + motion + batch);
      EXPECT_EQ(refused.status, 1) << env << batch << refused.output;
      EXPECT_NE(refused.output.find("QT_QPA_PLATFORM=offscreen"), std::string::npos)
          << refused.output;
      EXPECT_NE(refused.output.find("xvfb-run -a saltus-gui"), std::string::npos) << refused.output;
      EXPECT_FALSE(std::filesystem::exists(dir.path() / "none.png"));
    }
  }
}

TEST(GuiBatch, BadInputAndUsageExitWithStatus2) {
  saltus::test::TempDir dir;
  const saltus::test::CliRun missing =
      run_gui("--export-figures '" + (dir / "f") + "' '" + (dir / "no-such-folder") + "'");
  EXPECT_EQ(missing.status, 2) << missing.output;
  EXPECT_NE(missing.output.find("no-such-folder"), std::string::npos) << missing.output;
  const saltus::test::CliRun usage = run_gui("--frobnicate");
  EXPECT_EQ(usage.status, 2) << usage.output;
  const saltus::test::CliRun bad_motion =
      run_gui("'" + (dir / "absent.motion.json") + "' --screenshot '" + (dir / "s.png") + "'");
  EXPECT_EQ(bad_motion.status, 2) << bad_motion.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "s.png"));
  const saltus::test::CliRun help = run_gui("--help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.output.find("--export-figures"), std::string::npos);
}

}  // namespace
}  // namespace saltus::gui
