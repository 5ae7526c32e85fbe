// Every control of the app is pressed by some GUI test: each entry of the main window's menu bar
// (submenus included), each button or check box of the window, its docks, toolbar and status
// bar, and each button or check box of the compare window and of the New athlete dialog must be
// in the list of tests/gui/support/pressed_controls.h, which names the test that presses it; a
// new control without one fails here with its name. The list is checked the other way too: each
// entry names a control the app has, and a test that exists.

#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QApplication>
#include <QDockWidget>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <QTabBar>
#include <QToolBar>
#include <QToolButton>
#include <map>
#include <set>
#include <string>

#include "app/athlete_controller.h"
#include "app/compare_controller.h"
#include "app/compare_window.h"
#include "app/main_window.h"
#include "app/new_athlete_dialog.h"
#include "gui/support/menu_actions.h"
#include "gui/support/open_motion_fixture.h"
#include "gui/support/pressed_controls.h"

namespace saltus::gui {
namespace {

/// The controls' stable names: a menu entry by its path of texts, a button by the dock, toolbar
/// or bar it sits in and its object name (or its text).
class ControlCoverageTest : public test::EmptyWindowTest {
 protected:
  void SetUp() override {
    test::EmptyWindowTest::SetUp();
    if (HasFatalFailure()) return;
    QString error;
    ASSERT_TRUE(window_->open_motion(
        SALTUS_EXAMPLES_DIR "/motions/M1-straight-back-somersault.motion.json", &error))
        << error.toStdString();
    QApplication::processEvents();
  }

  /// Every leaf entry under `menu`, keyed by its path; the entries of the recent files are one.
  void collect_menu(const QMenu* menu, const QString& path, std::set<std::string>* out) {
    for (QAction* a : menu->actions()) {
      if (a->isSeparator()) continue;
      QString name = test::shown_text(a);
      if (path == "File > Open recent" && name != "Clear list") name = "(a recent motion)";
      const QString here = path + " > " + name;
      if (a->menu())
        collect_menu(a->menu(), here, out);
      else
        out->insert(here.toStdString());
    }
  }

  std::set<std::string> menu_entries() {
    std::set<std::string> out;
    for (QAction* top : window_->menuBar()->actions())
      if (top->menu()) collect_menu(top->menu(), test::shown_text(top), &out);
    return out;
  }

  /// Qt's own buttons (a dock's close and float buttons, tab and toolbar scrollers, a table's
  /// corner), which no Saltus code makes.
  static bool qt_own(const QAbstractButton* b) {
    const QString cls = b->metaObject()->className();
    return b->objectName().startsWith("qt_") || cls == "QDockWidgetTitleButton" ||
           cls == "QTableCornerButton" || qobject_cast<const QTabBar*>(b->parentWidget());
  }

  /// Where a button sits: the object name of its dock or toolbar, or "status bar" or "main".
  static QString container(const QWidget* w) {
    for (; w; w = w->parentWidget()) {
      if (qobject_cast<const QDockWidget*>(w) || qobject_cast<const QToolBar*>(w))
        return w->objectName();
      if (qobject_cast<const QStatusBar*>(w)) return "status bar";
    }
    return "main";
  }

  /// Buttons by "<container> / <object name or text>"; a toolbar button of a menu entry is that
  /// entry (named by the entry, so not listed twice).
  std::set<std::string> buttons() {
    std::set<std::string> out;
    std::set<QAction*> in_menus;
    for (QAction* top : window_->menuBar()->actions())
      if (top->menu()) add_actions(top->menu(), &in_menus);
    for (QAbstractButton* b : window_->findChildren<QAbstractButton*>()) {
      if (qt_own(b)) continue;
      auto* tool = qobject_cast<QToolButton*>(b);
      if (tool && tool->defaultAction() && in_menus.count(tool->defaultAction())) continue;
      const QString name = b->objectName().isEmpty() ? b->text().remove('&') : b->objectName();
      out.insert((container(b) + " / " + name).toStdString());
    }
    return out;
  }

  /// The buttons and check boxes of a window of its own (no menu bar, so every toolbar button
  /// counts), by "<container> / <object name or text>". The dialog button box's Cancel counts as
  /// ours: the dialog puts it there, and pressing it must drop the athlete.
  static std::set<std::string> window_buttons(const QWidget* window, const QString& container) {
    std::set<std::string> out;
    for (QAbstractButton* b : window->findChildren<QAbstractButton*>()) {
      if (qt_own(b)) continue;
      const QString name = b->objectName().isEmpty() ? b->text().remove('&') : b->objectName();
      out.insert((container + " / " + name).toStdString());
    }
    return out;
  }

  static void add_actions(const QMenu* menu, std::set<QAction*>* out) {
    for (QAction* a : menu->actions()) {
      out->insert(a);
      if (a->menu()) add_actions(a->menu(), out);
    }
  }
};

TEST_F(ControlCoverageTest, EveryMenuEntryAndButtonIsPressedByATest) {
  std::set<std::string> controls = menu_entries();
  const std::set<std::string> found_buttons = buttons();
  ASSERT_GT(controls.size(), 40u);
  ASSERT_GT(found_buttons.size(), 15u);
  controls.insert(found_buttons.begin(), found_buttons.end());

  // The compare window, opened on the open motion against itself.
  QString error;
  ASSERT_TRUE(window_->compare().compare_with_motion(
      SALTUS_EXAMPLES_DIR "/motions/M1-straight-back-somersault.motion.json", &error))
      << error.toStdString();
  ASSERT_NE(window_->compare().window(), nullptr);
  const std::set<std::string> compare =
      window_buttons(window_->compare().window(), "compare window");
  EXPECT_GT(compare.size(), 8u);
  controls.insert(compare.begin(), compare.end());
  window_->compare().close();

  // The New athlete dialog, as File > New athlete… opens it.
  NewAthleteDialog* dialog = window_->athletes().open_dialog(false);
  ASSERT_NE(dialog, nullptr);
  const std::set<std::string> athlete = window_buttons(dialog, "new athlete dialog");
  EXPECT_GE(athlete.size(), 6u);
  controls.insert(athlete.begin(), athlete.end());
  dialog->reject();

  std::map<std::string, const test::PressedControl*> listed;
  for (const test::PressedControl& c : test::kPressedControls) {
    EXPECT_TRUE(listed.emplace(c.control, &c).second) << "listed twice: " << c.control;
  }
  for (const std::string& c : controls)
    EXPECT_TRUE(listed.count(c)) << "no GUI test presses \"" << c
                                 << "\": add a test that presses it and checks its effect, and "
                                    "list it in tests/gui/support/pressed_controls.h";
  for (const auto& [name, entry] : listed)
    EXPECT_TRUE(controls.count(name)) << "listed, but the window has no \"" << name << "\"";
}

TEST(PressedControls, EachEntryNamesATestThatExists) {
  std::map<std::string, QString> sources;
  for (const test::PressedControl& c : test::kPressedControls) {
    SCOPED_TRACE(c.control);
    auto it = sources.find(c.file);
    if (it == sources.end()) {
      QFile file(QString(SALTUS_GUI_BASELINE_DIR) + "/../" + c.file);
      ASSERT_TRUE(file.open(QIODevice::ReadOnly)) << "no tests/gui/" << c.file;
      it = sources.emplace(c.file, QString::fromUtf8(file.readAll())).first;
    }
    EXPECT_NE(it->second.indexOf(QString("TEST_F(%1)").arg(c.test)), -1)
        << "tests/gui/" << c.file << " has no TEST_F(" << c.test << ")";
  }
}

}  // namespace
}  // namespace saltus::gui
