#pragma once
// The shared start of the GUI tests that drive the main window: a 1280×800 window, shown and
// exposed, empty (EmptyWindowTest) or with the GUI test motion (gui_core/test_motion.h) open
// (OpenMotionTest).

#include <gtest/gtest.h>

#include <QApplication>
#include <QString>
#include <QTest>
#include <memory>

#include "app/main_window.h"
#include "gui_core/test_motion.h"

namespace saltus::gui::test {

/// The main window, 1280×800, shown and exposed, nothing open; closed after the test.
class EmptyWindowTest : public ::testing::Test {
 protected:
  void SetUp() override {
    window_ = std::make_unique<MainWindow>(false);
    window_->resize(1280, 800);
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
  }
  void TearDown() override {
    window_->close();
    window_.reset();
  }

  std::unique_ptr<MainWindow> window_;
};

/// The main window with the GUI test motion open.
class OpenMotionTest : public EmptyWindowTest {
 protected:
  void SetUp() override {
    EmptyWindowTest::SetUp();
    if (HasFatalFailure()) return;
    QString error;
    ASSERT_TRUE(window_->open_motion(QString::fromStdString(gui_test_motion_path()), &error))
        << error.toStdString();
    QApplication::processEvents();
  }
};

}  // namespace saltus::gui::test
