#pragma once
/// @file
/// The main window: the 3D view with the timeline under it, the plots (root force and moment
/// before/after, joint loads, rotation for teaching), the display, optimisation, keyframe and
/// model panels, the compare window, menus with file handling (open, drag and drop, recent
/// files, save result, PNG export) and remembered settings. Qt types only in this header: tests
/// and batch mode include it.

#include <QElapsedTimer>
#include <QImage>
#include <QMainWindow>
#include <QPointer>
#include <QStringList>
#include <array>
#include <functional>
#include <memory>
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
class CompareWindow;
class KeyframePanel;
class ModelPanel;
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

  // Compare (a second window; the open motion as shown is the first run). Each loads and
  // evaluates the second run as open_motion / open_model would.
  /// Before vs after of the current optimisation.
  bool compare_before_after(QString* error = nullptr);
  /// The open motion vs another motion file (with the model in use).
  bool compare_with_motion(const QString& path, QString* error = nullptr);
  /// The open motion with its model vs the same motion with this model file.
  bool compare_with_model(const QString& path, QString* error = nullptr);
  /// The open motion vs a `saltus optimize` (or `evaluate`) output folder.
  bool compare_with_folder(const QString& dir, QString* error = nullptr);
  /// The compare window while it is open, else null.
  CompareWindow* compare_window() const;
  void close_compare();

  // Keyframe editing (the Keyframes panel). Each edit goes through the library (checked by its
  // parser, then evaluated); a rejected edit changes nothing and its message is shown in the
  // panel (and stored in `error` if given). Edits drop an optimisation result.
  /// Joint rotation of `segment` at keyframe `keyframe` (0-based) as X-Y-Z Euler angles, degrees.
  bool set_keyframe_angles(int keyframe, int segment, double x_deg, double y_deg, double z_deg,
                           QString* error = nullptr);
  bool set_keyframe_time(int keyframe, double time, QString* error = nullptr);
  /// A keyframe at time t with the pose the shown motion has there.
  bool add_keyframe(double t, QString* error = nullptr);
  bool delete_keyframe(int keyframe, QString* error = nullptr);
  /// Writes the (edited) motion as a motion file and reads it back through the library.
  bool save_motion(const QString& path, QString* error = nullptr);
  KeyframePanel* keyframe_panel() const { return keyframe_panel_; }
  /// Mass factors per segment relative to the model as loaded (the Model panel).
  bool set_mass_factors(const std::vector<double>& factors, QString* error = nullptr);
  /// Writes the model in use as a model file (named after the file) and reads it back.
  bool save_model(const QString& path, QString* error = nullptr);
  ModelPanel* model_panel() const { return model_panel_; }

  void seek(double t);
  double time() const;
  /// Which version the 3D view shows (kAfter only once optimised).
  void set_stage(Stage stage);
  Stage stage() const { return stage_; }
  void set_camera(CameraPreset preset);
  void set_scene_options(const SceneOptions& options);
  /// The joint whose loads the "Joint loads" plot shows: a segment index (the segment below the
  /// joint), -1 without a motion.
  int selected_joint() const;
  /// Shows the loads at a segment's joint in the plots (switching to that tab) and highlights
  /// the segment in the 3D view, as a click on it does; -1 only removes the highlight.
  void pick_segment(int segment);
  /// The segment highlighted in the 3D view (-1: none).
  int highlighted_segment() const;
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
  /// (new pictures of the 3D view painted on the screen).
  double benchmark_playback(double seconds);
  /// 3D renders during the last benchmark (>= its frames; more means renders never shown).
  int benchmark_renders() const { return benchmark_renders_; }

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
  /// Opens (or reuses) the compare window with the open motion as shown against `second`.
  bool show_compare(const QString& first_label, Stage first_stage,
                    std::shared_ptr<const Document> second, const QString& second_label,
                    Stage second_stage, QString* error);
  /// Replaces the motion by make()'s edit; on failure shows the message in the panel.
  bool apply_edit(const std::function<Motion()>& make, QString* error);
  /// After an edit of the motion or the model: everything shown again, at the same time.
  void show_edited();
  /// "M1" or "M1 (optimised)": the open motion at a stage, as a compare label.
  QString stage_label(Stage stage) const;
  /// Loads a second document like open_motion does; false (with the library's message) on error.
  bool load_second(const std::string& motion, const std::string& model, Document* out,
                   QString* error);

  bool interactive_;
  Document document_;
  Stage stage_ = Stage::kBefore;
  std::string model_override_;  ///< model file chosen with "Open model", else ""
  int generation_ = 0;          ///< changes with every opened motion: tags optimisation runs
  OptimizeOptions running_options_;
  QString last_dir_;
  QStringList recent_;
  int frames_drawn_ = 0;
  int benchmark_renders_ = 0;

  SceneWidget* scene_ = nullptr;
  TimelineWidget* timeline_ = nullptr;
  QTabWidget* plots_ = nullptr;
  QWidget* joint_tab_ = nullptr;
  ChartWidget* force_chart_ = nullptr;
  ChartWidget* moment_chart_ = nullptr;
  ChartWidget* joint_chart_ = nullptr;
  ChartWidget* rotation_chart_ = nullptr;
  std::array<QCheckBox*, 6> component_boxes_{};
  QComboBox* joint_combo_ = nullptr;
  QComboBox* rotation_combo_ = nullptr;
  OptimizePanel* optimize_panel_ = nullptr;
  KeyframePanel* keyframe_panel_ = nullptr;
  ModelPanel* model_panel_ = nullptr;
  OptimizationRunner* runner_ = nullptr;
  QLabel* status_label_ = nullptr;
  QPointer<CompareWindow> compare_;

  QMenu* recent_menu_ = nullptr;
  QAction* save_action_ = nullptr;
  QAction* export_view_action_ = nullptr;
  QAction* export_plots_action_ = nullptr;
  QAction* export_window_action_ = nullptr;
  QAction* play_action_ = nullptr;
  QAction* run_action_ = nullptr;
  QAction* cancel_action_ = nullptr;
  QAction* compare_before_after_action_ = nullptr;
  QAction* compare_motion_action_ = nullptr;
  QAction* compare_model_action_ = nullptr;
  QAction* compare_folder_action_ = nullptr;
  QAction* close_compare_action_ = nullptr;
  QAction* before_action_ = nullptr;
  QAction* after_action_ = nullptr;
  std::array<QAction*, 4> camera_actions_{};
  std::array<QAction*, 8> option_actions_{};
};

}  // namespace saltus::gui
