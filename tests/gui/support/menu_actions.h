#pragma once
// Menu entries as a user finds them: by their path of texts from the menu bar ("View", "Side
// camera"), the mnemonic ampersands left out; and a modal dialog an entry opens, read and closed
// by a timer while the entry's trigger() waits for it.

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QFileDialog>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QStringList>
#include <QTimer>
#include <functional>
#include <vector>

namespace saltus::gui::test {

/// An action's text as shown, without the mnemonic ampersands.
inline QString shown_text(const QAction* action) {
  QString text = action->text();
  return text.remove('&');
}

/// The action at `path` under `window`'s menu bar (null: none).
inline QAction* menu_action(QMainWindow* window, const QStringList& path) {
  QList<QAction*> actions = window->menuBar()->actions();
  QAction* found = nullptr;
  for (const QString& step : path) {
    found = nullptr;
    for (QAction* a : actions)
      if (!a->isSeparator() && shown_text(a) == step) found = a;
    if (!found) return nullptr;
    if (found->menu()) actions = found->menu()->actions();
  }
  return found;
}

/// What a modal dialog said before it was closed.
struct SeenDialog {
  bool shown = false;
  QString title;
  QString text;  ///< a message box's text
};

/// Triggers `action` and closes (rejects) the first modal dialog it opens.
inline SeenDialog trigger_and_close_dialog(QAction* action) {
  SeenDialog seen;
  QTimer timer;
  timer.setInterval(20);
  QObject::connect(&timer, &QTimer::timeout, [&seen] {
    QWidget* modal = QApplication::activeModalWidget();
    if (!modal || seen.shown) return;
    seen.shown = true;
    seen.title = modal->windowTitle();
    if (auto* box = qobject_cast<QMessageBox*>(modal)) seen.text = box->text();
    if (auto* dialog = qobject_cast<QDialog*>(modal))
      dialog->reject();
    else
      modal->close();
  });
  timer.start();
  action->trigger();
  timer.stop();
  return seen;
}

/// Types `path` into a file dialog's name field, as a user would (selectFile() leaves the field
/// alone while it has the focus).
inline void type_file_name(QFileDialog* dialog, const QString& path) {
  if (auto* edit = dialog->findChild<QLineEdit*>("fileNameEdit"))
    edit->setText(path);
  else
    dialog->selectFile(path);
}

/// Calls `open` (a menu entry triggered, a button clicked) and answers the modal dialog it opens,
/// a file dialog, with `path` (empty: cancelled); returns the dialog's title (empty: no dialog was
/// opened). The answer is given again at each tick while the dialog stays open (it may still be
/// reading its folder), and the dialog is rejected after 5 s, so that a dialog refusing the answer
/// fails the test, not hangs.
inline QString answer_file_dialog(const std::function<void()>& open, const QString& path) {
  QString title;
  int ticks = 0;
  QTimer timer;
  timer.setInterval(50);
  QObject::connect(&timer, &QTimer::timeout, [&] {
    auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
    if (!dialog) return;
    if (title.isEmpty()) title = dialog->windowTitle();
    auto* files = qobject_cast<QFileDialog*>(dialog);
    if (files && !path.isEmpty() && ++ticks < 100) {
      type_file_name(files, path);
      dialog->accept();  // QFileDialog::accept: takes the name if it suits the dialog's mode
    } else {
      dialog->reject();
    }
  });
  timer.start();
  open();
  timer.stop();
  return title;
}

inline QString trigger_and_answer_file_dialog(QAction* action, const QString& path) {
  return answer_file_dialog([action] { action->trigger(); }, path);
}

/// Triggers `action` and hands the modal dialogs it opens, one after the other, to `answers`
/// (each answers its dialog: accepts or rejects it); returns how many dialogs were answered.
inline int trigger_and_answer_dialogs(QAction* action,
                                      const std::vector<std::function<void(QDialog*)>>& answers) {
  std::size_t answered = 0;
  QDialog* last = nullptr;
  QTimer timer;
  timer.setInterval(20);
  QObject::connect(&timer, &QTimer::timeout, [&] {
    auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
    if (!dialog || dialog == last || answered >= answers.size()) return;
    last = dialog;
    answers[answered++](dialog);
  });
  timer.start();
  action->trigger();
  timer.stop();
  return static_cast<int>(answered);
}

}  // namespace saltus::gui::test
