#include "app/athlete_controller.h"

#include <QAction>
#include <QDir>
#include <QPushButton>
#include <exception>

#include "app/compare_controller.h"
#include "app/file_controller.h"
#include "app/new_athlete_dialog.h"
#include "app/qt_text.h"
#include "saltus/base/input_error.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/readable_formats.h"
#include "saltus/use_cases/athlete_models.h"

namespace saltus::gui {

AthleteController::AthleteController(AppContext& context, FileController& files,
                                     CompareController& compare, QObject* parent)
    : QObject(parent), context_(context), files_(files), compare_controller_(compare) {
  new_ = new QAction(tr("New &athlete…"), this);
  new_->setToolTip(
      tr("A body model of one athlete from height, mass and sex, or from Yeadon's measurements; "
         "saved, then used for the open motion"));
  connect(new_, &QAction::triggered, this, [this] { open_dialog(false); });
  compare_ = new QAction(tr("With a &new athlete…"), this);
  compare_->setToolTip(
      tr("The open motion on the model in use and on an athlete made here, side by side"));
  connect(compare_, &QAction::triggered, this, [this] { open_dialog(true); });
  const auto update = [this] { compare_->setEnabled(context_.workspace().loaded()); };
  context_.workspace().subscribe([update](WorkspaceChange) { update(); });
  update();
}

NewAthleteDialog* AthleteController::open_dialog(bool compare) {
  if (dialog_) dialog_->close();
  const Workspace& ws = context_.workspace();
  dialog_ = new NewAthleteDialog(ws.loaded() ? &ws.document().file() : nullptr,
                                 ws.loaded() ? ws.document().evaluate_options() : EvaluateOptions{},
                                 context_.window());
  dialog_->setAttribute(Qt::WA_DeleteOnClose);
  if (compare && ws.loaded()) dialog_->compare_button()->setDefault(true);
  connect(dialog_, &NewAthleteDialog::save_requested, this, [this](bool compare_with) {
    if (!dialog_ || !dialog_->draft().model) return;
    // The dialog stays open when the user cancels the save dialog or saving fails.
    if (save_and_use(*dialog_->draft().model, compare_with)) dialog_->accept();
  });
  dialog_->open();
  return dialog_;
}

NewAthleteDialog* AthleteController::dialog() const {
  return dialog_.data();
}

bool AthleteController::save_and_use(const BodyModel& model, bool compare, QString* error) {
  const QString suggestion = QDir(context_.save_dir()).filePath(qstr(model.name) + ".model.json");
  const QString path = files_.choose_save_path(tr("Save the athlete's body model"), suggestion,
                                               qstr(save_dialog_filter(ReadableKind::kModel)));
  if (path.isEmpty()) {
    if (error) *error = tr("Not saved: no file chosen.");
    return false;
  }
  try {
    write_athlete_model(path.toStdString(), model);
    load_body_model(path.toStdString());  // what was written must load
  } catch (const InputError& e) {
    context_.status(tr("Not saved: %1").arg(qstr(e.what())), 15000);
    return context_.fail(tr("Cannot save model"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    context_.status(tr("Not saved: %1: %2").arg(path, qstr(e.what())), 15000);
    return context_.fail(tr("Cannot save model"), path + ": " + qstr(e.what()), error);
  }
  context_.note_saved(path);
  if (compare) return compare_controller_.compare_with_model(path, error);
  return files_.open_model(path, error);
}

}  // namespace saltus::gui
