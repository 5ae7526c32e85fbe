#pragma once
/// @file
/// New athlete (File menu, the Model panel's button, Compare menu): the NewAthleteDialog, then
/// the model saved where the user chooses (FileController's save dialog, replaced in tests)
/// with the library's write_athlete_model, and either used for the open motion as File > Open
/// model uses a model (the unsaved-work prompt, a fresh undo history) or compared with the
/// model in use (CompareController::compare_with_model).

#include <QObject>
#include <QPointer>

#include "app/app_context.h"
#include "saltus/body/body_model.h"

class QAction;

namespace saltus::gui {

class CompareController;
class FileController;
class NewAthleteDialog;

class AthleteController : public QObject {
  Q_OBJECT

 public:
  AthleteController(AppContext& context, FileController& files, CompareController& compare,
                    QObject* parent = nullptr);

  /// File > New athlete… (next to Open model).
  QAction* new_action() const { return new_; }
  /// Compare > With a new athlete… (the same dialog).
  QAction* compare_action() const { return compare_; }

  /// Opens the dialog (window-modal, returns at once) and returns it; it closes itself once
  /// its athlete is saved and used or compared, or on Cancel. `compare`: "Save and compare…" is
  /// the default button (opened from the Compare menu).
  NewAthleteDialog* open_dialog(bool compare = false);
  /// The dialog while it is open, else null.
  NewAthleteDialog* dialog() const;

  /// Asks where to save `model`, writes it (write_athlete_model) and reads it back, then uses it
  /// for the open motion or compares with it. False if the user cancelled or it failed (the
  /// message in `error`, else in the status bar and a dialog).
  bool save_and_use(const BodyModel& model, bool compare, QString* error = nullptr);

 private:
  AppContext& context_;
  FileController& files_;
  CompareController& compare_controller_;
  QAction* new_ = nullptr;
  QAction* compare_ = nullptr;
  QPointer<NewAthleteDialog> dialog_;
};

}  // namespace saltus::gui
