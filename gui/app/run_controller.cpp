#include "app/run_controller.h"

#include <QAction>
#include <QEventLoop>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QTimer>
#include <memory>
#include <optional>

#include "app/optimization_runner.h"
#include "app/optimize_panel.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/optim/result_standing.h"
#include "saltus/use_cases/athlete_verdict.h"

namespace saltus::gui {

namespace {

QString newtons(double value) {
  return QString::number(value, 'g', 3) + " N";
}

}  // namespace

RunController::RunController(AppContext& context, QObject* parent)
    : QObject(parent), context_(context) {
  panel_ = new OptimizePanel(context_.window());
  runner_ = new OptimizationRunner(this);
  connect(runner_, &OptimizationRunner::progress, panel_, &OptimizePanel::show_progress);
  connect(runner_, &OptimizationRunner::finished, this, &RunController::on_finished);
  connect(panel_, &OptimizePanel::run_requested, this, [this] { start(panel_->settings()); });
  connect(panel_, &OptimizePanel::cancel_requested, this, &RunController::cancel);
  connect(panel_, &OptimizePanel::run_chosen, this, [this](int index) { show_run(index); });

  run_ = new QAction(tr("&Run optimisation"), this);
  run_->setShortcut(Qt::CTRL | Qt::Key_R);
  run_->setToolTip(tr("Optimise the open motion with the Optimise panel's settings (Ctrl+R)"));
  connect(run_, &QAction::triggered, this, [this] { start(panel_->settings()); });
  cancel_ = new QAction(tr("&Cancel optimisation"), this);
  cancel_->setShortcut(Qt::Key_Escape);
  connect(cancel_, &QAction::triggered, this, &RunController::cancel);
  // Esc cancels from the view, the timeline, the plots and the panel itself, not while typing
  // elsewhere.
  context_.scope_shortcut(cancel_);
  panel_->addAction(cancel_);
  context_.workspace().subscribe([this](WorkspaceChange c) { on_workspace(c); });
  update_actions();
}

void RunController::fill_menu(QMenu* optimise) {
  optimise->addAction(run_);
  optimise->addAction(cancel_);
}

void RunController::on_workspace(WorkspaceChange change) {
  // A run of a motion that is no longer the one shown (another file, an undo) is stopped.
  if ((change == WorkspaceChange::kOpened || change == WorkspaceChange::kEdited) && running())
    runner_->cancel();
  switch (change) {
    case WorkspaceChange::kOpened:
      // Nothing of the previous motion stays in the panel.
      panel_->reset();
      break;
    case WorkspaceChange::kEdited:
    case WorkspaceChange::kRuns:
      show_list();
      break;
    case WorkspaceChange::kStage:
    case WorkspaceChange::kSaved:
      break;
  }
  update_actions();
}

void RunController::show_list() {
  const Workspace& ws = context_.workspace();
  std::vector<OptimizePanel::RunRow> rows;
  for (int i : ws.runs().ranking())
    rows.push_back({i, ws.runs().label(i, false), ws.runs().label(i, true)});
  const int shown = ws.shown_run() ? *ws.shown_run() : -1;
  panel_->show_runs(rows, shown);
  if (shown >= 0) {
    const RunRecord& run = ws.runs().at(shown);
    panel_->show_result(result_table(*run.result, run.options));
  } else {
    panel_->clear_result();
  }
}

void RunController::update_actions() {
  const bool loaded = context_.workspace().loaded();
  run_->setEnabled(loaded && !running());
  cancel_->setEnabled(running());
  panel_->set_available(loaded);
}

OptimizeSettings RunController::settings() const {
  return panel_->settings();
}

bool RunController::start(const OptimizeSettings& settings, QString* error) {
  Workspace& ws = context_.workspace();
  if (!ws.loaded())
    return context_.fail(tr("Nothing to optimise"), tr("Open a motion first."), error);
  if (running())
    return context_.fail(tr("Already running"), tr("An optimisation is already running."), error);
  try {
    running_options_ = to_optimize_options(settings);
  } catch (const std::invalid_argument& e) {
    return context_.fail(tr("Cannot optimise"), QString::fromStdString(e.what()), error);
  }
  running_settings_ = settings;
  panel_->set_settings(settings);
  runner_->start(ws.document().file(), running_options_, ws.generation());
  panel_->set_running(true);
  update_actions();
  context_.status(tr("Optimising run %1…").arg(ws.runs().next_number()), 0);
  return true;
}

void RunController::cancel() {
  if (!running()) return;
  runner_->cancel();
  panel_->show_message(tr("Cancelling after the current iteration…"));
}

bool RunController::running() const {
  return runner_->running();
}

bool RunController::wait(int timeout_ms) {
  if (!running()) return true;
  // A nested event loop that sleeps between events (no busy polling competing with the worker).
  QEventLoop loop;
  connect(this, &RunController::finished, &loop, &QEventLoop::quit);
  QTimer::singleShot(timeout_ms, &loop, &QEventLoop::quit);
  loop.exec();
  return !running();
}

bool RunController::show_run(int index, QString* error) {
  try {
    context_.workspace().show_run(index >= 0 ? std::optional<int>(index) : std::nullopt);
  } catch (const std::out_of_range&) {
    show_list();  // back to what is shown
    return context_.fail(tr("Cannot show the run"),
                         tr("That run failed and has no motion to show."), error);
  }
  return true;
}

void RunController::on_finished(int tag, bool ok, const QString& error) {
  panel_->set_running(false);
  std::optional<OptimizationResult> result = runner_->take_result();
  Workspace& ws = context_.workspace();
  update_actions();
  context_.status(QString(), 1);
  if (tag != ws.generation()) {
    // The motion changed while optimising (another file, an edit): the run belongs to a motion
    // no longer shown.
    panel_->show_message(tr("The motion changed during the run; its result was set aside."));
    emit finished(false);
    return;
  }
  RunRecord record;
  record.settings = running_settings_;
  record.options = running_options_;
  if (ok && result) record.result = std::make_shared<const OptimizationResult>(std::move(*result));
  record.error = error.toStdString();
  const int index = ws.add_run(std::move(record));
  const RunRecord& run = ws.runs().at(index);
  if (!run.result) {
    const QString message = tr("Run %1 failed: %2").arg(run.number).arg(error);
    panel_->show_message(message);
    if (context_.interactive())
      QMessageBox::critical(context_.window(), tr("Optimisation failed"), message);
    else
      qWarning("saltus-gui: the optimisation failed: %s", qPrintable(error));
    emit finished(false);
    return;
  }
  const OptimizationResult& r = *run.result;
  // The joints' verdict beside the root force: a run that zeroes the root force by making a
  // joint carry many times its input load is not physics to read as the athlete's. In the
  // words of `saltus optimize`. Then the one verdict it prints (use_cases/athlete_verdict.h):
  // whether the optimised motion lands within the athlete's strength, so that a run within its
  // joint policy that asks more than the athlete's muscles give does not read as a success.
  const JointLoadRise& rise = run.standing.largest_rise;
  QString joints =
      rise.joint.empty()
          ? QString()
          : tr(" Joints: %1.").arg(QString::fromStdString(joint_load_verdict_words(rise)));
  QString verdict;  // in a few words for the status bar, where a long line is cut
  try {
    const Document& d = ws.document();
    const AthleteVerdict v = athlete_verdict(d.file(), d.evaluate_options(), r);
    joints += tr(" Can this athlete land it? %1.").arg(QString::fromStdString(v.headline));
    verdict = tr(" %1 (Optimise panel).").arg(QString::fromStdString(v.summary));
  } catch (const std::exception&) {
    // Options the library refuses: the run itself says what went wrong.
  }
  const QString forces = tr("Run %1 %2 after %3 iterations in %4 s: average root force %5 → %6.")
                             .arg(run.number)
                             .arg(QString::fromStdString(status_text(r.solve.status)))
                             .arg(r.solve.iterations)
                             .arg(r.solve.seconds, 0, 'f', 1)
                             .arg(newtons(r.before.metrics.avg_root_force))
                             .arg(newtons(r.after.metrics.avg_root_force));
  const QString outcome = forces + joints;
  QString where;
  if (ws.shown_run() == index) {
    where = tr(" Shown now (View > After).");
  } else if (ws.shown_run()) {
    const RunRecord& kept = ws.runs().at(*ws.shown_run());
    where = tr(" Run %1 (%2, %3%4) stays shown: it ranks higher; choose run %5 in the list to "
               "see this one.")
                .arg(kept.number)
                .arg(QString::fromStdString(status_text(kept.result->solve.status)))
                .arg(newtons(kept.result->after.metrics.avg_root_force))
                .arg(kept.standing.joints_within_policy ? tr(", joints within their policy")
                                                        : QString())
                .arg(run.number);
  } else {
    where = tr(" Not better than the interpolated keyframes; choose it in the list to see it.");
  }
  panel_->show_message(outcome + where);
  context_.status(forces + verdict, 10000);
  emit finished(true);
}

void RunController::load_settings(const QSettings& s) {
  panel_->set_settings(
      settings_from_entries([&s](const std::string& key) -> std::optional<std::string> {
        const QString k = QString::fromStdString(key);
        if (!s.contains(k)) return std::nullopt;
        return s.value(k).toString().toStdString();
      }));
}

void RunController::save_settings(QSettings& s) const {
  for (const auto& [key, text] : settings_entries(panel_->settings()))
    s.setValue(QString::fromStdString(key), QString::fromStdString(text));
}

}  // namespace saltus::gui
