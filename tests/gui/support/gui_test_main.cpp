// main() of the GUI tests: VTK's surface format must be set before the QApplication exists
// (docs/dependencies.md), and there is one QApplication for all tests of a process.

#include <QVTKOpenGLNativeWidget.h>
#include <gtest/gtest.h>

#include <QApplication>
#include <QSurfaceFormat>

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("Saltus");
  QApplication::setApplicationName("saltus-gui-test");
  return RUN_ALL_TESTS();
}
