#pragma once
/// @file
/// Studies from the app (Optimise > Convergence study of this motion…): the `saltus` program
/// runs `study convergence` on the open motion's file in a process of its own, so the study
/// is exactly the command line's (each case isolated, the same files). It runs on one core
/// fewer than the machine has (`--jobs`, at least 1) and at a lower priority (nice 10), so the
/// app's 3D view and an optimisation started in the app keep their pace. Its progress lines
/// (formats/study_progress.h) drive the Study panel (StudyPanel, a tab of the panel column) and
/// a strip in the status bar; nothing covers the 3D view. Stop stops the study the way Ctrl+C
/// does: its finished cases stay in DIR.partial, and running it again into DIR offers to
/// resume. When it ends, the panel shows the study's folder as the library reads it back
/// (read_convergence_study_folder): the summary table, a chart, the cases, Open folder and Open
/// report.

#include <QObject>
#include <QString>
#include <QStringList>
#include <QUrl>
#include <functional>
#include <optional>

#include "app/app_context.h"
#include "saltus/formats/convergence_files.h"
#include "saltus/formats/study_progress.h"

class QAction;
class QLabel;
class QMenu;
class QProcess;
class QProgressBar;
class QToolButton;

namespace saltus::gui {

class StudyPanel;

class StudyController : public QObject, public RemembersSettings {
  Q_OBJECT

 public:
  StudyController(AppContext& context, QObject* parent = nullptr);

  void fill_menu(QMenu* menu);
  /// Optimise > Convergence study of this motion…
  QAction* action() const { return action_; }
  StudyPanel* panel() const { return panel_; }
  /// The status bar's strip while a study runs: a small progress bar and a button that brings
  /// the Study panel to the front.
  QWidget* status_strip() const { return strip_; }
  QToolButton* status_button() const { return strip_button_; }

  /// The `saltus` program studies run with: beside this executable, else on the PATH.
  void set_program(const QString& path) { program_ = path; }
  const QString& program() const { return program_; }

  /// Cases a study from the app runs at once: the cores this process may use less one (left
  /// to the app), at least 1.
  static int default_jobs();
  /// The study's processes run at this niceness (the app's stays 0).
  static constexpr int kStudyNiceness = 10;

  /// Where the folder dialog starts: PARENT/<motion>-convergence, PARENT being the folder the
  /// last study was written into when it is still there and writable, else ~/saltus-studies
  /// (created). Never the motion's own folder just because the motion is there: that may be
  /// read-only (bundled examples, a shared drive).
  QString proposed_folder() const;
  /// Where to write the study: the chosen folder, or "" when the user cancels.
  using FolderChooser = std::function<QString(const QString& suggestion)>;
  /// Replaces the folder dialog (tests). The default is Qt's save dialog starting at the
  /// proposed folder.
  void set_folder_chooser(FolderChooser chooser) { chooser_ = std::move(chooser); }
  /// Opens a folder or a file with the desktop's program; replaced in tests.
  using UrlOpener = std::function<bool(const QUrl& url)>;
  void set_url_opener(UrlOpener opener) { opener_ = std::move(opener); }

  /// Starts a convergence study of the open motion's file into `out_dir`. `design` are further
  /// arguments of `saltus study convergence` (--epsilons, --mass-errors, ...; with --jobs it
  /// replaces default_jobs()); `resume` continues the interrupted run in `out_dir`.partial.
  /// False (with the reason) when nothing is open, the motion has unsaved edits or another
  /// model, or a study is running.
  bool start(const QString& out_dir, const QStringList& design = {}, bool resume = false,
             QString* error = nullptr);
  /// Stops the running study as Ctrl+C does (finished cases kept for a resume).
  void cancel();
  bool running() const;
  /// Keeps the event loop running until the study ends or `timeout_ms` pass; whether it ended.
  bool wait(int timeout_ms);
  /// The study's process id while it runs, else 0.
  qint64 process_id() const;
  /// The arguments the last study was started with.
  const QStringList& arguments() const { return arguments_; }

  /// The latest progress line of the running or last study.
  const std::optional<StudyProgressLine>& progress() const { return progress_; }
  /// What the last study came to, in words (also shown in the status bar).
  const QString& outcome() const { return outcome_; }
  /// The last study's folder as the library read it when it ended: DIR, or the cases a stopped
  /// study kept in DIR.partial; nothing while one runs or when it failed.
  const std::optional<ConvergenceStudyFolder>& results() const { return results_; }
  /// Open folder and Open report (the panel's buttons): the results' folder, convergence.md.
  bool open_folder();
  bool open_report();

  void load_settings(const QSettings& settings) override;
  void save_settings(QSettings& settings) const override;

 signals:
  /// The study's process ended with `exit_code` (0 done, 3 done with failed or unsolved
  /// cases, 128 + signal stopped, 2 bad input).
  void finished(int exit_code);
  /// A study started or ended: its panel should come to the front.
  void panel_wanted();
  /// The study's tables (StudyPanel::tables()) have results to show (true: bring them to the
  /// front) or none any more (a new study started, the last one failed).
  void tables_changed(bool results);

 private:
  void ask_and_start();
  void read_progress();
  void on_finished(int exit_code);
  void update_action();

  AppContext& context_;
  QString program_;
  QAction* action_ = nullptr;
  StudyPanel* panel_ = nullptr;
  QWidget* strip_ = nullptr;
  QProgressBar* strip_bar_ = nullptr;
  QToolButton* strip_button_ = nullptr;
  QProcess* process_ = nullptr;
  FolderChooser chooser_;
  UrlOpener opener_;
  QString out_dir_;
  QString last_out_dir_;  ///< the folder the last study was started into (remembered)
  QString title_;
  QStringList arguments_;
  QString last_message_;  ///< the last line on stderr that is not a progress line
  std::optional<StudyProgressLine> progress_;
  QString outcome_;
  std::optional<ConvergenceStudyFolder> results_;
  bool cancelled_ = false;
};

}  // namespace saltus::gui
