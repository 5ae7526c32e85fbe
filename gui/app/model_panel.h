#pragma once
/// @file
/// The mass-parameter table: per segment its mass (kg) and a scale factor relative to the model
/// as loaded, both editable (mass and inertia scale together); reset and save as a new model
/// file. Under it, "Can this athlete land it?" for the model in use (core/athlete_landing.h),
/// worked out while the panel is in view. It only asks for edits; the main window makes them
/// through the library.

#include <QWidget>
#include <functional>
#include <optional>
#include <vector>

#include "core/athlete_landing.h"

#include "saltus/body/body_model.h"

class QLabel;
class QPushButton;
class QTableWidget;
class QTableWidgetItem;

namespace saltus::gui {

class ModelPanel : public QWidget {
  Q_OBJECT

 public:
  explicit ModelPanel(QWidget* parent = nullptr);

  /// Shows `current` with factors relative to `loaded` (both null: nothing open).
  void set_model(const BodyModel* loaded, const BodyModel* current);
  /// The factors the table shows, one per segment.
  std::vector<double> factors() const;
  void show_problem(const QString& message);
  QString problem() const;
  QTableWidget* table() const { return table_; }

  /// Where "Can this athlete land it?" comes from: the open motion on the model in use (with
  /// the run shown), or nothing without a motion.
  using LandingSource = std::function<std::optional<AthleteLanding>()>;
  void set_landing_source(LandingSource source) { landing_source_ = std::move(source); }
  /// The motion, the model or the run changed: worked out again now if the panel is in view,
  /// else when it comes into view.
  void landing_changed();
  /// The verdict and words as shown (tests).
  QString landing_text() const;

 signals:
  void factors_edited(const std::vector<double>& factors);
  void save_requested();
  /// New athlete… pressed (AthleteController's dialog).
  void new_athlete_requested();

 private:
  void on_item_changed(QTableWidgetItem* item);
  void showEvent(QShowEvent* event) override;
  void refresh_landing();

  const BodyModel* loaded_ = nullptr;
  const BodyModel* current_ = nullptr;
  QTableWidget* table_ = nullptr;
  QLabel* total_ = nullptr;
  QPushButton* reset_ = nullptr;
  QPushButton* save_ = nullptr;
  QPushButton* new_athlete_ = nullptr;
  QLabel* problem_ = nullptr;
  QLabel* landing_ = nullptr;
  LandingSource landing_source_;
  bool landing_stale_ = true;
};

}  // namespace saltus::gui
