#include "app/study_controller.h"

#include <unistd.h>

#include <QAction>
#include <QCoreApplication>
#include <QDesktopServices>
#include <QDir>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QProcess>
#include <QProgressBar>
#include <QSettings>
#include <QStatusBar>
#include <QToolButton>
#include <algorithm>
#include <exception>

#include "app/qt_text.h"
#include "app/study_panel.h"
#include "saltus/studies/isolated_runner.h"
#include "saltus/use_cases/study_runner.h"

namespace saltus::gui {

namespace {

/// The study's process: lowered in priority before it runs `saltus`, so that its case processes
/// (which inherit the niceness) give way to the app whenever both want a core.
class NiceProcess : public QProcess {
 public:
  using QProcess::QProcess;

 protected:
  void setupChildProcess() override {
    // Between fork and exec: only async-signal-safe calls. A failure leaves the priority as is.
    (void)::nice(StudyController::kStudyNiceness);
  }
};

/// "M1-straight-back-somersault" from ".../M1-straight-back-somersault.motion.json".
QString study_motion_stem(const std::string& path) {
  return QFileInfo(qstr(path)).completeBaseName().remove(".motion");
}

bool writable_folder(const QString& path) {
  const QFileInfo info(path);
  return info.isDir() && info.isWritable();
}

}  // namespace

StudyController::StudyController(AppContext& context, QObject* parent)
    : QObject(parent), context_(context) {
  const QString beside = QCoreApplication::applicationDirPath() + "/saltus";
  program_ = QFileInfo(beside).isExecutable() ? beside : QString("saltus");
  chooser_ = [this](const QString& suggestion) {
    return QFileDialog::getSaveFileName(
        context_.window(), tr("Study folder (created, or an earlier study's, replaced)"),
        suggestion);
  };
  opener_ = [](const QUrl& url) { return QDesktopServices::openUrl(url); };

  panel_ = new StudyPanel(context_.window());
  connect(panel_, &StudyPanel::stop_requested, this, [this] { cancel(); });
  connect(panel_, &StudyPanel::open_folder_requested, this, [this] { open_folder(); });
  connect(panel_, &StudyPanel::open_report_requested, this, [this] { open_report(); });

  strip_ = new QWidget(context_.window());
  strip_->setObjectName("study_strip");
  auto* strip = new QHBoxLayout(strip_);
  strip->setContentsMargins(0, 0, 0, 0);
  strip_bar_ = new QProgressBar(strip_);
  strip_bar_->setFixedWidth(110);
  strip_bar_->setMaximumHeight(14);
  strip_bar_->setTextVisible(false);
  strip_button_ = new QToolButton(strip_);
  strip_button_->setObjectName("study_strip_button");
  // Text from the start: the status bar lays itself out again when its height changes, and that
  // brings its normal widgets back over a message it shows.
  strip_button_->setText(tr("Study"));
  strip_button_->setAutoRaise(true);
  strip_button_->setToolTip(tr("Show the Study panel: progress, Stop, and the results"));
  connect(strip_button_, &QToolButton::clicked, this, &StudyController::panel_wanted);
  strip->addWidget(strip_bar_);
  strip->addWidget(strip_button_);
  strip_->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Preferred);
  // No taller than a line of text: the status bar takes the height of its tallest widget, shown
  // or not, and a button's height would push the panels and the 3D view up by a few pixels.
  strip_->setMaximumHeight(strip_->fontMetrics().height());
  context_.window()->statusBar()->addPermanentWidget(strip_);
  strip_->hide();

  context_.workspace().subscribe([this](WorkspaceChange) { update_action(); });
}

void StudyController::fill_menu(QMenu* menu) {
  action_ = new QAction(tr("Convergence &study of this motion…"), this);
  action_->setStatusTip(
      tr("The paper's experiment on the open motion: the relaxed and the strict model under "
         "mass and timing errors, every case in a process of its own (saltus study "
         "convergence); progress and results in the Study panel"));
  connect(action_, &QAction::triggered, this, [this] { ask_and_start(); });
  menu->addSeparator();
  menu->addAction(action_);
  update_action();
}

void StudyController::update_action() {
  if (action_) action_->setEnabled(context_.workspace().loaded() && !running());
}

int StudyController::default_jobs() {
  return std::max(1, available_cpus() - 1);
}

bool StudyController::running() const {
  return process_ && process_->state() != QProcess::NotRunning;
}

qint64 StudyController::process_id() const {
  return running() ? process_->processId() : 0;
}

QString StudyController::proposed_folder() const {
  QString parent;
  if (!last_out_dir_.isEmpty()) {
    const QString last_parent = QFileInfo(last_out_dir_).absolutePath();
    if (writable_folder(last_parent)) parent = last_parent;
  }
  if (parent.isEmpty()) {
    const QString studies = QDir::home().filePath("saltus-studies");
    parent = QDir().mkpath(studies) && writable_folder(studies) ? studies : QDir::tempPath();
  }
  const Workspace& ws = context_.workspace();
  const QString stem = ws.loaded() ? study_motion_stem(ws.document().file().path) : "study";
  return QDir(parent).filePath(stem + "-convergence");
}

void StudyController::ask_and_start() {
  const QString dir = chooser_(proposed_folder());
  if (dir.isEmpty()) return;
  bool resume = false;
  const QString partial = qstr(study_partial_folder(dir.toStdString()));
  if (QFileInfo::exists(partial)) {
    // Without someone to ask, the question's default: resume.
    if (context_.interactive()) {
      const auto answer = QMessageBox::question(
          context_.window(), tr("Resume the study?"),
          tr("%1 holds the finished cases of an interrupted study. Resume it (run only "
             "the cases it lacks)?")
              .arg(partial),
          QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Yes);
      if (answer != QMessageBox::Yes) return;
    }
    resume = true;
  }
  start(dir, {}, resume);
}

bool StudyController::start(const QString& out_dir, const QStringList& design, bool resume,
                            QString* error) {
  const Workspace& ws = context_.workspace();
  const QString title = tr("Cannot run the study");
  if (running()) return context_.fail(title, tr("A study is already running."), error);
  if (!ws.loaded()) return context_.fail(title, tr("Open a motion first."), error);
  const Document& d = ws.document();
  if (ws.motion_unsaved() || ws.model_unsaved())
    return context_.fail(title,
                         tr("The study reads the motion from its file: save the edits first (File "
                            "> Save motion as…)."),
                         error);
  if (!d.model_override().empty())
    return context_.fail(title,
                         tr("The study reads the model the motion file names; this motion is "
                            "shown with another model. Save the motion beside that model first."),
                         error);

  QStringList arguments{"study", "convergence", qstr(d.file().path), "--out", out_dir};
  const bool jobs_given = std::any_of(design.begin(), design.end(), [](const QString& a) {
    return a == "--jobs" || a == "-j" || a.startsWith("--jobs=");
  });
  if (!jobs_given) arguments << "--jobs" << QString::number(default_jobs());
  arguments += design;
  if (resume) arguments << "--resume";
  arguments_ = arguments;
  out_dir_ = out_dir;
  last_out_dir_ = QFileInfo(out_dir).absoluteFilePath();
  title_ = tr("Convergence study of %1").arg(qstr(d.file().motion.name));
  last_message_.clear();
  progress_.reset();
  outcome_.clear();
  results_.reset();
  cancelled_ = false;

  delete process_;
  process_ = new NiceProcess(this);
  process_->setProgram(program_);
  process_->setArguments(arguments);
  process_->setProcessChannelMode(QProcess::SeparateChannels);
  connect(process_, &QProcess::readyReadStandardError, this, [this] { read_progress(); });
  connect(process_, qOverload<int, QProcess::ExitStatus>(&QProcess::finished), this,
          [this](int code, QProcess::ExitStatus status) {
            on_finished(status == QProcess::NormalExit ? code : 128 + 9);
          });

  emit tables_changed(false);
  panel_->show_started(title_, out_dir,
                       tr("starting %1 cases in processes of their own…")
                           .arg(resume ? tr("the missing") : tr("its")));
  strip_bar_->setRange(0, 0);
  strip_button_->setText(tr("Study starting…"));
  strip_->show();
  emit panel_wanted();

  process_->start();
  if (!process_->waitForStarted(10000)) {
    strip_->hide();
    const QString message = tr("%1 did not start: %2").arg(program_, process_->errorString());
    panel_->show_ended(message, true);
    return context_.fail(title, message, error);
  }
  update_action();
  context_.status(title_ + tr(": running"));
  return true;
}

void StudyController::read_progress() {
  process_->setReadChannel(QProcess::StandardError);
  while (process_->canReadLine()) {
    const std::string line = process_->readLine().toStdString();
    std::optional<StudyProgressLine> p = parse_study_progress_line(line);
    if (!p) {
      const QString text = qstr(line).trimmed();
      if (!text.isEmpty()) last_message_ = text;
      continue;
    }
    progress_ = p;
    panel_->show_progress(*p);
    strip_bar_->setRange(0, p->total);
    strip_bar_->setValue(p->done);
    strip_button_->setText(tr("Study %1/%2 · %3")
                               .arg(p->done)
                               .arg(p->total)
                               .arg(p->eta_s < 0
                                        ? tr("time left unknown")
                                        : tr("about %1 left").arg(qstr(clock_text(p->eta_s)))));
  }
}

void StudyController::cancel() {
  if (!running()) return;
  cancelled_ = true;
  process_->terminate();  // SIGTERM: the study stops like Ctrl+C and keeps DIR.partial
}

void StudyController::on_finished(int exit_code) {
  read_progress();
  const bool done = exit_code == 0 || exit_code == 3;
  const bool stopped = !done && (exit_code > 128 || cancelled_);
  // What the folder holds, as the library reads it: the whole study, or the cases kept.
  results_.reset();
  QString unread;
  const QString folder = done ? out_dir_ : qstr(study_partial_folder(out_dir_.toStdString()));
  if ((done || stopped) && QFileInfo::exists(folder + "/study.json")) {
    try {
      results_ = read_convergence_study_folder(folder.toStdString());
    } catch (const std::exception& e) {
      unread = qstr(e.what());
    }
  }
  // A study stopped between writing a case and reporting it has kept more than it reported:
  // the count said is what the folder holds, as the case table shows it.
  if (stopped && results_ && progress_)
    progress_->done = std::max(progress_->done, static_cast<int>(results_->outcomes.size()));
  const QString cases =
      progress_ ? tr("%1 of %2 cases").arg(progress_->done).arg(progress_->total) : tr("no case");
  if (done) {
    const QString failures =
        progress_ ? tr(", %1 failed, %2 not solved").arg(progress_->failed).arg(progress_->unsolved)
                  : QString();
    outcome_ = tr("%1 done (%2%3): convergence.md and convergence.csv written to %4")
                   .arg(title_, cases, failures, out_dir_);
  } else if (stopped) {
    outcome_ = tr("%1 stopped after %2; the finished cases are kept in %3.partial: run the "
                  "study into %3 again and choose Resume to continue")
                   .arg(title_, cases, out_dir_);
  } else {
    outcome_ = tr("%1 failed (exit status %2): %3").arg(title_).arg(exit_code).arg(last_message_);
  }
  if (!unread.isEmpty()) outcome_ += tr(". Its folder could not be read back: %1").arg(unread);
  const bool failure = !(done || stopped) || !unread.isEmpty();
  panel_->show_ended(outcome_, failure);
  if (results_)
    panel_->show_results(*results_);
  else
    panel_->clear_results();
  strip_->hide();
  context_.status(outcome_, 20000);
  emit panel_wanted();
  emit tables_changed(results_.has_value());
  if (context_.interactive() && failure)
    QMessageBox::warning(context_.window(), tr("Study"), outcome_);
  update_action();
  emit finished(exit_code);
}

bool StudyController::open_folder() {
  if (!results_) return false;
  return opener_(QUrl::fromLocalFile(qstr(results_->path)));
}

bool StudyController::open_report() {
  if (!results_ || results_->markdown_path.empty()) return false;
  return opener_(QUrl::fromLocalFile(qstr(results_->markdown_path)));
}

bool StudyController::wait(int timeout_ms) {
  QElapsedTimer timer;
  timer.start();
  while (running() && timer.elapsed() < timeout_ms)
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
  QCoreApplication::processEvents();
  return !running();
}

void StudyController::load_settings(const QSettings& s) {
  last_out_dir_ = s.value("studies/last_folder").toString();
}

void StudyController::save_settings(QSettings& s) const {
  s.setValue("studies/last_folder", last_out_dir_);
}

}  // namespace saltus::gui
