#pragma once
/// @file
/// Studies from the app (Optimise > Convergence study of this motion…): the `saltus` program
/// runs `study convergence` on the open motion's file in a process of its own, so the study
/// is exactly the command line's (every core, each case isolated, the same files); its progress
/// lines (formats/study_progress.h) drive a progress dialog with cases done, failures and the
/// time left. Cancel stops the study the way Ctrl+C does: its finished cases stay in
/// DIR.partial, and running it again into DIR offers to resume.

#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <optional>

#include "app/app_context.h"
#include "saltus/formats/study_progress.h"

class QAction;
class QMenu;
class QProcess;
class QProgressDialog;

namespace saltus::gui {

class StudyController : public QObject {
  Q_OBJECT

 public:
  StudyController(AppContext& context, QObject* parent = nullptr);

  void fill_menu(QMenu* menu);

  /// The `saltus` program studies run with: beside this executable, else on the PATH.
  void set_program(const QString& path) { program_ = path; }
  const QString& program() const { return program_; }

  /// Starts a convergence study of the open motion's file into `out_dir`. `design` are further
  /// arguments of `saltus study convergence` (--epsilons, --mass-errors, ...); `resume`
  /// continues the interrupted run in `out_dir`.partial. False (with the reason) when nothing
  /// is open, the motion has unsaved edits or another model, or a study is running.
  bool start(const QString& out_dir, const QStringList& design = {}, bool resume = false,
             QString* error = nullptr);
  /// Stops the running study as Ctrl+C does (finished cases kept for a resume).
  void cancel();
  bool running() const;
  /// Keeps the event loop running until the study ends or `timeout_ms` pass; whether it ended.
  bool wait(int timeout_ms);

  /// The latest progress line of the running or last study.
  const std::optional<StudyProgressLine>& progress() const { return progress_; }
  /// What the last study came to, in words (also shown in the status bar).
  const QString& outcome() const { return outcome_; }
  QProgressDialog* dialog() const;

 signals:
  /// The study's process ended with `exit_code` (0 done, 3 done with failed or unsolved
  /// cases, 128 + signal stopped, 2 bad input).
  void finished(int exit_code);

 private:
  void ask_and_start();
  void read_progress();
  void on_finished(int exit_code);
  void update_action();

  AppContext& context_;
  QString program_;
  QAction* action_ = nullptr;
  QProcess* process_ = nullptr;
  QPointer<QProgressDialog> dialog_;
  QString out_dir_;
  QString title_;
  QString last_message_;  ///< the last line on stderr that is not a progress line
  std::optional<StudyProgressLine> progress_;
  QString outcome_;
  bool cancelled_ = false;
};

}  // namespace saltus::gui
