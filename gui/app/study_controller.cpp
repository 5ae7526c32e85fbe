#include "app/study_controller.h"

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QProcess>
#include <QProgressDialog>

#include "app/qt_text.h"
#include "saltus/formats/study_progress.h"

namespace saltus::gui {

namespace {

QString clock(double seconds) {
  return qstr(clock_text(seconds));
}

}  // namespace

StudyController::StudyController(AppContext& context, QObject* parent)
    : QObject(parent), context_(context) {
  const QString beside = QCoreApplication::applicationDirPath() + "/saltus";
  program_ = QFileInfo(beside).isExecutable() ? beside : QString("saltus");
  context_.workspace().subscribe([this](WorkspaceChange) { update_action(); });
}

void StudyController::fill_menu(QMenu* menu) {
  action_ = new QAction(tr("Convergence &study of this motion…"), this);
  action_->setStatusTip(
      tr("The paper's experiment on the open motion: the relaxed and the strict model under "
         "mass and timing errors, every case in a process of its own (saltus study "
         "convergence)"));
  connect(action_, &QAction::triggered, this, [this] { ask_and_start(); });
  menu->addSeparator();
  menu->addAction(action_);
  update_action();
}

void StudyController::update_action() {
  if (action_) action_->setEnabled(context_.workspace().loaded() && !running());
}

QProgressDialog* StudyController::dialog() const {
  return dialog_;
}

bool StudyController::running() const {
  return process_ && process_->state() != QProcess::NotRunning;
}

void StudyController::ask_and_start() {
  const QString dir = QFileDialog::getSaveFileName(
      context_.window(), tr("Study folder (created, or an earlier study's, replaced)"),
      context_.last_dir() + "/convergence-study");
  if (dir.isEmpty()) return;
  bool resume = false;
  if (QFileInfo::exists(dir + ".partial")) {
    const auto answer = QMessageBox::question(
        context_.window(), tr("Resume the study?"),
        tr("%1.partial holds the finished cases of an interrupted study. Resume it (run only "
           "the cases it lacks)?")
            .arg(dir),
        QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Yes);
    if (answer != QMessageBox::Yes) return;
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
  arguments += design;
  if (resume) arguments << "--resume";
  out_dir_ = out_dir;
  title_ = tr("Convergence study of %1").arg(qstr(d.file().motion.name));
  last_message_.clear();
  progress_.reset();
  outcome_.clear();
  cancelled_ = false;

  delete process_;
  process_ = new QProcess(this);
  process_->setProgram(program_);
  process_->setArguments(arguments);
  process_->setProcessChannelMode(QProcess::SeparateChannels);
  connect(process_, &QProcess::readyReadStandardError, this, [this] { read_progress(); });
  connect(process_, qOverload<int, QProcess::ExitStatus>(&QProcess::finished), this,
          [this](int code, QProcess::ExitStatus status) {
            on_finished(status == QProcess::NormalExit ? code : 128 + 9);
          });

  if (!dialog_) {
    dialog_ = new QProgressDialog(context_.window());
    dialog_->setWindowTitle(tr("Study"));
    dialog_->setMinimumWidth(560);
    dialog_->setAutoClose(false);
    dialog_->setAutoReset(false);
    connect(dialog_, &QProgressDialog::canceled, this, [this] { cancel(); });
  }
  dialog_->setCancelButtonText(tr("Stop (keep finished cases)"));
  dialog_->setRange(0, 0);  // busy until the first case reports the total
  dialog_->setValue(0);
  dialog_->setLabelText(title_ + "\n" +
                        tr("starting %1 cases in processes of their own…")
                            .arg(resume ? tr("the missing") : tr("its")));
  dialog_->show();

  process_->start();
  if (!process_->waitForStarted(10000)) {
    dialog_->hide();
    return context_.fail(title, tr("%1 did not start: %2").arg(program_, process_->errorString()),
                         error);
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
    if (!dialog_) continue;
    dialog_->setRange(0, p->total);
    dialog_->setValue(p->done);
    const QString left =
        p->eta_s < 0 ? tr("time left unknown") : tr("about %1 left").arg(clock(p->eta_s));
    dialog_->setLabelText(title_ + "\n" +
                          tr("%1 of %2 cases · %3 failed · %4 not solved · %5 elapsed · %6")
                              .arg(p->done)
                              .arg(p->total)
                              .arg(p->failed)
                              .arg(p->unsolved)
                              .arg(clock(p->elapsed_s), left) +
                          "\n" + tr("last: %1 — %2").arg(qstr(p->last_case), qstr(p->last_result)));
  }
}

void StudyController::cancel() {
  if (!running()) return;
  cancelled_ = true;
  process_->terminate();  // SIGTERM: the study stops like Ctrl+C and keeps DIR.partial
}

void StudyController::on_finished(int exit_code) {
  read_progress();
  const QString cases =
      progress_ ? tr("%1 of %2 cases").arg(progress_->done).arg(progress_->total) : tr("no case");
  if (exit_code == 0 || exit_code == 3) {
    const QString failures =
        progress_ ? tr(", %1 failed, %2 not solved").arg(progress_->failed).arg(progress_->unsolved)
                  : QString();
    outcome_ = tr("%1 written to %2 (%3%4): convergence.md and convergence.csv")
                   .arg(title_, out_dir_, cases, failures);
  } else if (exit_code > 128 || cancelled_) {
    outcome_ = tr("%1 stopped after %2; the finished cases are kept in %3.partial: run the "
                  "study into %3 again and choose Resume to continue")
                   .arg(title_, cases, out_dir_);
  } else {
    outcome_ = tr("%1 failed (exit status %2): %3").arg(title_).arg(exit_code).arg(last_message_);
  }
  if (dialog_) {
    if (progress_) dialog_->setValue(progress_->done);
    dialog_->hide();
  }
  context_.status(outcome_, 20000);
  if (context_.interactive()) {
    if (exit_code == 0 || exit_code == 3 || exit_code > 128 || cancelled_)
      QMessageBox::information(context_.window(), tr("Study"), outcome_);
    else
      QMessageBox::warning(context_.window(), tr("Study"), outcome_);
  }
  update_action();
  emit finished(exit_code);
}

bool StudyController::wait(int timeout_ms) {
  QElapsedTimer timer;
  timer.start();
  while (running() && timer.elapsed() < timeout_ms)
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
  QCoreApplication::processEvents();
  return !running();
}

}  // namespace saltus::gui
