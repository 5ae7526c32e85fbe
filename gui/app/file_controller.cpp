#include "app/file_controller.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QTemporaryDir>
#include <QToolBar>
#include <exception>
#include <nlohmann/json.hpp>

#include "app/capture_import_dialog.h"
#include "app/playback_controller.h"
#include "app/plots_panel.h"
#include "app/qt_text.h"
#include "app/scene_widget.h"
#include "app/view_controller.h"
#include "core/lecture_figure.h"
#include "core/shown_motion.h"
#include "saltus/base/input_error.h"
#include "saltus/base/resources.h"
#include "saltus/evaluation/residual_measures.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/readable_formats.h"
#include "saltus/use_cases/captures.h"
#include "saltus/use_cases/flight_page.h"
#include "saltus/use_cases/motion_exports.h"
#include "scene/lecture_figure_picture.h"

namespace saltus::gui {

namespace {

constexpr int kMaxRecent = 8;

/// The open dialog's filter for `kind` (formats/readable_formats.h).
QString filter(ReadableKind kind) {
  return qstr(dialog_filter(kind));
}

/// "M1-straight-back-somersault" from ".../M1-straight-back-somersault.motion.json".
QString motion_stem(const std::string& path) {
  return QFileInfo(qstr(path)).completeBaseName().remove(".motion");
}

}  // namespace

FileController::FileController(AppContext& context, ViewController& view,
                               PlaybackController& playback, PlotsPanel& plots, QObject* parent)
    : QObject(parent), context_(context), view_(view), playback_(playback), plots_(plots) {
  QMainWindow* w = context_.window();
  open_ =
      new QAction(w->style()->standardIcon(QStyle::SP_DialogOpenButton), tr("&Open motion…"), this);
  open_->setShortcut(QKeySequence::Open);
  connect(open_, &QAction::triggered, this, [this] {
    const QString path = ask_open_file(tr("Open motion"), filter(ReadableKind::kMotion) + ";;" +
                                                              filter(ReadableKind::kCapture) +
                                                              ";;" + tr("All files (*)"));
    if (!path.isEmpty()) open_motion(path);
  });
  import_capture_ = new QAction(tr("&Import motion capture…"), this);
  import_capture_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
  import_capture_->setToolTip(
      tr("A BVH file onto the body model (as `saltus import`): its flight, take-off state and "
         "picked keyframes; the capture is drawn beside the motion"));
  connect(import_capture_, &QAction::triggered, this, [this] {
    const QString path = ask_open_file(tr("Import motion capture"), filter(ReadableKind::kCapture));
    if (path.isEmpty()) return;
    // The flags of `saltus import` as controls, at their defaults.
    const std::optional<CaptureFileOptions> options =
        capture_settings_(path, CaptureFileOptions{}, 0.0, std::nullopt);
    if (options) import_capture(path, *options);
  });
  save_result_ = new QAction(w->style()->standardIcon(QStyle::SP_DialogSaveButton),
                             tr("&Save result folder…"), this);
  save_result_->setShortcut(QKeySequence::Save);
  save_result_->setToolTip(
      tr("Write what `saltus optimize` writes for the run shown (or `saltus "
         "evaluate` without one)"));
  connect(save_result_, &QAction::triggered, this, [this] { ask_save_result(); });
  save_motion_ = new QAction(tr("Save &motion as…"), this);
  save_motion_->setToolTip(
      tr("The motion on screen: with a run shown, its optimised motion (keyframes at their "
         "optimised times, with its spline); else the keyframes"));
  connect(save_motion_, &QAction::triggered, this, [this] { ask_save_motion(); });
  save_given_ = new QAction(tr("Save &given keyframes as…"), this);
  save_given_->setToolTip(tr("The keyframes as given (or edited), whatever is shown"));
  connect(save_given_, &QAction::triggered, this, [this] { ask_save_given_keyframes(); });
  save_model_ = new QAction(tr("Save body mo&del as…"), this);
  connect(save_model_, &QAction::triggered, this, [this] { ask_save_model(); });
  need_motion_ = {save_result_, save_motion_, save_given_, save_model_};

  status_line_ = new QLabel(w);
  w->statusBar()->addWidget(status_line_, 1);
  context_.workspace().subscribe([this](WorkspaceChange c) { on_workspace(c); });
  prompt_ = [this](const QString& question) {
    if (!context_.interactive()) return DiscardAnswer::kDiscard;
    const auto answer = QMessageBox::question(
        context_.window(), tr("Unsaved work"), question,
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    return answer == QMessageBox::Save      ? DiscardAnswer::kSave
           : answer == QMessageBox::Discard ? DiscardAnswer::kDiscard
                                            : DiscardAnswer::kCancel;
  };
  capture_settings_ = [this](const QString& capture, const CaptureFileOptions& current,
                             double stated,
                             std::optional<double> suggested) -> std::optional<CaptureFileOptions> {
    if (!context_.interactive()) return current;
    CaptureImportDialog settings(capture, current, stated, suggested, context_.window());
    if (settings.exec() != QDialog::Accepted) return std::nullopt;
    return settings.options();
  };
  save_chooser_ = [this](const QString& title, const QString& suggestion, const QString& filter) {
    // Qt's dialog asks before it replaces an existing file.
    return QFileDialog::getSaveFileName(context_.window(), title, suggestion, filter);
  };
}

void FileController::fill_menu(QMenu* file, QAction* new_model,
                               const std::vector<QAction*>& more_exports) {
  QMainWindow* w = context_.window();
  file->addAction(open_);
  file->addAction(import_capture_);
  file->addAction(tr("Open &model…"), this, [this] {
    const QString path = ask_open_file(tr("Open body model"), filter(ReadableKind::kModel));
    if (!path.isEmpty()) open_model(path);
  });
  if (new_model) file->addAction(new_model);
  recent_menu_ = file->addMenu(tr("Open &recent"));
  rebuild_recent_menu();
  file->addSeparator();
  file->addAction(save_result_);
  file->addAction(save_motion_);
  file->addAction(save_given_);
  file->addAction(save_model_);
  file->addSeparator();
  QAction* view_png = file->addAction(tr("Export 3D view as PNG…"), this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        context_.window(), tr("Export 3D view"), QDir(context_.save_dir()).filePath("view.png"),
        tr("PNG (*.png)"));
    if (!path.isEmpty()) export_view_png(path);
  });
  QAction* lecture =
      file->addAction(tr("Export &lecture figure (stroboscopic side view)…"), this, [this] {
        const QString path = choose_save_path(
            tr("Export lecture figure"), QDir(context_.save_dir()).filePath("lecture-figure.png"),
            tr("PNG (*.png)"));
        if (!path.isEmpty()) export_lecture_figure(path, kDefaultStroboscopePoses);
      });
  lecture->setObjectName("export_lecture_figure");
  lecture->setToolTip(
      tr("The flight shown from the side: poses at equal time steps along the centre of mass's "
         "path, each coloured by the whole-body spin rate, with a colour bar and a caption"));
  QAction* plots_png = file->addAction(tr("Export plots as figures…"), this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(
        context_.window(), tr("Export plots into folder"), context_.save_dir());
    if (dir.isEmpty()) return;
    QStringList written;
    if (plots_.export_figures(dir, &written))
      context_.status(tr("Wrote %1 into %2").arg(written.join(", "), dir), 8000);
  });
  QAction* window_png = file->addAction(tr("Export window screenshot…"), this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        context_.window(), tr("Export window"), QDir(context_.save_dir()).filePath("saltus.png"),
        tr("PNG (*.png)"));
    if (!path.isEmpty()) export_window_png(path);
  });
  QAction* web_page = file->addAction(tr("Export web page…"), this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        context_.window(), tr("Export web page"), QDir(context_.save_dir()).filePath("flight.html"),
        tr("Web page (*.html)"));
    if (!path.isEmpty()) export_web_page(path);
  });
  need_motion_.insert(need_motion_.end(), {view_png, lecture, plots_png, window_png, web_page});
  // The motion for other tools: one entry per format the library exports (motion_exports.h).
  QMenu* motion_for = file->addMenu(tr("Export motion as"));
  for (const ExportFormat& format : export_formats()) {
    if (!format.sampled) continue;
    QAction* a = motion_for->addAction(qstr(format.title) + "…", this, [this, format] {
      const bool folder = format.extension.empty();
      const QString path = QFileDialog::getSaveFileName(
          context_.window(), tr("Export motion as %1").arg(qstr(format.title)),
          QDir(context_.last_dir())
              .filePath(qstr("flight" + (folder ? "-" + format.name : format.extension))),
          folder ? tr("Folder (*)") : qstr("*" + format.extension));
      if (!path.isEmpty()) export_motion_as(format.name, path);
    });
    need_motion_.push_back(a);
  }
  for (QAction* a : more_exports) {
    file->addAction(a);
    need_motion_.push_back(a);
  }
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), w, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);
  on_workspace(WorkspaceChange::kSaved);
}

void FileController::fill_toolbar(QToolBar* bar) {
  bar->addAction(open_);
  bar->addAction(save_result_);
}

void FileController::on_workspace(WorkspaceChange change) {
  const Workspace& ws = context_.workspace();
  for (QAction* a : need_motion_)
    a->setEnabled(ws.loaded());
  // "Save given keyframes" only when Save motion would write something else.
  const std::optional<MotionToSave> on_screen = motion_to_save(ws);
  save_given_->setEnabled(on_screen && on_screen->optimised);
  save_motion_->setText(on_screen && on_screen->optimised
                            ? tr("Save optimised &motion (run %1) as…").arg(on_screen->run_number)
                            : tr("Save &motion as…"));
  if (change == WorkspaceChange::kStage) return;
  if (!ws.loaded()) {
    context_.window()->setWindowTitle(tr("Saltus"));
    status_line_->setText(
        tr("Open a motion: File > Open, or drop a *.motion.json (or a .bvh capture) here."));
    return;
  }
  const MotionFile& f = ws.document().file();
  const bool edited = ws.motion_unsaved() || ws.model_unsaved();
  context_.window()->setWindowTitle(
      tr("Saltus — %1%2").arg(qstr(f.motion.name), edited ? tr(" (edited)") : QString()));
  const double force = ws.document().evaluation(Stage::kBefore).metrics.avg_root_force;
  // A saved optimised result (a stored spline) is not "before optimisation".
  const QString what =
      f.motion.spline ? tr("of the optimised trajectory as saved") : tr("before optimisation");
  status_line_->setText(
      tr("%1%2 — model %3 (%4 kg), %5 keyframes, flight %6 s; average root force %7 N "
         "(%8 % of body weight) %9")
          .arg(qstr(f.motion.name), edited ? tr(" (edited)") : QString(), qstr(f.model.name))
          .arg(f.model.total_mass(), 0, 'f', 1)
          .arg(f.motion.keyframes.size())
          .arg(f.motion.flight_time(), 0, 'f', 2)
          .arg(force, 0, 'g', 3)
          .arg(percent_of_body_weight(force, f.model), 0, 'f', 1)
          .arg(what));
  if (change == WorkspaceChange::kOpened) context_.window()->statusBar()->clearMessage();
}

QString FileController::ask_open_file(const QString& title, const QString& filter) {
  return QFileDialog::getOpenFileName(context_.window(), title, context_.last_dir(), filter);
}

bool FileController::confirm_discard(const QString& action) {
  const Workspace& ws = context_.workspace();
  if (!ws.has_unsaved_work()) return true;
  const QString question =
      tr("%1 — %2.\n\nSave before %3?")
          .arg(qstr(ws.document().file().motion.name), qstr(ws.unsaved_summary()), action);
  switch (prompt_(question)) {
    case DiscardAnswer::kDiscard:
      return true;
    case DiscardAnswer::kCancel:
      return false;
    case DiscardAnswer::kSave:
      if (ws.motion_unsaved() && !ask_save_given_keyframes()) return false;
      if (ws.model_unsaved() && !ask_save_model()) return false;
      if (ws.unsaved_runs() > 0 && !ask_save_result()) return false;
      return true;
  }
  return false;
}

bool FileController::open_motion(const QString& path, QString* error) {
  return import_capture(path, CaptureFileOptions{}, error);
}

bool FileController::ask_import_settings() {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded() || !ws.document().capture()) return false;
  const CaptureImport& im = ws.document().capture()->import;
  const QString path = qstr(ws.document().file().path);
  const std::optional<CaptureFileOptions> options = capture_settings_(
      path, ws.document().capture_options(), im.stated_frame_time, im.suggested_frame_time);
  return options && import_capture(path, *options);
}

bool FileController::import_capture(const QString& path, const CaptureFileOptions& options,
                                    QString* error) {
  if (!confirm_discard(tr("opening %1").arg(QFileInfo(path).fileName()))) {
    if (error) *error = tr("Kept the open motion (it has unsaved work).");
    return false;
  }
  Workspace& ws = context_.workspace();
  try {
    // A model chosen with "Open model" applies to every motion opened after it.
    ws.open(path.toStdString(), model_override_, kDefaultSamples, options);
  } catch (const InputError& e) {
    return context_.fail(tr("Cannot open motion"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return context_.fail(tr("Cannot open motion"), path + ": " + qstr(e.what()), error);
  }
  context_.set_last_dir_from(path);
  add_recent(QFileInfo(path).absoluteFilePath());
  emit motion_opened();
  return true;
}

bool FileController::open_model(const QString& path, QString* error) {
  const std::string absolute = QFileInfo(path).absoluteFilePath().toStdString();
  Workspace& ws = context_.workspace();
  try {
    // Validate the model on its own first, so that its own errors are reported as such.
    load_body_model(absolute);
    if (ws.loaded()) {
      if (!confirm_discard(tr("using the model %1").arg(QFileInfo(path).fileName()))) {
        if (error) *error = tr("Kept the open motion (it has unsaved work).");
        return false;
      }
      const double t = playback_.time();
      ws.open(ws.document().file().path, absolute, ws.document().evaluate_options().samples,
              ws.document().capture_options());
      playback_.seek(t);
    }
  } catch (const InputError& e) {
    return context_.fail(tr("Cannot use model"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return context_.fail(tr("Cannot use model"), path + ": " + qstr(e.what()), error);
  }
  // Used for the motions opened from now on, too.
  model_override_ = absolute;
  context_.set_last_dir_from(path);
  context_.status(tr("Model %1 in use").arg(path));
  return true;
}

bool FileController::ask_save_result() {
  const Workspace& ws = context_.workspace();
  const QString suggestion =
      QDir(context_.save_dir()).filePath(motion_stem(ws.document().file().path) + "-result");
  const QString dir = QFileDialog::getSaveFileName(
      context_.window(), tr("Save result folder (created or replaced)"), suggestion, QString(),
      nullptr, QFileDialog::DontConfirmOverwrite);
  return !dir.isEmpty() && save_result(dir);
}

bool FileController::ask_save_motion() {
  return ask_save(motion_to_save(context_.workspace()));
}

bool FileController::ask_save_given_keyframes() {
  return ask_save(given_keyframes_to_save(context_.workspace()));
}

bool FileController::ask_save(const std::optional<MotionToSave>& motion) {
  if (!motion) return report_save_failure(tr("Nothing to save"), tr("Open a motion first."));
  const QString stem = motion_stem(context_.workspace().document().file().path);
  const QString suggestion =
      QDir(context_.save_dir()).filePath(qstr(motion->file_name(stem.toStdString())));
  // The dialog says which motion it writes.
  const QString path = save_chooser_(tr("Save %1").arg(qstr(motion->what)), suggestion,
                                     qstr(save_dialog_filter(ReadableKind::kMotion)));
  if (path.isEmpty()) return false;
  QString error;
  return write_motion(path, *motion, &error) ||
         report_save_failure(tr("Cannot save motion"), error);
}

bool FileController::ask_save_model() {
  if (!context_.workspace().loaded())
    return report_save_failure(tr("Nothing to save"), tr("Open a motion first."));
  const QString path =
      save_chooser_(tr("Save body model"), QDir(context_.save_dir()).filePath("edited-model.json"),
                    filter(ReadableKind::kModel));
  if (path.isEmpty()) return false;
  QString error;
  return save_model(path, &error) || report_save_failure(tr("Cannot save model"), error);
}

bool FileController::report_save_failure(const QString& title, const QString& message) {
  context_.status(tr("Not saved: %1").arg(message), 15000);
  return context_.fail(title, message, nullptr);
}

bool FileController::save_result(const QString& dir, QString* error) {
  Workspace& ws = context_.workspace();
  if (!ws.loaded()) return context_.fail(tr("Nothing to save"), tr("Open a motion first."), error);
  try {
    ws.document().save_result(dir.toStdString());
  } catch (const InputError& e) {
    return context_.fail(tr("Cannot save result"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return context_.fail(tr("Cannot save result"), dir + ": " + qstr(e.what()), error);
  }
  ws.mark_result_saved();
  context_.note_saved(QFileInfo(dir).absolutePath());
  context_.status(tr("Saved %1").arg(dir));
  return true;
}

bool FileController::save_model(const QString& path, QString* error) {
  Workspace& ws = context_.workspace();
  if (!ws.loaded()) return context_.fail(tr("Nothing to save"), tr("Open a motion first."), error);
  try {
    BodyModel model = ws.document().file().model;
    if (ws.model_unsaved()) model.name = QFileInfo(path).completeBaseName().toStdString();
    save_body_model_file(path.toStdString(), model);  // atomic; replaces only a model file
    load_body_model(path.toStdString());              // what was written must load
  } catch (const InputError& e) {
    return context_.fail(tr("Cannot save model"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return context_.fail(tr("Cannot save model"), path + ": " + qstr(e.what()), error);
  }
  ws.mark_model_saved();
  context_.note_saved(path);
  context_.status(tr("Saved %1").arg(path));
  return true;
}

bool FileController::save_motion(const QString& path, QString* error) {
  const std::optional<MotionToSave> motion = motion_to_save(context_.workspace());
  if (!motion) return context_.fail(tr("Nothing to save"), tr("Open a motion first."), error);
  return write_motion(path, *motion, error);
}

bool FileController::save_given_keyframes(const QString& path, QString* error) {
  const std::optional<MotionToSave> motion = given_keyframes_to_save(context_.workspace());
  if (!motion) return context_.fail(tr("Nothing to save"), tr("Open a motion first."), error);
  return write_motion(path, *motion, error);
}

bool FileController::write_motion(const QString& path, const MotionToSave& what, QString* error) {
  Workspace& ws = context_.workspace();
  const Document& d = ws.document();
  QString outside_model;  // the model's path when it lies outside the motion's folder
  try {
    Motion motion = what.motion;
    // The model the document shows, named so that the saved file finds it again: a bundled
    // name, or a path relative to where the motion is saved.
    const std::string model_file = !d.model_override().empty()
                                       ? d.model_override()
                                       : resolve_model_path(motion.model, d.file().path);
    ModelReference reference{motion.model, true};
    if (!model_file.empty()) reference = model_reference_for(model_file, path.toStdString());
    motion.model = reference.field;
    save_motion_file(path.toStdString(), motion, d.file().model);  // atomic, as the CLI writes
    // Read back through the library: what was written must load as this motion.
    load_motion_file(path.toStdString(), reference.loads_by_itself ? "" : model_file);
    if (!reference.loads_by_itself) outside_model = qstr(reference.field);
  } catch (const InputError& e) {
    return context_.fail(tr("Cannot save motion"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return context_.fail(tr("Cannot save motion"), path + ": " + qstr(e.what()), error);
  }
  // The edits are saved when the keyframes are; an optimised motion is a run's result.
  if (!what.optimised) ws.mark_motion_saved();
  context_.note_saved(path);
  const QString saved = tr("Saved %1 to %2").arg(qstr(what.what), path);
  if (outside_model.isEmpty()) {
    context_.status(saved);
  } else {
    // Motion files may only name models beside them (docs/safety.md): say what reopening needs.
    context_.status(tr("%1. Its model %2 lies outside the motion's folder: reopen it with "
                       "File > Open model, or keep the model beside the motion")
                        .arg(saved, outside_model));
  }
  return true;
}

bool FileController::export_view_png(const QString& path, QString* error) {
  view_.scene()->render_refined();
  const QImage image = view_.scene()->picture();
  if (image.isNull() || !image.save(path, "PNG"))
    return context_.fail(tr("Cannot export"), tr("%1: cannot write the image").arg(path), error);
  context_.note_saved(path);
  return true;
}

bool FileController::export_lecture_figure(const QString& path, int poses, QString* error) {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded())
    return context_.fail(tr("Nothing to export"), tr("Open a motion first."), error);
  try {
    write_lecture_figure_png(lecture_figure(ws.document(), ws.stage(), poses), path.toStdString());
  } catch (const std::exception& e) {
    return context_.fail(tr("Cannot export"), qstr(e.what()), error);
  }
  context_.note_saved(path);
  context_.status(tr("Wrote the lecture figure %1").arg(path), 8000);
  return true;
}

bool FileController::export_web_page(const QString& path, QString* error) {
  Workspace& ws = context_.workspace();
  if (!ws.loaded())
    return context_.fail(tr("Nothing to export"), tr("Open a motion first."), error);
  try {
    const QTemporaryDir folder;
    if (!folder.isValid()) throw std::runtime_error("cannot create a temporary folder");
    const Document& d = ws.document();
    std::string source;
    if (d.has_optimization()) {
      source = folder.filePath("run").toStdString();
      d.save_result(source);
    } else {
      Motion motion = d.file().motion;
      motion.model = "model.json";
      source = folder.filePath("motion.motion.json").toStdString();
      save_body_model_file(folder.filePath("model.json").toStdString(), d.file().model);
      save_motion_file(source, motion, d.file().model);
    }
    // The capture the motion was imported from goes beside the athlete as the app draws it:
    // its own trajectory on the model in use (an import folder the page reads).
    std::string capture;
    if (d.capture()) {
      capture = folder.filePath("capture").toStdString();
      write_capture_outputs(capture, capture_on_model(*d.capture(), d.file().model));
    }
    export_flight_page(source, path.toStdString(), capture);
  } catch (const InputError& e) {
    return context_.fail(tr("Cannot export web page"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return context_.fail(tr("Cannot export web page"), path + ": " + qstr(e.what()), error);
  }
  context_.note_saved(path);
  context_.status(tr("Wrote %1").arg(path));
  return true;
}

bool FileController::export_motion_as(const std::string& format, const QString& path,
                                      QString* error) {
  Workspace& ws = context_.workspace();
  if (!ws.loaded())
    return context_.fail(tr("Nothing to export"), tr("Open a motion first."), error);
  try {
    const Document& d = ws.document();
    MotionFile motion = d.file();
    if (d.has_optimization()) motion.motion = d.optimization().optimized_motion;
    export_motion(motion, format, path.toStdString());
  } catch (const InputError& e) {
    return context_.fail(tr("Cannot export"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return context_.fail(tr("Cannot export"), path + ": " + qstr(e.what()), error);
  }
  context_.set_last_dir_from(path);
  context_.status(tr("Wrote %1").arg(path));
  return true;
}

bool FileController::export_window_png(const QString& path, QString* error) {
  view_.scene()->render_refined();
  const QImage image = context_.window()->grab().toImage();
  if (image.isNull() || !image.save(path, "PNG"))
    return context_.fail(tr("Cannot export"), tr("%1: cannot write the image").arg(path), error);
  context_.note_saved(path);
  return true;
}

void FileController::add_recent(const QString& path) {
  recent_.removeAll(path);
  recent_.prepend(path);
  while (recent_.size() > kMaxRecent)
    recent_.removeLast();
  rebuild_recent_menu();
}

void FileController::rebuild_recent_menu() {
  if (!recent_menu_) return;
  recent_menu_->clear();
  for (const QString& path : recent_) {
    recent_menu_->addAction(QFileInfo(path).fileName(), this, [this, path] { open_motion(path); })
        ->setToolTip(path);
  }
  recent_menu_->setEnabled(!recent_.isEmpty());
  if (!recent_.isEmpty()) {
    recent_menu_->addSeparator();
    recent_menu_->addAction(tr("Clear list"), this, [this] {
      recent_.clear();
      rebuild_recent_menu();
    });
  }
}

void FileController::drag_enter(QDragEnterEvent* event) {
  if (!event->mimeData()->hasUrls()) return;
  for (const QUrl& url : event->mimeData()->urls()) {
    const auto kind =
        url.isLocalFile() ? identify_readable(url.toLocalFile().toStdString()) : std::nullopt;
    if (kind == ReadableKind::kMotion || kind == ReadableKind::kModel ||
        kind == ReadableKind::kCapture) {
      event->acceptProposedAction();
      return;
    }
  }
}

void FileController::drop(QDropEvent* event) {
  // A dropped model applies first, so "model + motion" dropped together opens the motion with it.
  QStringList motions;
  for (const QUrl& url : event->mimeData()->urls()) {
    if (!url.isLocalFile()) continue;
    const QString path = url.toLocalFile();
    const auto kind = identify_readable(path.toStdString());
    if (kind == ReadableKind::kModel)
      open_model(path);
    else if (kind == ReadableKind::kMotion || kind == ReadableKind::kCapture)
      motions.append(path);
  }
  if (!motions.isEmpty()) open_motion(motions.first());
  event->acceptProposedAction();
}

void FileController::load_settings(const QSettings& s) {
  context_.set_last_dir(s.value("files/last_dir", QDir::homePath()).toString());
  context_.set_last_saved_dir(s.value("files/last_saved_dir").toString());
  recent_ = s.value("files/recent").toStringList();
  rebuild_recent_menu();
}

void FileController::save_settings(QSettings& s) const {
  s.setValue("files/last_dir", context_.last_dir());
  s.setValue("files/last_saved_dir", context_.last_saved_dir());
  s.setValue("files/recent", recent_);
}

}  // namespace saltus::gui
