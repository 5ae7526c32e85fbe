#pragma once
/// @file
/// What the app holds of the open motion, as one state that every window part reads: the
/// Document (motion, model, evaluations), the optimisation runs of this motion and which one is
/// shown, the stage the 3D view shows, and what is not saved yet. Edits, undo and redo go
/// through snapshots of this state, so an undo brings back the runs an edit made stale.
/// No Qt: observers are plain callbacks, and all of it is unit-tested.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/document.h"
#include "core/run_list.h"

namespace saltus::gui {

enum class WorkspaceChange {
  kOpened,  ///< another motion (or model) was loaded: fit the camera, clear messages
  kEdited,  ///< the motion or the model changed (an edit, an undo or a redo)
  kRuns,    ///< a run was added, or another run is shown
  kStage,   ///< the 3D view shows another stage
  kSaved,   ///< something was saved (titles, the unsaved-work prompt)
};

class Workspace {
 public:
  const Document& document() const { return document_; }
  bool loaded() const { return document_.loaded(); }
  /// The stage shown: kAfter only while a run is shown.
  Stage stage() const { return stage_; }
  void set_stage(Stage stage);
  /// Changes with every motion or model the runs would belong to (open, edit, undo, redo): an
  /// optimisation started under another generation belongs to a motion no longer shown.
  int generation() const { return generation_; }

  /// Opens a motion file (see Document::load); runs and unsaved state start afresh. Throws
  /// like Document::load; on failure nothing changes.
  void open(const std::string& motion_path, const std::string& model_override = "",
            int samples = kDefaultSamples, const CaptureFileOptions& capture_options = {});

  /// An edit of the motion or of the model (same segments): evaluated at once, the runs of the
  /// previous version leave the list (a snapshot taken before keeps them for undo). Throws
  /// like Document::set_motion / set_model; on failure nothing changes.
  void set_motion(const Motion& motion);
  void set_model(const BodyModel& model);

  const RunList& runs() const { return runs_; }
  /// Adds a finished run; shows it if it becomes the preferred one (RunList::preferred), so a
  /// cancelled or failed run never replaces a solved one. Returns its index.
  int add_run(RunRecord run);
  /// The run shown (its result is the "after" stage), nullopt for none.
  std::optional<int> shown_run() const { return shown_; }
  /// Shows a run (nullopt: none, the interpolation only). Throws std::out_of_range for a run
  /// without a result.
  void show_run(std::optional<int> index);

  /// Everything an undo must bring back.
  struct Snapshot {
    Motion motion;
    BodyModel model;
    RunList runs;
    std::optional<int> shown;
    Stage stage = Stage::kBefore;
    int motion_version = 0;
    int model_version = 0;
  };
  Snapshot snapshot() const;
  /// Back to a snapshot of the same open motion (re-evaluated). Throws like set_motion.
  void restore(const Snapshot& snapshot);

  /// Unsaved work: edits since the motion (model) was opened or saved, runs not written.
  bool motion_unsaved() const { return motion_version_ != saved_motion_version_; }
  bool model_unsaved() const { return model_version_ != saved_model_version_; }
  int unsaved_runs() const { return runs_.unsaved(); }
  bool has_unsaved_work() const {
    return loaded() && (motion_unsaved() || model_unsaved() || unsaved_runs() > 0);
  }
  /// "the keyframes were edited; 2 optimisation runs were not saved" ("" when nothing).
  std::string unsaved_summary() const;
  void mark_motion_saved();
  void mark_model_saved();
  /// The shown run (or, with none, nothing) was written to a result folder.
  void mark_result_saved();

  /// Called after every change, in subscription order.
  void subscribe(std::function<void(WorkspaceChange)> observer);

 private:
  void notify(WorkspaceChange change);
  void apply_shown();

  Document document_;
  RunList runs_;
  std::optional<int> shown_;
  Stage stage_ = Stage::kBefore;
  int generation_ = 0;
  int next_version_ = 1;
  int motion_version_ = 0, saved_motion_version_ = 0;
  int model_version_ = 0, saved_model_version_ = 0;
  std::vector<std::function<void(WorkspaceChange)>> observers_;
};

}  // namespace saltus::gui
