#pragma once
/// @file
/// The main window: it lays out the 3D view with the timeline, the plots and the docked panels,
/// builds the menus and the toolbar, and hands each job to its part (one class each): files
/// (FileController), edits with the undo stack (EditController), optimisation runs and the
/// result list (RunController), the 3D view (ViewController), playback (PlaybackController), the
/// plots (PlotsPanel), compare (CompareController), studies (StudyController), where the twist
/// comes from (TwistPanel), what if the tuck were another (WhatIfPanel). All of them share the
/// workspace through the AppContext; settings are remembered by every part that has any. Qt types
/// only in this header: tests and batch mode include it.

#include <QImage>
#include <QMainWindow>
#include <memory>
#include <vector>

#include "app/app_context.h"
#include "core/optimize_settings.h"
#include "core/scene_options.h"

class QDockWidget;

namespace saltus::gui {

class AthleteController;
class CompareController;
class StudyController;
class EditController;
class FileController;
class PlaybackController;
class PlotsPanel;
class RunController;
class SceneWidget;
class TimelineWidget;
class TwistPanel;
class VideoExporter;
class ViewController;
class WhatIfPanel;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  /// @param interactive  read and write the user's settings (QSettings) and show dialogs.
  ///                     Batch mode and tests pass false: their pictures must not depend on
  ///                     what a user did before, and nobody is there to answer a dialog
  ///                     (errors go to stderr; unsaved work is discarded without asking).
  explicit MainWindow(bool interactive = true, QWidget* parent = nullptr);
  ~MainWindow() override;

  AppContext& context() { return *context_; }
  Workspace& workspace() { return context_->workspace(); }
  const Document& document() const { return context_->workspace().document(); }

  FileController& files() { return *files_; }
  EditController& edits() { return *edits_; }
  RunController& runs() { return *runs_; }
  ViewController& view() { return *view_; }
  PlaybackController& playback() { return *playback_; }
  PlotsPanel& plots() { return *plots_; }
  CompareController& compare() { return *compare_; }
  AthleteController& athletes() { return *athletes_; }
  StudyController& studies() { return *studies_; }
  VideoExporter& video() { return *video_; }
  TwistPanel& twist() { return *twist_; }
  /// Brings the Twist panel to the front (View > Where does the twist come from?).
  void show_twist_panel();
  WhatIfPanel& what_if() { return *what_if_; }
  /// Brings the What if panel to the front (View > What if…).
  void show_what_if_panel();
  /// Brings the Study panel to the front (a study starts or ends, the status bar's strip).
  void show_study_panel();
  /// Brings the Model panel to the front.
  void show_model_panel();
  QDockWidget* study_dock() const { return study_dock_; }

  // Shortcuts to what batch mode and tests use most.
  bool open_motion(const QString& path, QString* error = nullptr);
  void seek(double t);
  double time() const;
  Stage stage() const { return context_->workspace().stage(); }
  void set_stage(Stage stage);
  void set_camera(CameraPreset preset);
  void set_scene_options(const SceneOptions& options);

  /// The 3D view itself (focus, key presses in tests).
  SceneWidget* view_widget() const { return scene_; }
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
  /// The process's CPU time (every thread: Mesa's software rasteriser draws on threads of its
  /// own) per frame shown during the last benchmark, ms: what a frame costs, less disturbed by
  /// other work on the machine than the frame rate.
  double benchmark_cpu_ms_per_frame() const { return benchmark_cpu_ms_per_frame_; }

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void build_menus();
  void build_docks(QMenu* view_menu);
  void keep_tab_titles_whole();
  void load_settings();
  void save_settings() const;

  std::unique_ptr<AppContext> context_;
  SceneWidget* scene_ = nullptr;
  TimelineWidget* timeline_ = nullptr;
  PlotsPanel* plots_ = nullptr;
  ViewController* view_ = nullptr;
  PlaybackController* playback_ = nullptr;
  RunController* runs_ = nullptr;
  EditController* edits_ = nullptr;
  FileController* files_ = nullptr;
  CompareController* compare_ = nullptr;
  AthleteController* athletes_ = nullptr;
  StudyController* studies_ = nullptr;
  VideoExporter* video_ = nullptr;
  TwistPanel* twist_ = nullptr;
  QDockWidget* twist_dock_ = nullptr;
  WhatIfPanel* what_if_ = nullptr;
  QDockWidget* what_if_dock_ = nullptr;
  QDockWidget* study_dock_ = nullptr;
  QDockWidget* model_dock_ = nullptr;
  /// Parts that remember settings, in the order they are loaded.
  std::vector<RemembersSettings*> remembered_;
  int frames_drawn_ = 0;
  int benchmark_renders_ = 0;
  double benchmark_cpu_ms_per_frame_ = 0.0;
};

}  // namespace saltus::gui
