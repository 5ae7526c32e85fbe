#pragma once
// The shared start of the GUI tests that drive the main window: a 1280×800 window, shown and
// exposed, with the GUI test motion (gui_core/test_motion.h) open.

#include <gtest/gtest.h>

#include <QApplication>
#include <QString>
#include <QTest>
#include <memory>

#include "app/main_window.h"
#include "gui_core/test_motion.h"

namespace saltus::gui::test {

class OpenMotionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    window_ = std::make_unique<MainWindow>(false);
    window_->resize(1280, 800);
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
    QString error;
    ASSERT_TRUE(window_->open_motion(QString::fromStdString(gui_test_motion_path()), &error))
        << error.toStdString();
    QApplication::processEvents();
  }
  void TearDown() override {
    window_->close();
    window_.reset();
  }

  std::unique_ptr<MainWindow> window_;
};

}  // namespace saltus::gui::test
