#pragma once
/// @file
/// What the parts of the main window share: the window (parent of dialogs, its status bar), the
/// workspace, whether someone is there to answer dialogs, the folder file dialogs start in, and
/// the widgets where the view's keyboard shortcuts act. Each part (files, edits, runs, view,
/// playback, plots, compare) gets a reference to it instead of to the other parts.

#include <QString>
#include <QWidget>
#include <vector>

#include "core/workspace.h"

class QAction;
class QMainWindow;
class QSettings;

namespace saltus::gui {

class AppContext {
 public:
  /// @param interactive  dialogs for errors and questions; false (batch mode, tests): errors
  ///                     go to the caller or stderr and nothing waits for an answer
  AppContext(QMainWindow* window, bool interactive);

  QMainWindow* window() const { return window_; }
  Workspace& workspace() { return workspace_; }
  const Workspace& workspace() const { return workspace_; }
  bool interactive() const { return interactive_; }

  /// Where open dialogs start: the folder of the last file opened or written.
  QString last_dir() const { return last_dir_; }
  void set_last_dir_from(const QString& path);
  void set_last_dir(const QString& dir) { last_dir_ = dir; }
  /// Where save dialogs start (core/file_places.h): the folder last saved into, else the last
  /// one opened from unless it is bundled with Saltus or read-only, else ~/saltus (made).
  QString save_dir() const;
  /// A file or folder was written at `path`: later saves start beside it.
  void note_saved(const QString& path);
  QString last_saved_dir() const { return last_saved_dir_; }
  void set_last_saved_dir(const QString& dir) { last_saved_dir_ = dir; }

  /// Reports a failure: into `error` when given, else in a dialog (interactive) or on stderr.
  /// Always returns false, so operations can `return context.fail(...)`.
  bool fail(const QString& title, const QString& message, QString* error) const;
  /// A transient message in the status bar.
  void status(const QString& message, int milliseconds = 6000) const;

  /// Widgets inside which the view's single-key shortcuts (Space, arrows, digits, B/A, R, Esc)
  /// act: the 3D view, the timeline and the charts. Never an input field, a list or a check box,
  /// which need the keys.
  void add_shortcut_scope(QWidget* widget) { scopes_.push_back(widget); }
  /// Makes `action`'s shortcut act only while the focus is inside one of the scope widgets.
  void scope_shortcut(QAction* action) const;

 private:
  QMainWindow* window_;
  Workspace workspace_;
  bool interactive_;
  QString last_dir_;
  QString last_saved_dir_;
  std::vector<QWidget*> scopes_;
};

/// A part of the window that remembers values between sessions (QSettings).
class RemembersSettings {
 public:
  virtual ~RemembersSettings() = default;
  virtual void load_settings(const QSettings& settings) = 0;
  virtual void save_settings(QSettings& settings) const = 0;
};

}  // namespace saltus::gui
