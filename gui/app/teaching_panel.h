#pragma once
/// @file
/// The teaching view: for the moment shown, why the body spins as it does — the angular
/// momentum L about the centre of mass cannot change in the air, the moment of inertia I changes
/// with the shape, so the spin follows as ω = I⁻¹·L — next to the sanity checks of a flight (the
/// CoM on its parabola, the angular momentum's drift since take-off, the flight time that the
/// take-off velocity implies), and a chart of the rotation quantities over the flight. Every
/// number is the library's (rotation_metrics, flight_checks); this panel words them.

#include <QWidget>

#include "app/app_context.h"

class QComboBox;
class QLabel;

namespace saltus::gui {

class ChartWidget;

class TeachingPanel : public QWidget {
  Q_OBJECT

 public:
  TeachingPanel(AppContext& context, QWidget* parent = nullptr);

  /// Re-reads the workspace (new motion, edit, other run or stage).
  void refresh();
  /// The explanation for time t.
  void set_time(double t);
  ChartWidget* chart() const { return chart_; }
  QComboBox* quantity() const { return quantity_; }
  /// The explanation as shown (tests).
  QString text() const;

 signals:
  void seek_requested(double t);

 private:
  void refresh_chart();

  AppContext& context_;
  QLabel* explanation_ = nullptr;
  QLabel* checks_ = nullptr;
  QComboBox* quantity_ = nullptr;
  ChartWidget* chart_ = nullptr;
  double time_ = 0.0;
};

}  // namespace saltus::gui
