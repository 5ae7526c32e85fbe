#include "app/edit_controller.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QDateTime>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QStringList>
#include <QUndoCommand>
#include <QUndoStack>
#include <QUndoView>
#include <exception>

#include "app/capture_panel.h"
#include "app/keyframe_panel.h"
#include "app/model_panel.h"
#include "app/optimize_panel.h"
#include "app/qt_text.h"
#include "app/run_controller.h"
#include "core/capture_keyframes.h"
#include "core/model_edit.h"
#include "core/motion_edit.h"
#include "saltus/base/input_error.h"
#include "saltus/body/segment_names.h"

namespace saltus::gui {

namespace {

/// Edits of one value closer together than this are one undo step (a slider drag, arrow
/// clicks in a spin box).
constexpr qint64 kMergeWindowMs = 1500;
constexpr int kDocumentEditId = 1;
constexpr int kOptionsEditId = 2;
constexpr int kUndoLimit = 200;

/// An edit of the motion or the model: the workspace before and after, as snapshots.
class DocumentEdit : public QUndoCommand {
 public:
  DocumentEdit(Workspace& workspace, Workspace::Snapshot before, Workspace::Snapshot after,
               const QString& text, const QString& merge_key)
      : workspace_(workspace),
        before_(std::move(before)),
        after_(std::move(after)),
        merge_key_(merge_key),
        stamp_(QDateTime::currentMSecsSinceEpoch()) {
    setText(text);
  }

  void redo() override {
    // The first redo is the edit itself, already made.
    if (first_) {
      first_ = false;
      return;
    }
    workspace_.restore(after_);
  }
  void undo() override { workspace_.restore(before_); }
  int id() const override { return kDocumentEditId; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* next = static_cast<const DocumentEdit*>(other);
    if (merge_key_.isEmpty() || next->merge_key_ != merge_key_ ||
        next->stamp_ - stamp_ > kMergeWindowMs)
      return false;
    after_ = next->after_;
    stamp_ = next->stamp_;
    return true;
  }

 private:
  Workspace& workspace_;
  Workspace::Snapshot before_;
  Workspace::Snapshot after_;
  QString merge_key_;
  qint64 stamp_;
  bool first_ = true;
};

/// The label of the first option that differs (option table order, in lower case as in "Change
/// samples"), for the undo text and merging.
QString changed_option(const OptimizeSettings& a, const OptimizeSettings& b) {
  return QString::fromStdString(first_changed_option(a, b)).toLower();
}

/// A change of the Optimise panel's values.
class OptionsEdit : public QUndoCommand {
 public:
  OptionsEdit(OptimizePanel* panel, const OptimizeSettings& before, const OptimizeSettings& after)
      : panel_(panel),
        before_(before),
        after_(after),
        field_(changed_option(before, after)),
        stamp_(QDateTime::currentMSecsSinceEpoch()) {
    setText(QObject::tr("optimisation option: %1").arg(field_));
  }
  void redo() override {
    if (first_) {
      first_ = false;
      return;
    }
    panel_->set_settings(after_);
  }
  void undo() override { panel_->set_settings(before_); }
  int id() const override { return kOptionsEditId; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* next = static_cast<const OptionsEdit*>(other);
    if (next->field_ != field_ || next->stamp_ - stamp_ > kMergeWindowMs) return false;
    after_ = next->after_;
    stamp_ = next->stamp_;
    return true;
  }

 private:
  OptimizePanel* panel_;
  OptimizeSettings before_, after_;
  QString field_;
  qint64 stamp_;
  bool first_ = true;
};

}  // namespace

EditController::EditController(AppContext& context, RunController& runs, QObject* parent)
    : QObject(parent), context_(context), runs_(runs) {
  stack_ = new QUndoStack(this);
  stack_->setUndoLimit(kUndoLimit);
  undo_ = stack_->createUndoAction(this, tr("&Undo"));
  redo_ = stack_->createRedoAction(this, tr("&Redo"));
  undo_->setShortcut(QKeySequence::Undo);
  // Ctrl+Shift+Z everywhere, and the platform's own (Ctrl+Y on some); each sequence once, or
  // Qt finds the shortcut ambiguous and triggers nothing.
  QList<QKeySequence> redo_keys = {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)};
  for (const QKeySequence& key : QKeySequence::keyBindings(QKeySequence::Redo))
    if (!redo_keys.contains(key)) redo_keys.append(key);
  redo_->setShortcuts(redo_keys);

  keyframe_panel_ = new KeyframePanel(context_.window());
  model_panel_ = new ModelPanel(context_.window());
  model_panel_->set_landing_source([this]() -> std::optional<AthleteLanding> {
    const Workspace& ws = context_.workspace();
    if (!ws.loaded()) return std::nullopt;
    const Document& d = ws.document();
    try {
      return athlete_landing(d.file(), d.evaluate_options(),
                             d.has_optimization() ? &d.optimization() : nullptr);
    } catch (const std::exception&) {
      return std::nullopt;  // a motion the library cannot fly freely: no verdict
    }
  });
  capture_panel_ = new CapturePanel(context_.window());
  connect(capture_panel_, &CapturePanel::frame_toggled, this,
          [this](int f) { toggle_capture_frame(f); });
  connect(capture_panel_, &CapturePanel::automatic_requested, this,
          [this](bool every) { pick_capture_frames(every); });
  connect(keyframe_panel_, &KeyframePanel::keyframe_selected, this, [this](int k) {
    const Workspace& ws = context_.workspace();
    if (ws.loaded() && k < static_cast<int>(ws.document().file().motion.keyframes.size()))
      emit keyframe_chosen(ws.document().file().motion.keyframes[static_cast<std::size_t>(k)].time);
  });
  connect(
      keyframe_panel_, &KeyframePanel::angles_edited, this,
      [this](int k, int s, double x, double y, double z) { set_keyframe_angles(k, s, x, y, z); });
  connect(keyframe_panel_, &KeyframePanel::time_edited, this,
          [this](int k, double t) { set_keyframe_time(k, t); });
  connect(keyframe_panel_, &KeyframePanel::delete_requested, this,
          [this](int k) { delete_keyframe(k); });
  connect(model_panel_, &ModelPanel::factors_edited, this,
          [this](const std::vector<double>& f) { set_mass_factors(f); });
  connect(runs_.panel(), &OptimizePanel::settings_edited, this,
          [this](const OptimizeSettings& before, const OptimizeSettings& after) {
            if (changed_option(before, after).isEmpty()) return;
            // A value that costs minutes or gigabytes is kept (for this and later sessions)
            // only when the user says so.
            const std::vector<std::string> costly = newly_costly_settings(before, after);
            if (!costly.empty() && context_.interactive()) {
              QStringList said;
              for (const std::string& c : costly)
                said << qstr(c);
              const auto answer = QMessageBox::question(
                  context_.window(), tr("Keep a costly setting?"),
                  tr("%1.\n\nKeep it (also for later sessions)?").arg(said.join(".\n")),
                  QMessageBox::Yes | QMessageBox::No, QMessageBox::No);
              if (answer != QMessageBox::Yes) {
                runs_.panel()->set_settings(before);
                return;
              }
            }
            stack_->push(new OptionsEdit(runs_.panel(), before, after));
          });
  context_.workspace().subscribe([this](WorkspaceChange c) { on_workspace(c); });
  on_workspace(WorkspaceChange::kOpened);
}

void EditController::fill_menu(QMenu* edit) {
  edit->addAction(undo_);
  edit->addAction(redo_);
}

QUndoView* EditController::make_history_view(QWidget* parent) {
  auto* view = new QUndoView(stack_, parent);
  view->setEmptyLabel(tr("As opened"));
  return view;
}

void EditController::on_workspace(WorkspaceChange change) {
  const Workspace& ws = context_.workspace();
  if (change == WorkspaceChange::kOpened) {
    // Steps of another motion cannot be undone here; old messages go with them.
    stack_->clear();
    keyframe_panel_->show_problem(QString());
    model_panel_->show_problem(QString());
    capture_panel_->show_problem(QString());
  }
  if (change == WorkspaceChange::kOpened || change == WorkspaceChange::kEdited) {
    capture_panel_->set_document(ws.loaded() ? &ws.document() : nullptr);
    // A motion just opened is shown from t = 0: its first keyframe is the one selected.
    keyframe_panel_->set_motion(ws.loaded() ? &ws.document().file().motion : nullptr,
                                ws.loaded() ? &ws.document().file().model : nullptr,
                                change == WorkspaceChange::kOpened);
    model_panel_->set_model(ws.loaded() ? &ws.document().loaded_model() : nullptr,
                            ws.loaded() ? &ws.document().file().model : nullptr);
  }
  if (change != WorkspaceChange::kSaved && change != WorkspaceChange::kStage)
    model_panel_->landing_changed();
}

bool EditController::apply(const QString& text, const QString& merge_key, Source source,
                           const std::function<void(Workspace&)>& edit, QString* error) {
  Workspace& ws = context_.workspace();
  if (!ws.loaded()) return context_.fail(tr("Nothing to edit"), tr("Open a motion first."), error);
  QString problem;
  try {
    Workspace::Snapshot before = ws.snapshot();
    // A run of the motion being edited would belong to the old version.
    if (runs_.running()) runs_.cancel();
    edit(ws);
    stack_->push(new DocumentEdit(ws, std::move(before), ws.snapshot(), text, merge_key));
  } catch (const InputError& e) {
    problem = qstr(e.what());
  } catch (const std::exception& e) {
    problem = qstr(e.what());
  }
  if (!problem.isEmpty()) {
    // No dialog: edits come from sliders and spin boxes; the panel says what is wrong and shows
    // the values in force again.
    switch (source) {
      case Source::kKeyframes:
        keyframe_panel_->set_motion(&ws.document().file().motion, &ws.document().file().model);
        keyframe_panel_->show_problem(problem);
        break;
      case Source::kModel:
        model_panel_->set_model(&ws.document().loaded_model(), &ws.document().file().model);
        model_panel_->show_problem(problem);
        break;
      case Source::kCapture:
        capture_panel_->show_problem(problem);
        break;
    }
    if (error) *error = problem;
    return false;
  }
  keyframe_panel_->show_problem(QString());
  model_panel_->show_problem(QString());
  capture_panel_->show_problem(QString());
  return true;
}

bool EditController::set_keyframe_angles(int keyframe, int segment, double x_deg, double y_deg,
                                         double z_deg, QString* error) {
  const Workspace& ws = context_.workspace();
  QString joint;
  if (ws.loaded() && segment >= 0 && segment < ws.document().file().model.size())
    joint = qstr(
        joint_label(ws.document().file().model.segments[static_cast<std::size_t>(segment)].joint));
  return apply(
      tr("%1 at keyframe %2").arg(joint).arg(keyframe + 1),
      QString("angles %1 %2").arg(keyframe).arg(segment), Source::kKeyframes,
      [&](Workspace& w) {
        const MotionFile& f = w.document().file();
        w.set_motion(with_joint_angles(f.motion, f.model, keyframe, segment,
                                       Eigen::Vector3d(x_deg, y_deg, z_deg)));
      },
      error);
}

bool EditController::set_keyframe_time(int keyframe, double t, QString* error) {
  return apply(
      tr("time of keyframe %1").arg(keyframe + 1), QString("time %1").arg(keyframe),
      Source::kKeyframes,
      [&](Workspace& w) {
        const MotionFile& f = w.document().file();
        w.set_motion(with_keyframe_time(f.motion, f.model, keyframe, t));
      },
      error);
}

bool EditController::add_keyframe(double t, QString* error) {
  const bool ok = apply(
      tr("new keyframe at %1 s").arg(t, 0, 'f', 3), QString(), Source::kKeyframes,
      [&](Workspace& w) {
        const Document& d = w.document();
        // The pose of the motion as shown (interpolated or optimised) at t.
        w.set_motion(
            with_keyframe_added(d.file().motion, d.file().model, t, d.sample_at(w.stage(), t)));
      },
      error);
  if (ok) {
    const std::vector<Keyframe>& k = context_.workspace().document().file().motion.keyframes;
    for (std::size_t i = 0; i < k.size(); ++i)
      if (k[i].time == t) keyframe_panel_->select(static_cast<int>(i), -1);
  }
  return ok;
}

bool EditController::delete_keyframe(int keyframe, QString* error) {
  return apply(
      tr("deleted keyframe %1").arg(keyframe + 1), QString(), Source::kKeyframes,
      [&](Workspace& w) {
        const MotionFile& f = w.document().file();
        w.set_motion(with_keyframe_deleted(f.motion, f.model, keyframe));
      },
      error);
}

bool EditController::set_mass_factors(const std::vector<double>& factors, QString* error) {
  const Workspace& ws = context_.workspace();
  // Name the segment that changed (the one differing from the current model), for the undo text.
  QString what = tr("masses");
  QString key;
  if (ws.loaded()) {
    const BodyModel& loaded = ws.document().loaded_model();
    const BodyModel& current = ws.document().file().model;
    for (std::size_t i = 0; i < factors.size() && i < current.segments.size(); ++i) {
      if (std::abs(factors[i] * loaded.segments[i].mass - current.segments[i].mass) > 1e-12) {
        what = tr("mass of the %1").arg(qstr(segment_label(current.segments[i].name)));
        key = QString("mass %1").arg(i);
        break;
      }
    }
  }
  return apply(
      what, key, Source::kModel,
      [&](Workspace& w) {
        w.set_model(model_with_mass_factors(w.document().loaded_model(), factors));
      },
      error);
}

bool EditController::toggle_capture_frame(int frame, QString* error) {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded() || !ws.document().capture())
    return context_.fail(tr("No capture"), tr("Import a motion capture first."), error);
  const CaptureFile& capture = *ws.document().capture();
  const std::vector<int> picked = capture_frames_in(ws.document().file().motion, capture);
  const bool adding = std::find(picked.begin(), picked.end(), frame) == picked.end();
  return apply(
      adding ? tr("captured frame %1 added as a keyframe").arg(frame + 1)
             : tr("captured frame %1 no longer a keyframe").arg(frame + 1),
      QString(), Source::kCapture,
      [&](Workspace& w) {
        const MotionFile& f = w.document().file();
        w.set_motion(with_capture_frame_toggled(f.motion, f.model, capture, frame));
      },
      error);
}

bool EditController::pick_capture_frames(bool every_frame, QString* error) {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded() || !ws.document().capture())
    return context_.fail(tr("No capture"), tr("Import a motion capture first."), error);
  const CaptureFile& capture = *ws.document().capture();
  return apply(
      every_frame ? tr("every captured frame a keyframe") : tr("keyframes picked automatically"),
      QString(), Source::kCapture,
      [&](Workspace& w) {
        const MotionFile& f = w.document().file();
        w.set_motion(with_capture_frames(f.motion, f.model, capture,
                                         automatic_capture_frames(capture, every_frame)));
      },
      error);
}

namespace {

/// The text field of a spin box or line edit (null for other widgets).
QLineEdit* text_field_of(QObject* object) {
  if (auto* edit = qobject_cast<QLineEdit*>(object)) return edit;
  if (auto* box = qobject_cast<QAbstractSpinBox*>(object)) return box->findChild<QLineEdit*>();
  return nullptr;
}

}  // namespace

void EditController::route_undo_keys(QWidget* root) {
  // A field's "modified" flag says a value is being typed; committing the value clears it.
  for (QAbstractSpinBox* box : root->findChildren<QAbstractSpinBox*>()) {
    box->installEventFilter(this);
    connect(box, &QAbstractSpinBox::editingFinished, this, [box] {
      if (QLineEdit* edit = text_field_of(box)) edit->setModified(false);
    });
  }
  for (QLineEdit* edit : root->findChildren<QLineEdit*>()) {
    if (qobject_cast<QAbstractSpinBox*>(edit->parentWidget())) continue;  // the box has it
    edit->installEventFilter(this);
    connect(edit, &QLineEdit::editingFinished, this, [edit] { edit->setModified(false); });
  }
}

bool EditController::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() == QEvent::ShortcutOverride) {
    const auto* key = static_cast<QKeyEvent*>(event);
    const QKeySequence pressed(static_cast<int>(key->modifiers() & ~Qt::KeypadModifier) |
                               key->key());
    const bool undo_or_redo =
        undo_->shortcuts().contains(pressed) || redo_->shortcuts().contains(pressed);
    const QLineEdit* field = text_field_of(watched);
    if (undo_or_redo && field && !field->isModified()) {
      // Not claimed by the field: the window's Undo or Redo shortcut acts.
      event->ignore();
      return true;
    }
  }
  return QObject::eventFilter(watched, event);
}

bool EditController::can_undo() const {
  return stack_->canUndo();
}

bool EditController::can_redo() const {
  return stack_->canRedo();
}

void EditController::undo() {
  stack_->undo();
}

void EditController::redo() {
  stack_->redo();
}

}  // namespace saltus::gui
