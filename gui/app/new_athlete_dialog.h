#pragma once
/// @file
/// Model > New athlete…: a body model of a particular athlete from height, mass and sex (de Leva,
/// `saltus model new`) or from a file of Yeadon's measurements (`saltus model yeadon`), made by
/// the library as the fields change (core/athletes.h). The athlete is drawn standing beside the
/// model in use, on one scale, with a line of its figures; a value the library refuses shows
/// its message and disables the buttons. With a motion open: "Can this athlete land it?"
/// (core/athlete_landing.h) — the open motion's take-off flown by the new body and by the one
/// in use, both drawn at landing side by side, the verdict first, the joints against the new
/// athlete's strength. The dialog only asks: AthleteController saves the model and uses it or
/// compares with it.

#include <QDialog>
#include <QImage>
#include <memory>
#include <optional>
#include <vector>

#include "core/athlete_landing.h"
#include "core/athletes.h"

class QButtonGroup;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QRadioButton;
class QTimer;
class QWidget;

namespace saltus::gui {

class VtkImageWidget;
class StandingFigures;

class NewAthleteDialog : public QDialog {
  Q_OBJECT

 public:
  /// `open`: the open motion on the model in use (null: none open), whose model is drawn in
  /// grey beside the new athlete and whose take-off the new athlete flies (with `options`);
  /// with it "Save and compare…" is offered.
  NewAthleteDialog(const MotionFile* open, const EvaluateOptions& options,
                   QWidget* parent = nullptr);
  ~NewAthleteDialog() override;

  /// What the fields ask for now, and the library's model of it (or its message).
  AthleteRequest request() const;
  const AthleteDraft& draft() const { return draft_; }

  /// The preview as drawn now.
  QImage grab_preview();
  /// The landing preview (both free flights at landing) as drawn now.
  QImage grab_landing();
  /// "Can this athlete land it?" for the athlete of the fields, worked out now (tests; the
  /// dialog works it out a moment after the fields stop changing). Null without a motion or a
  /// valid athlete.
  const AthleteLanding* landing();
  /// Its headline and the rest of its words as shown.
  QString landing_headline() const;
  QString landing_details() const;
  /// The heights of the figures drawn (m): the new athlete's first.
  std::vector<double> preview_heights() const;

  // The fields and buttons (tests type into them).
  QLineEdit* name_edit() const { return name_; }
  QRadioButton* size_choice() const { return from_size_; }
  QRadioButton* yeadon_choice() const { return from_yeadon_; }
  QDoubleSpinBox* height_box() const { return height_; }
  QDoubleSpinBox* mass_box() const { return mass_; }
  QComboBox* sex_box() const { return sex_; }
  QLineEdit* measurements_edit() const { return measurements_; }
  QComboBox* densities_box() const { return densities_; }
  QDoubleSpinBox* yeadon_mass_box() const { return yeadon_mass_; }
  QPushButton* use_button() const { return use_; }
  QPushButton* compare_button() const { return compare_; }
  /// The library's message, empty when the athlete is fine.
  QString problem() const;
  /// The figures line under the preview.
  QString figures() const;

 signals:
  /// A button was pressed with a valid athlete: save it, then use it for the open motion
  /// (`compare` false) or compare the open motion on it with the model in use.
  void save_requested(bool compare);

 private:
  void refresh();
  /// Flies the open motion's take-off on the athlete of the fields (a moment after they stop
  /// changing: each flight and evaluation is a tenth of a second or so).
  void refresh_landing();

  QLineEdit* name_ = nullptr;
  QRadioButton* from_size_ = nullptr;
  QRadioButton* from_yeadon_ = nullptr;
  QWidget* size_fields_ = nullptr;
  QWidget* yeadon_fields_ = nullptr;
  QDoubleSpinBox* height_ = nullptr;
  QDoubleSpinBox* mass_ = nullptr;
  QComboBox* sex_ = nullptr;
  QLineEdit* measurements_ = nullptr;
  QComboBox* densities_ = nullptr;
  QDoubleSpinBox* yeadon_mass_ = nullptr;
  VtkImageWidget* preview_ = nullptr;
  std::unique_ptr<StandingFigures> figures_;
  QLabel* figures_line_ = nullptr;
  QPlainTextEdit* warnings_ = nullptr;
  QLabel* problem_ = nullptr;
  QPushButton* use_ = nullptr;
  QPushButton* compare_ = nullptr;
  std::optional<BodyModel> current_;
  std::optional<MotionFile> open_;
  EvaluateOptions options_;
  bool can_compare_ = false;
  AthleteDraft draft_;
  VtkImageWidget* landing_view_ = nullptr;
  std::unique_ptr<StandingFigures> landing_figures_;
  QLabel* landing_title_ = nullptr;
  QLabel* landing_headline_ = nullptr;
  QLabel* landing_details_ = nullptr;
  QTimer* landing_timer_ = nullptr;
  /// The open motion as it flies on the model in use, worked out once.
  std::optional<AthleteLanding> current_landing_;
  std::optional<AthleteLanding> landing_;
  bool landing_stale_ = true;
};

}  // namespace saltus::gui
