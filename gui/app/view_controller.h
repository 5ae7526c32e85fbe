#pragma once
/// @file
/// The 3D view's part of the main window: which stage it shows (before / after, B / A), the
/// camera (Side, Front, Top, Follow, Reset: 1-4, R), the display options (View menu and the
/// Display panel, both built from scene_option_table()) and the highlighted segment. Keeps the
/// scene in step with the workspace.

#include <QObject>
#include <QString>
#include <vector>

#include "app/app_context.h"
#include "core/scene_options.h"
#include "saltus/evaluation/simulate.h"

class QAction;
class QMenu;
class QToolBar;
class QWidget;

namespace saltus::gui {

class SceneWidget;

class ViewController : public QObject, public RemembersSettings {
  Q_OBJECT

 public:
  ViewController(AppContext& context, SceneWidget* scene, QObject* parent = nullptr);

  /// Stage, camera and display-option actions into the View menu; the everyday ones into the
  /// toolbar; the Display panel's check boxes (mirroring the menu both ways).
  void fill_menu(QMenu* view);
  void fill_toolbar(QToolBar* bar);
  QWidget* make_display_panel(QWidget* parent);

  SceneWidget* scene() const { return scene_; }
  void set_stage(Stage stage);
  void set_camera(CameraPreset preset);
  CameraPreset camera() const;
  void reset_camera();
  void set_scene_options(const SceneOptions& options);
  SceneOptions scene_options() const;
  /// Poses the body at t (texts refresh less often while playing).
  void set_time(double t, bool playing);
  /// Draws a what-if flight beside the athlete, labelled (null: none).
  void set_what_if(const SimulationResult* flight, const QString& label);

  /// Marks a segment in the 3D view (-1: none).
  void highlight(int segment);
  int highlighted_segment() const;

  void load_settings(const QSettings& settings) override;
  void save_settings(QSettings& settings) const override;

 signals:
  /// A click on a body segment (its index), or beside the body (-1).
  void segment_clicked(int segment);

 private:
  void on_workspace(WorkspaceChange change);
  void update_actions();
  void apply_options();

  AppContext& context_;
  SceneWidget* scene_;
  QAction* before_ = nullptr;
  QAction* after_ = nullptr;
  QAction* reset_ = nullptr;
  std::vector<QAction*> cameras_;  ///< in camera_presets() order
  /// One state per display option: the View menu's checkable actions, in
  /// scene_option_table() order. The Display panel's boxes and the settings read and write
  /// these, never a copy.
  std::vector<QAction*> options_;
  bool setting_options_ = false;  ///< set_scene_options is ticking several at once
};

}  // namespace saltus::gui
