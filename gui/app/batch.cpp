#include "app/batch.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QLoggingCategory>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "app/compare_controller.h"
#include "app/compare_window.h"
#include "app/file_controller.h"
#include "app/main_window.h"
#include "app/plots_panel.h"
#include "app/run_controller.h"
#include "app/strength_strips.h"
#include "app/teaching_panel.h"
#include "app/twist_panel.h"
#include "core/figures.h"
#include "core/result_folder.h"
#include "saltus/base/input_error.h"
#include "saltus/evaluation/joint_loads.h"
#include "scene/chart_view.h"

namespace saltus::gui {

namespace {

constexpr int kExitFailure = 1;
constexpr int kExitBadInput = 2;
constexpr int kFigureWidth = 1200;
constexpr int kFigureHeight = 600;
constexpr int kPanelWidth = 900;  ///< one chart of a grid figure (mass study loads)
constexpr int kPanelHeight = 480;
constexpr int kOptimizationTimeoutMs = 6 * 60 * 60 * 1000;

int export_figures(const CommandLine& c) {
  std::vector<ResultFolder> folders;
  std::vector<MassStudyFolder> mass_folders;
  std::vector<TwistFolder> twist_folders;
  try {
    for (const std::string& dir : c.result_dirs) {
      if (is_mass_study_folder(dir))
        mass_folders.push_back(read_mass_study_folder(dir));
      else if (is_twist_analysis_folder(dir))
        twist_folders.push_back(read_twist_analysis_folder(dir));
      else
        folders.push_back(read_optimization_folder(dir));
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "saltus-gui: error: %s\n", e.what());
    return kExitBadInput;
  }
  try {
    std::filesystem::create_directories(c.export_figures);
    for (const Figure& figure : result_figures(folders)) {
      const std::string path =
          (std::filesystem::path(c.export_figures) / figure.file_name).string();
      write_chart_png(figure.chart, path, kFigureWidth, kFigureHeight, 15);
      std::printf("wrote %s\n", path.c_str());
    }
    for (const FigureGrid& figure : mass_study_load_figures(mass_folders)) {
      const std::string path =
          (std::filesystem::path(c.export_figures) / figure.file_name).string();
      write_chart_grid_png(figure.panels, figure.columns, path, kPanelWidth, kPanelHeight, 14);
      std::printf("wrote %s\n", path.c_str());
    }
    for (const Figure& figure : twist_figures(twist_folders)) {
      const std::string path =
          (std::filesystem::path(c.export_figures) / figure.file_name).string();
      write_chart_png(figure.chart, path, kFigureWidth, kFigureHeight, 15);
      std::printf("wrote %s\n", path.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "saltus-gui: error: %s\n", e.what());
    return kExitFailure;
  }
  return 0;
}

int show_motion(const CommandLine& c) {
  MainWindow window(false);
  // Laid out and rendered like a shown window, but never mapped on a screen; except for the
  // benchmark, which must measure frames really drawn into a window (under Xvfb, a virtual one).
  // Grabbing an unmapped window makes Qt's xcb plugin log a harmless X error (BadGC): the
  // picture is complete, so that warning is silenced here.
  if (!c.benchmark) {
    window.setAttribute(Qt::WA_DontShowOnScreen);
    QLoggingCategory::setFilterRules("qt.qpa.xcb.warning=false");
  }
  window.resize(c.width, c.height);
  window.show();
  QApplication::processEvents();

  QString error;
  if (!window.open_motion(QString::fromStdString(c.motion), &error)) {
    std::fprintf(stderr, "saltus-gui: error: %s\n", qPrintable(error));
    return kExitBadInput;
  }
  if (c.camera) window.set_camera(*c.camera);
  if (c.optimize) {
    // Library defaults, not the panel's remembered values: batch runs are reproducible.
    if (!window.runs().start(c.applied_to(OptimizeSettings{}), &error)) {
      std::fprintf(stderr, "saltus-gui: error: %s\n", qPrintable(error));
      return kExitBadInput;
    }
    window.runs().wait(kOptimizationTimeoutMs);
    const RunList& runs = window.workspace().runs();
    if (runs.empty() || !runs.showable(runs.size() - 1)) {
      std::fprintf(stderr, "saltus-gui: error: the optimisation failed%s%s\n",
                   runs.empty() ? "" : ": ", runs.empty() ? "" : runs.at(0).error.c_str());
      return kExitFailure;
    }
    // The one run batch mode asked for is shown whatever its status (interactively a run that
    // did not solve is shown only when nothing better exists).
    window.runs().show_run(runs.size() - 1);
    const OptimizationResult& r = window.document().optimization();
    std::printf("optimised: %s after %d iterations, average root force %.4g N -> %.4g N\n",
                r.solve.status.c_str(), r.solve.iterations, r.before.metrics.avg_root_force,
                r.after.metrics.avg_root_force);
  }
  if (c.stage) window.set_stage(*c.stage);
  if (c.time) window.seek(*c.time);
  QApplication::processEvents();
  if (c.panel == "twist") {
    window.show_twist_panel();
    // The analysis runs off the GUI thread: the picture shows its result, not "working".
    QElapsedTimer waited;
    waited.start();
    while (window.twist().busy() && waited.elapsed() < 120000)
      QApplication::processEvents(QEventLoop::AllEvents, 20);
    QApplication::processEvents();
  } else if (c.panel == "teaching") {
    window.plots().setCurrentWidget(window.plots().teaching());
    QApplication::processEvents();
  } else if (c.panel == "joints") {
    // The joint the run shown raised most, else the plots' own choice.
    int joint = window.plots().selected_joint();
    const Document& d = window.document();
    if (d.has_optimization()) {
      const JointLoadRise rise = largest_joint_load_rise(
          d.file().model, d.optimization().before.check, d.optimization().after.check);
      if (!rise.joint.empty()) joint = d.file().model.joint_index(rise.joint);
    }
    window.plots().show_joint(joint);
    QApplication::processEvents();
  } else if (c.panel == "strength") {
    window.plots().setCurrentWidget(window.plots().strength());
    QApplication::processEvents();
  } else if (c.panel == "model") {
    window.show_model_panel();
    QApplication::processEvents();
  }

  if (!c.save_result.empty()) {
    if (!window.files().save_result(QString::fromStdString(c.save_result), &error)) {
      std::fprintf(stderr, "saltus-gui: error: %s\n", qPrintable(error));
      return kExitBadInput;
    }
    std::printf("wrote %s\n", c.save_result.c_str());
  }
  if (!c.lecture_figure.empty()) {
    if (!window.files().export_lecture_figure(QString::fromStdString(c.lecture_figure),
                                              c.lecture_poses, &error)) {
      std::fprintf(stderr, "saltus-gui: error: %s\n", qPrintable(error));
      return kExitFailure;
    }
    std::printf("wrote %s\n", c.lecture_figure.c_str());
  }
  if (!c.screenshot_view.empty()) {
    if (!window.files().export_view_png(QString::fromStdString(c.screenshot_view), &error)) {
      std::fprintf(stderr, "saltus-gui: error: %s\n", qPrintable(error));
      return kExitFailure;
    }
    std::printf("wrote %s\n", c.screenshot_view.c_str());
  }
  if (!c.compare.empty()) {
    const int status =
        write_compare_screenshot(window, QString::fromStdString(c.compare), window.time(),
                                 QSize(c.width, c.height), QString::fromStdString(c.screenshot));
    if (status != 0) return status;
  } else if (!c.screenshot.empty()) {
    if (!window.files().export_window_png(QString::fromStdString(c.screenshot), &error)) {
      std::fprintf(stderr, "saltus-gui: error: %s\n", qPrintable(error));
      return kExitFailure;
    }
    std::printf("wrote %s\n", c.screenshot.c_str());
  }
  if (!c.export_video.empty()) {
    VideoOptions video;
    video.fps = c.video_fps;
    video.speed = c.video_speed;
    const int status = write_video(window, QString::fromStdString(c.export_video), video);
    if (status != 0) return status;
  }
  if (c.benchmark) {
    const double fps = window.benchmark_playback(c.benchmark_seconds);
    std::printf(
        "playback: %.1f frames per second at %dx%d over %.1f s (%d 3D renders, %.1f ms CPU a "
        "frame)\n",
        fps, c.width, c.height, c.benchmark_seconds, window.benchmark_renders(),
        window.benchmark_cpu_ms_per_frame());
  }
  return 0;
}

}  // namespace

int write_compare_screenshot(MainWindow& window, const QString& other, double time,
                             const QSize& size, const QString& png) {
  QString error;
  if (!window.compare().compare_with(other, &error)) {
    std::fprintf(stderr, "saltus-gui: error: %s\n", qPrintable(error));
    return kExitBadInput;
  }
  // A model comparison optimises its second run in the background first.
  window.compare().wait(kOptimizationTimeoutMs);
  CompareWindow* compare = window.compare().window();
  compare->setAttribute(Qt::WA_DontShowOnScreen);
  compare->resize(size);
  compare->show();
  compare->seek(time);
  QApplication::processEvents();
  if (!compare->grab_window().save(png, "PNG")) {
    std::fprintf(stderr, "saltus-gui: error: %s: cannot write the image\n", qPrintable(png));
    return kExitFailure;
  }
  std::printf("wrote %s\n", qPrintable(png));
  return 0;
}

int write_video(MainWindow& window, const QString& path, const VideoOptions& options) {
  QString error;
  VideoPlan plan;
  if (!window.video().export_video(path, options, &error, &plan)) {
    std::fprintf(stderr, "saltus-gui: error: %s\n", qPrintable(error));
    return video_format_for(path.toStdString()) ? kExitFailure : kExitBadInput;
  }
  std::printf("wrote %s (%d frames, %.2f s at %g frames per second)\n", qPrintable(path),
              plan.frames(), plan.video_seconds(), plan.fps);
  return 0;
}

int run_batch(const CommandLine& c) {
  if (!c.export_figures.empty()) {
    const int status = export_figures(c);
    if (status != 0) return status;
  }
  if (!c.motion.empty()) return show_motion(c);
  return 0;
}

}  // namespace saltus::gui
