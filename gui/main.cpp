// saltus-gui: the desktop app (gui/README.md). Parses the command line, then either runs the
// batch jobs (screenshots, figures, benchmark) or opens the main window.

#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QSurfaceFormat>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/batch.h"
#include "app/main_window.h"
#include "app/run_controller.h"
#include "core/command_line.h"
#include "saltus/optim/solver_memory.h"
#include "x_display.h"

namespace {

constexpr int kExitNoDisplay = 1;

/// What to do without a display, instead of Qt's abort with a core dump.
void print_no_display_advice(const char* why) {
  std::fprintf(stderr,
               "saltus-gui: cannot open a window: %s.\n"
               "On a machine without a screen, run it under a virtual display:\n"
               "  xvfb-run -a saltus-gui [MOTION] [options]\n"
               "(batch options such as --screenshot and --export-figures need one too).\n",
               why);
}

/// The Qt platform chosen in QT_QPA_PLATFORM ("offscreen", "vnc", ...), "" for Qt's default.
std::string qt_platform() {
  const char* platform = std::getenv("QT_QPA_PLATFORM");
  return platform ? std::string(platform) : std::string();
}

/// Whether Qt's own platform is X11 (the default here) or Wayland, which need a display of
/// their own; other platforms (offscreen, vnc, ...) draw Qt's windows without one.
bool qt_platform_needs_display() {
  const std::string platform = qt_platform();
  return platform.empty() || platform.rfind("xcb", 0) == 0 || platform.rfind("wayland", 0) == 0;
}

/// Whether Qt's default platform (X11, or Wayland) has a display to connect to.
bool display_configured() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 && *x11) || (wayland && *wayland);
}

/// Qt ends with qFatal (an abort) when its platform plugin cannot connect, e.g. to a DISPLAY that
/// names no running X server: said in words, with the way out, and a plain exit status.
void on_qt_message(QtMsgType type, const QMessageLogContext&, const QString& message) {
  if (type == QtFatalMsg) {
    if (message.contains("platform plugin", Qt::CaseInsensitive) ||
        message.contains("could not connect to display", Qt::CaseInsensitive)) {
      print_no_display_advice("the display could not be reached");
      std::_Exit(kExitNoDisplay);
    }
    std::fprintf(stderr, "saltus-gui: %s\n", qPrintable(message));
    std::abort();
  }
  std::fprintf(stderr, "%s\n", qPrintable(message));
}

}  // namespace

int main(int argc, char** argv) {
  saltus::keep_solver_memory_in_heap();
  std::vector<std::string> args(argv + 1, argv + argc);
  saltus::gui::CommandLine command_line;
  try {
    command_line = saltus::gui::parse_command_line(args);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "saltus-gui: %s\n", e.what());
    return 2;
  }
  if (command_line.help) {
    std::fputs(saltus::gui::usage_text().c_str(), stdout);
    return 0;
  }
  if (command_line.version) {
    std::puts("saltus-gui 0.1.0");
    return 0;
  }

  if (qt_platform_needs_display() && !display_configured()) {
    print_no_display_advice("no display is set (DISPLAY is empty)");
    return kExitNoDisplay;
  }
  if (!saltus::gui::x_display_reachable()) {
    // Qt might run (offscreen, Wayland), but the first 3D view would abort: say so now.
    const char* x11 = std::getenv("DISPLAY");
    const std::string at = x11 && *x11 ? std::string(" at DISPLAY=") + x11 : " (DISPLAY is empty)";
    const std::string why =
        qt_platform_needs_display()
            ? "no X server answers" + at + ", and the 3D view draws through X"
            : "QT_QPA_PLATFORM=" + qt_platform() +
                  " draws the window without a screen, but the 3D view needs an X display and "
                  "no X server answers" +
                  at;
    print_no_display_advice(why.c_str());
    return kExitNoDisplay;
  }
  qInstallMessageHandler(on_qt_message);
  // VTK's OpenGL needs its surface format set before the QApplication exists
  // (docs/dependencies.md).
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("Saltus");
  QApplication::setApplicationName("saltus-gui");
  QApplication::setApplicationVersion("0.1.0");

  if (command_line.batch()) return saltus::gui::run_batch(command_line);

  saltus::gui::MainWindow window;
  window.show();
  if (!command_line.motion.empty()) {
    window.open_motion(QString::fromStdString(command_line.motion));
    if (command_line.camera) window.set_camera(*command_line.camera);
    if (command_line.stage) window.set_stage(*command_line.stage);
    if (command_line.time) window.seek(*command_line.time);
    if (command_line.optimize && window.document().loaded()) {
      window.runs().start(command_line.applied_to(window.runs().settings()));
    }
  }
  return app.exec();
}
