#pragma once
/// @file
/// The plots under the 3D view, one tab each: the root force and moment (before and after
/// optimisation), the loads at any joint as a coach reads them (core/joint_load_view.h), every
/// joint's share of the athlete's strength as strips, and the rotation quantities for teaching.
/// Every chart comes from a core chart builder; this panel picks what to show, keeps the time
/// cursors in step and exports the charts as figures.

#include <QStringList>
#include <QTabWidget>
#include <array>

#include "app/app_context.h"

class QCheckBox;
class QComboBox;
class QLabel;

namespace saltus::gui {

class ChartWidget;
class StrengthStrips;
class TeachingPanel;

class PlotsPanel : public QTabWidget, public RemembersSettings {
  Q_OBJECT

 public:
  PlotsPanel(AppContext& context, QWidget* parent = nullptr);

  /// Moves the time cursors (and the teaching panel's numbers) to t.
  void set_time(double t, bool playing);
  /// Shows the loads at a segment's joint (switching to that tab).
  void show_joint(int segment);
  /// The segment whose joint the joint-loads tab shows (-1 without a motion).
  int selected_joint() const;

  /// Every chart as a figure (PNG, titled with the motion and the run's settings) into `dir`;
  /// the file names written go to `written`.
  bool export_figures(const QString& dir, QStringList* written = nullptr, QString* error = nullptr);

  /// The charts as they are now (tests, exported figures).
  std::vector<ChartWidget*> charts() const;
  ChartWidget* force_chart() const { return force_chart_; }
  ChartWidget* moment_chart() const { return moment_chart_; }
  /// The Joint loads tab's charts: the force (N, % of body weight) and the moment (N·m, and its
  /// share of the athlete's strength); its line of peaks and its line on the optimiser's rise.
  ChartWidget* joint_force_chart() const { return joint_force_chart_; }
  ChartWidget* joint_moment_chart() const { return joint_moment_chart_; }
  QString joint_summary() const;
  QString joint_raised() const;
  TeachingPanel* teaching() const { return teaching_; }
  /// The Strength tab: every joint's share of the athlete's strength over the flight.
  StrengthStrips* strength() const { return strength_; }
  /// Components instead of the resultant |F|, |M| (the default, as in the paper's figures).
  void set_show_components(bool components);
  /// Log scale for the magnitudes, so that the small "after" curve shows next to "before".
  void set_log_scale(bool log);

  void load_settings(const QSettings& settings) override;
  void save_settings(QSettings& settings) const override;

 signals:
  void seek_requested(double t);
  /// The joint list's choice changed (to follow it in the 3D view).
  void joint_selected(int segment);

 private:
  void on_workspace(WorkspaceChange change);
  void refresh_root_charts();
  void refresh_joint_chart();
  void refresh_strength();
  void update_cursors();

  AppContext& context_;
  QWidget* joint_tab_ = nullptr;
  ChartWidget* force_chart_ = nullptr;
  ChartWidget* moment_chart_ = nullptr;
  ChartWidget* joint_force_chart_ = nullptr;
  ChartWidget* joint_moment_chart_ = nullptr;
  QLabel* joint_light_ = nullptr;
  QLabel* joint_summary_ = nullptr;
  QLabel* joint_raised_ = nullptr;
  StrengthStrips* strength_ = nullptr;
  TeachingPanel* teaching_ = nullptr;
  QCheckBox* components_ = nullptr;
  std::array<QCheckBox*, 3> axes_{};
  QCheckBox* log_scale_ = nullptr;
  QComboBox* joint_combo_ = nullptr;
  double time_ = 0.0;  ///< where the cursors are, s
};

}  // namespace saltus::gui
