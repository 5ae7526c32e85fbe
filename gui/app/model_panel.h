#pragma once
/// @file
/// The mass-parameter table: per segment its mass (kg) and a scale factor relative to the model
/// as loaded, both editable (mass and inertia scale together); reset and save as a new model
/// file. It only asks for edits; the main window makes them through the library.

#include <QWidget>
#include <vector>

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

 signals:
  void factors_edited(const std::vector<double>& factors);
  void save_requested();
  /// New athlete… pressed (AthleteController's dialog).
  void new_athlete_requested();

 private:
  void on_item_changed(QTableWidgetItem* item);

  const BodyModel* loaded_ = nullptr;
  const BodyModel* current_ = nullptr;
  QTableWidget* table_ = nullptr;
  QLabel* total_ = nullptr;
  QPushButton* reset_ = nullptr;
  QPushButton* save_ = nullptr;
  QPushButton* new_athlete_ = nullptr;
  QLabel* problem_ = nullptr;
};

}  // namespace saltus::gui
