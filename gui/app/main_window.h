#pragma once
/// @file
/// The main window: the 3D view with the timeline under it, the plots (root force and moment
/// before/after, joint loads, rotation for teaching), the display and optimisation panels, menus
/// with file handling (open, drag and drop, recent files, save result, PNG export) and remembered
/// settings. Qt types only in this header: tests and batch mode include it.

#include <QElapsedTimer>
#include <QImage>
#include <QMainWindow>
#include <QStringList>
#include <array>
#include <string>

#include "core/document.h"
#include "core/optimize_settings.h"
#include "core/plot_series.h"
#include "core/scene_options.h"

class QAction;
class QCheckBox;
class QComboBox;
class QLabel;
class QMenu;
class QTabWidget;

namespace saltus::gui {

class ChartWidget;
class OptimizationRunner;
class OptimizePanel;
class SceneWidget;
class TimelineWidget;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  /// @param interactive  read and write the user's settings (QSettings) and show dialogs for
  ///                     errors that arrive later (a failed optimisation). Batch mode and tests
  ///                     pass false: their pictures must not depend on what a user did before,
  ///                     and nobody is there to close a dialog (such errors go to stderr).
  explicit MainWindow(bool interactive = true, QWidget* parent = nullptr);
  ~MainWindow() override;

  // The operations behind the menus, also used by batch mode and tests. Each returns false on
  // failure; with `error` null the message is shown in a dialog, else it is stored there.

  /// Opens a motion file (and the model it names, or the model opened before).
  bool open_motion(const QString& path, QString* error = nullptr);
  /// Uses this model file for the open motion (reloading it) and for motions opened later.
  bool open_model(const QString& path, QString* error = nullptr);
  /// Writes the CLI's output folder: `saltus optimize`'s after an optimisation, else `evaluate`'s.
  bool save_result(const QString& dir, QString* error = nullptr);
  /// The 3D view as PNG.
  bool export_view_png(const QString& path, QString* error = nullptr);
  /// The whole window as PNG.
  bool export_window_png(const QString& path, QString* error = nullptr);
  /// Every plot as PNG (1400×700) into `dir`; the file names written go to `written`.
  bool export_plots(const QString& dir, QStringList* written = nullptr, QString* error = nullptr);
  /// Starts optimising the open motion in the background.
  bool start_optimization(const OptimizeSettings& settings, QString* error = nullptr);
  void cancel_optimization();
  bool optimization_running() const;
  /// Keeps the event loop running until the optimisation ends or `timeout_ms` pass; returns
  /// whether it ended.
  bool wait_for_optimization(int timeout_ms);

  void seek(double t);
  double time() const;
  /// Which version the 3D view shows (kAfter only once optimised).
  void set_stage(Stage stage);
  Stage stage() const { return stage_; }
  void set_camera(CameraPreset preset);
  void set_scene_options(const SceneOptions& options);
  const Document& document() const { return document_; }
  /// The optimisation panel's current values.
  OptimizeSettings optimize_settings() const;

  /// The 3D view's current picture.
  QImage grab_view();
  /// Pins the 3D view to a size in pixels (pictures comparable across layouts); an empty size
  /// releases it.
  void fix_view_size(const QSize& size);
  QImage grab_window();
  /// Plays the motion for `seconds` of wall time; returns the 3D view's frames per second
  /// (new pictures of the 3D view that reached the screen).
  double benchmark_playback(double seconds);
  /// 3D renders during the last benchmark (>= its frames; more means renders never shown).
  int benchmark_renders() const { return scene_renders_; }

 signals:
  void motion_opened();
  void optimization_finished(bool ok);

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void build_ui();
  void build_menus();
  void load_settings();
  void save_settings() const;

  /// Everything shown after the document changed (open, optimisation done).
  void refresh_all(bool fit_camera);
  void refresh_root_charts();
  void refresh_joint_chart();
  void refresh_rotation_chart();
  void on_time_changed(double t);
  void update_cursors();
  void on_optimization_progress(const ProgressInfo& info);
  void on_optimization_finished(int tag, bool ok, const QString& error);
  void update_actions();
  void add_recent(const QString& path);
  void rebuild_recent_menu();
  bool fail(const QString& title, const QString& message, QString* error);
  QString ask_open_file(const QString& title, const QString& filter);

  bool interactive_;
  Document document_;
  Stage stage_ = Stage::kBefore;
  std::string model_override_;  ///< model file chosen with "Open model", else ""
  int generation_ = 0;          ///< changes with every opened motion: tags optimisation runs
  OptimizeOptions running_options_;
  QString last_dir_;
  QStringList recent_;
  int frames_drawn_ = 0;
  bool scene_rendered_ = false;
  int scene_renders_ = 0;

  SceneWidget* scene_ = nullptr;
  TimelineWidget* timeline_ = nullptr;
  QTabWidget* plots_ = nullptr;
  ChartWidget* force_chart_ = nullptr;
  ChartWidget* moment_chart_ = nullptr;
  ChartWidget* joint_chart_ = nullptr;
  ChartWidget* rotation_chart_ = nullptr;
  std::array<QCheckBox*, 6> component_boxes_{};
  QComboBox* joint_combo_ = nullptr;
  QComboBox* rotation_combo_ = nullptr;
  OptimizePanel* optimize_panel_ = nullptr;
  OptimizationRunner* runner_ = nullptr;
  QLabel* status_label_ = nullptr;

  QMenu* recent_menu_ = nullptr;
  QAction* save_action_ = nullptr;
  QAction* export_view_action_ = nullptr;
  QAction* export_plots_action_ = nullptr;
  QAction* export_window_action_ = nullptr;
  QAction* play_action_ = nullptr;
  QAction* run_action_ = nullptr;
  QAction* cancel_action_ = nullptr;
  QAction* before_action_ = nullptr;
  QAction* after_action_ = nullptr;
  std::array<QAction*, 4> camera_actions_{};
  std::array<QAction*, 8> option_actions_{};
};

}  // namespace saltus::gui
