#pragma once
/// @file
/// Edits and their undo stack: keyframe angles and times, added and deleted keyframes (the
/// Keyframes panel), segment masses (the Model panel) and the Optimise panel's options. Every
/// edit is a command on one QUndoStack (Edit > Undo, Ctrl+Z; Edit > Redo, Ctrl+Shift+Z; Edit >
/// History): an edit of the motion or the model stores the workspace's snapshot before it, so an
/// undo also brings back the optimisation runs that the edit made stale. A slider drag or a run
/// of arrow clicks on one value is one step. A rejected edit changes nothing and its message
/// appears in the panel, worded for the user.

#include <QObject>
#include <QString>
#include <functional>
#include <vector>

#include "app/app_context.h"

class QAction;
class QEvent;
class QMenu;
class QUndoStack;
class QUndoView;
class QWidget;

namespace saltus::gui {

class CapturePanel;
class KeyframePanel;
class ModelPanel;
class RunController;

class EditController : public QObject {
  Q_OBJECT

 public:
  EditController(AppContext& context, RunController& runs, QObject* parent = nullptr);

  void fill_menu(QMenu* edit);
  QUndoStack* undo_stack() const { return stack_; }
  KeyframePanel* keyframe_panel() const { return keyframe_panel_; }
  ModelPanel* model_panel() const { return model_panel_; }
  CapturePanel* capture_panel() const { return capture_panel_; }
  /// The Edit history (a list of the undo stack's steps) for a dock.
  QUndoView* make_history_view(QWidget* parent);

  // Each edit goes through the library (checked by its parser, then evaluated). On failure
  // nothing changes, the message is shown in the panel and stored in `error` if given.
  /// Joint rotation of `segment` at keyframe `keyframe` (0-based) as X-Y-Z Euler angles, degrees.
  bool set_keyframe_angles(int keyframe, int segment, double x_deg, double y_deg, double z_deg,
                           QString* error = nullptr);
  bool set_keyframe_time(int keyframe, double time, QString* error = nullptr);
  /// A keyframe at time t with the pose the shown motion has there.
  bool add_keyframe(double t, QString* error = nullptr);
  bool delete_keyframe(int keyframe, QString* error = nullptr);
  /// Mass factors per segment relative to the model as loaded (the Model panel).
  bool set_mass_factors(const std::vector<double>& factors, QString* error = nullptr);
  /// A motion imported from a capture (the Capture panel): flight frame `frame` (0-based) added
  /// as a keyframe with its captured pose, or removed when it is one.
  bool toggle_capture_frame(int frame, QString* error = nullptr);
  /// The keyframes replaced by the library's automatic pick, or by every captured frame.
  bool pick_capture_frames(bool every_frame, QString* error = nullptr);

  /// Makes Ctrl+Z and Ctrl+Shift+Z in the number fields under `root` (spin boxes, line edits)
  /// the window's Undo and Redo once the typed value is committed (Enter, or leaving the
  /// field). Qt's fields claim these keys for their own text history, so after typing a value
  /// and pressing Enter the keys did nothing visible. While a value is being typed they stay the
  /// field's own undo of the typing.
  void route_undo_keys(QWidget* root);

  bool can_undo() const;
  bool can_redo() const;
  void undo();
  void redo();

 signals:
  /// A keyframe was chosen in the Keyframes panel: show its time.
  void keyframe_chosen(double time);

 protected:
  /// Lets the Undo and Redo keys through to the window in committed fields (route_undo_keys).
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  /// The panel an edit comes from: it shows the edit's problem.
  enum class Source { kKeyframes, kModel, kCapture };
  /// Applies an edit of the motion or the model as one undoable step.
  /// `merge_key`: consecutive edits with the same non-empty key within a moment merge.
  bool apply(const QString& text, const QString& merge_key, Source source,
             const std::function<void(Workspace&)>& edit, QString* error);
  void on_workspace(WorkspaceChange change);

  AppContext& context_;
  RunController& runs_;
  QUndoStack* stack_ = nullptr;
  KeyframePanel* keyframe_panel_ = nullptr;
  ModelPanel* model_panel_ = nullptr;
  CapturePanel* capture_panel_ = nullptr;
  QAction* undo_ = nullptr;
  QAction* redo_ = nullptr;
};

}  // namespace saltus::gui
