// saltus-gui: the desktop app (gui/README.md). Parses the command line, then either runs the
// batch jobs (screenshots, figures, benchmark) or opens the main window.

#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QSurfaceFormat>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/batch.h"
#include "app/main_window.h"
#include "app/run_controller.h"
#include "core/command_line.h"
#include "saltus/optim/solver_memory.h"

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

/// Whether Qt's default platform (X11, or Wayland) has a display to connect to. Another
/// platform chosen in QT_QPA_PLATFORM (offscreen, vnc, ...) is left to Qt.
bool display_configured() {
  const char* platform = std::getenv("QT_QPA_PLATFORM");
  if (platform && *platform && std::strncmp(platform, "xcb", 3) != 0 &&
      std::strncmp(platform, "wayland", 7) != 0)
    return true;
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

  if (!display_configured()) {
    print_no_display_advice("no display is set (DISPLAY is empty)");
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
