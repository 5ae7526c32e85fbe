#include "app/app_context.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMainWindow>
#include <QMessageBox>
#include <QStatusBar>
#include <cstdio>

#include "core/file_places.h"

namespace saltus::gui {

AppContext::AppContext(QMainWindow* window, bool interactive)
    : window_(window), interactive_(interactive), last_dir_(QDir::homePath()) {}

void AppContext::set_last_dir_from(const QString& path) {
  const QFileInfo info(path);
  last_dir_ = info.isDir() ? info.absoluteFilePath() : info.absolutePath();
}

QString AppContext::save_dir() const {
  const QString fallback = QDir::home().filePath("saltus");
  const std::string folder = save_folder(last_saved_dir_.toStdString(), last_dir_.toStdString(),
                                         fallback.toStdString(), [](const std::string& path) {
                                           const QFileInfo info(QString::fromStdString(path));
                                           return info.isDir() && info.isWritable();
                                         });
  if (folder == fallback.toStdString()) QDir().mkpath(fallback);
  return QString::fromStdString(folder);
}

void AppContext::note_saved(const QString& path) {
  set_last_dir_from(path);
  last_saved_dir_ = last_dir_;
}

bool AppContext::fail(const QString& title, const QString& message, QString* error) const {
  if (error) {
    *error = message;
  } else if (interactive_) {
    QMessageBox::critical(window_, title, message);
  } else {
    std::fprintf(stderr, "saltus-gui: %s: %s\n", qPrintable(title), qPrintable(message));
  }
  return false;
}

void AppContext::status(const QString& message, int milliseconds) const {
  window_->statusBar()->showMessage(message, milliseconds);
}

void AppContext::scope_shortcut(QAction* action) const {
  action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
  for (QWidget* widget : scopes_)
    widget->addAction(action);
}

}  // namespace saltus::gui
