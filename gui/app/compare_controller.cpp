#include "app/compare_controller.h"

#include <QAction>
#include <QCoreApplication>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QTimer>

#include "app/compare_window.h"
#include "app/optimization_runner.h"
#include "app/qt_text.h"
#include "app/view_controller.h"
#include "core/athlete_landing.h"
#include "core/athletes.h"
#include "core/compare.h"
#include "saltus/base/input_error.h"
#include "saltus/formats/readable_formats.h"

namespace saltus::gui {

namespace {}  // namespace

CompareController::CompareController(AppContext& context, ViewController& view, QObject* parent)
    : QObject(parent), context_(context), view_(view) {
  runner_ = new OptimizationRunner(this);
  connect(runner_, &OptimizationRunner::finished, this, [this](int tag, bool ok, const QString&) {
    std::optional<OptimizationResult> result = runner_->take_result();
    if (!pending_ || tag != pending_tag_ || window_.isNull()) return;
    if (ok && result) {
      const Workspace& ws = context_.workspace();
      const OptimizeOptions options =
          ws.shown_run() ? ws.runs().at(*ws.shown_run()).options : OptimizeOptions{};
      pending_->set_optimization(std::move(*result), options);
      CompareWindow::Run first = window_->run(0);
      CompareWindow::Run second = window_->run(1);
      second.document = pending_;
      second.stage = Stage::kAfter;
      second.description = tr("optimised with the same settings (%1)")
                               .arg(qstr(status_text(pending_->optimization().solve.status)));
      // The run's warnings join its athlete's verdict, in the words of `saltus optimize`.
      second.landing = landing_of(*pending_, &pending_->optimization());
      window_->set_runs(std::move(first), std::move(second), true);
      window_->set_note(QString());
    } else {
      window_->set_note(
          tr("The second model's optimisation failed; it is shown as "
             "interpolated."));
    }
    pending_.reset();
    emit second_run_ready();
  });
  context_.workspace().subscribe([this](WorkspaceChange) { update_actions(); });
}

CompareController::~CompareController() = default;

void CompareController::fill_menu(QMenu* compare, QAction* new_athlete) {
  before_after_ = compare->addAction(tr("&Before vs after optimisation"), this,
                                     [this] { compare_before_after(); });
  QAction* motion = compare->addAction(tr("With another &motion…"), this, [this] {
    const QString path = QFileDialog::getOpenFileName(context_.window(), tr("Compare with motion"),
                                                      context_.last_dir(),
                                                      qstr(dialog_filter(ReadableKind::kMotion)));
    if (!path.isEmpty()) compare_with_motion(path);
  });
  QAction* model = compare->addAction(tr("With another body m&odel…"), this, [this] {
    const QString path = QFileDialog::getOpenFileName(
        context_.window(), tr("Compare with body model"), context_.last_dir(),
        qstr(dialog_filter(ReadableKind::kModel)));
    if (!path.isEmpty()) compare_with_model(path);
  });
  model->setToolTip(
      tr("The same motion flown by the athlete of another body model (other masses, or another "
         "athlete: the same take-off spin); optimised like the run shown, so the joint loads of "
         "both optimised motions compare (the paper's Fig. 8)"));
  if (new_athlete) compare->addAction(new_athlete);
  QAction* folder = compare->addAction(tr("With a saved &result folder…"), this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(
        context_.window(), tr("Compare with a `saltus optimize` result folder"),
        context_.last_dir());
    if (!dir.isEmpty()) compare_with_folder(dir);
  });
  need_motion_ = {motion, model, folder};
  compare->addSeparator();
  close_ = compare->addAction(tr("&Close compare"), this, &CompareController::close);
  update_actions();
}

void CompareController::update_actions() {
  const Workspace& ws = context_.workspace();
  if (before_after_) before_after_->setEnabled(ws.loaded() && ws.shown_run().has_value());
  for (QAction* a : need_motion_)
    a->setEnabled(ws.loaded());
  if (close_) close_->setEnabled(!window_.isNull());
}

bool CompareController::load_second(const std::string& motion, const std::string& model,
                                    Document* out, QString* error) {
  try {
    out->load(motion, model, context_.workspace().document().evaluate_options().samples);
  } catch (const InputError& e) {
    return context_.fail(tr("Cannot compare"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return context_.fail(tr("Cannot compare"), qstr(motion) + ": " + qstr(e.what()), error);
  }
  return true;
}

QString CompareController::stage_label(Stage stage) const {
  const Workspace& ws = context_.workspace();
  const QString name = qstr(ws.document().file().motion.name);
  if (stage != Stage::kAfter || !ws.shown_run()) return name;
  return tr("%1 (run %2)").arg(name).arg(ws.runs().at(*ws.shown_run()).number);
}

std::optional<AthleteLanding> CompareController::landing_of(const Document& document,
                                                            const OptimizationResult* run) const {
  try {
    return athlete_landing(document.file(), document.evaluate_options(), run);
  } catch (const std::exception& e) {
    context_.status(tr("Cannot fly the free flight: %1").arg(qstr(e.what())), 10000);
  }
  return std::nullopt;
}

QString CompareController::stage_description(Stage stage) const {
  const Workspace& ws = context_.workspace();
  // A saved optimised result (a stored spline) is not "interpolated keyframes".
  if (stage != Stage::kAfter || !ws.shown_run())
    return ws.document().file().motion.spline ? tr("optimised trajectory, as saved")
                                              : tr("interpolated keyframes");
  const RunRecord& run = ws.runs().at(*ws.shown_run());
  return tr("optimised, run %1 (%2)")
      .arg(run.number)
      .arg(qstr(status_text(run.result->solve.status)));
}

bool CompareController::show(const QString& first_label, Stage first_stage,
                             const QString& first_description,
                             std::shared_ptr<const Document> second, const QString& second_label,
                             Stage second_stage, const QString& second_description,
                             QString* error) {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded())
    return context_.fail(tr("Nothing to compare"), tr("Open a motion first."), error);
  // A copy: the compare window keeps showing this run if the main window opens another motion.
  CompareWindow::Run first{first_label, std::make_shared<const Document>(ws.document()),
                           first_stage, first_description, std::nullopt};
  CompareWindow::Run other{second_label, std::move(second), second_stage, second_description,
                           std::nullopt};
  if (window_.isNull()) {
    window_ = new CompareWindow(context_.window());
    window_->setAttribute(Qt::WA_DeleteOnClose);
    connect(window_, &QObject::destroyed, this, [this] { update_actions(); });
  }
  window_->set_scene_options(view_.scene_options());
  window_->set_runs(std::move(first), std::move(other));
  window_->set_note(QString());
  window_->show();
  window_->raise();
  update_actions();
  return true;
}

bool CompareController::compare_before_after(QString* error) {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded() || !ws.shown_run())
    return context_.fail(tr("Nothing to compare"), tr("Run an optimisation first."), error);
  return show(tr("before"), Stage::kBefore, stage_description(Stage::kBefore),
              std::make_shared<const Document>(ws.document()), tr("after"), Stage::kAfter,
              stage_description(Stage::kAfter), error);
}

bool CompareController::compare_with_motion(const QString& path, QString* error) {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded())
    return context_.fail(tr("Nothing to compare"), tr("Open a motion first."), error);
  auto second = std::make_shared<Document>();
  if (!load_second(path.toStdString(), ws.document().model_override(), second.get(), error))
    return false;
  QString label = qstr(second->file().motion.name);
  if (label == qstr(ws.document().file().motion.name)) label = QFileInfo(path).fileName();
  context_.set_last_dir_from(path);
  const QString second_description = second->file().motion.spline
                                         ? tr("optimised trajectory, as saved")
                                         : tr("interpolated keyframes");
  return show(stage_label(ws.stage()), ws.stage(), stage_description(ws.stage()), std::move(second),
              label, Stage::kBefore, second_description, error);
}

bool CompareController::compare_with_model(const QString& path, QString* error) {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded())
    return context_.fail(tr("Nothing to compare"), tr("Open a motion first."), error);
  auto second = std::make_shared<Document>();
  const std::string model = QFileInfo(path).absoluteFilePath().toStdString();
  if (!load_second(ws.document().file().path, model, second.get(), error)) return false;
  // Who flies each ("junior 1.45 m 38 kg, same take-off spin"); the file's name when both
  // models have one name.
  const QString first = qstr(athlete_label(ws.document().file()));
  QString label = qstr(athlete_label(second->file()));
  if (second->file().model.name == ws.document().file().model.name)
    label = QFileInfo(path).fileName() + label.mid(qstr(second->file().model.name).size());
  context_.set_last_dir_from(path);
  // With a run shown, both sides are optimised motions: this one now, the other model's in the
  // background with the same settings (the window shows its interpolation until then).
  const bool optimise = ws.shown_run().has_value();
  const Stage stage = optimise ? Stage::kAfter : Stage::kBefore;
  if (!show(first, stage, stage_description(stage), second, label, Stage::kBefore,
            optimise ? tr("interpolated keyframes (optimising…)") : tr("interpolated keyframes"),
            error))
    return false;
  // Two athletes: can each land it? The free flight of each from the same take-off, and with a
  // run its warnings.
  {
    CompareWindow::Run a = window_->run(0);
    CompareWindow::Run b = window_->run(1);
    a.landing = landing_of(*a.document, optimise && a.document->has_optimization()
                                            ? &a.document->optimization()
                                            : nullptr);
    b.landing = landing_of(*b.document, nullptr);
    window_->set_runs(std::move(a), std::move(b), true);
  }
  if (optimise) {
    if (runner_->running()) runner_->cancel();
    pending_ = second;
    ++pending_tag_;
    // A run of the previous comparison still stopping: start when it has.
    if (runner_->running()) wait(60000);
    runner_->start(second->file(), ws.runs().at(*ws.shown_run()).options, pending_tag_);
    window_->set_note(tr("Optimising the motion flown by %1 like run %2…")
                          .arg(label)
                          .arg(ws.runs().at(*ws.shown_run()).number));
  }
  return true;
}

bool CompareController::compare_with_folder(const QString& dir, QString* error) {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded())
    return context_.fail(tr("Nothing to compare"), tr("Open a motion first."), error);
  FolderRun run;
  try {
    run = folder_run(dir.toStdString());
  } catch (const InputError& e) {
    return context_.fail(tr("Cannot compare"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return context_.fail(tr("Cannot compare"), dir + ": " + qstr(e.what()), error);
  }
  auto second = std::make_shared<Document>();
  if (!load_second(run.motion_path, run.model_path, second.get(), error)) return false;
  context_.set_last_dir_from(QFileInfo(dir).absolutePath());
  return show(stage_label(ws.stage()), ws.stage(), stage_description(ws.stage()), std::move(second),
              qstr(run.label), Stage::kBefore, qstr(run.description), error);
}

bool CompareController::compare_with(const QString& path, QString* error) {
  if (QFileInfo(path).isDir()) return compare_with_folder(path, error);
  if (identify_readable(path.toStdString()) == ReadableKind::kModel)
    return compare_with_model(path, error);
  return compare_with_motion(path, error);
}

CompareWindow* CompareController::window() const {
  return window_.data();
}

void CompareController::close() {
  if (runner_->running()) runner_->cancel();
  pending_.reset();
  if (!window_.isNull()) window_->close();
  // The window deletes itself on close (deferred): finish that now, so window() is null.
  QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
  update_actions();
}

bool CompareController::optimising() const {
  return runner_->running();
}

bool CompareController::wait(int timeout_ms) {
  if (!runner_->running()) return true;
  QEventLoop loop;
  connect(runner_, &OptimizationRunner::finished, &loop, &QEventLoop::quit, Qt::QueuedConnection);
  QTimer::singleShot(timeout_ms, &loop, &QEventLoop::quit);
  loop.exec();
  return !runner_->running();
}

}  // namespace saltus::gui
