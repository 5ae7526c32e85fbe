// saltus-gui: the desktop app (gui/README.md). Parses the command line, then either runs the
// batch jobs (screenshots, figures, benchmark) or opens the main window.

#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QSurfaceFormat>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/batch.h"
#include "app/main_window.h"
#include "core/command_line.h"

int main(int argc, char** argv) {
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

  // VTK's OpenGL needs its surface format set before the QApplication exists (DESIGN §8).
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
      window.start_optimization(command_line.applied_to(window.optimize_settings()));
    }
  }
  return app.exec();
}
