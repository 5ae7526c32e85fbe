#pragma once
/// @file
/// The motion the 3D view shows, as the subject of a report that the library works out from it
/// (the Twist panel's twist sources, the What if panel's flights): the interpolated keyframes (or
/// a saved optimised trajectory), or with the "after" stage shown, the optimised motion of the
/// run shown; with a key that tells when it became another motion. And the motion that Save
/// motion as… writes, the one on screen.

#include <optional>
#include <string>

#include "core/workspace.h"

namespace saltus::gui {

/// The motion a report is about, with the model and options to evaluate it.
struct ShownMotion {
  Motion motion;
  BodyModel model;
  EvaluateOptions options;
  /// "the interpolated keyframes", "the optimised trajectory, as saved", "the optimised motion
  /// of run 2".
  std::string description;
  /// Which motion this is: the workspace's generation (a new motion, model, edit or undo) and the
  /// run shown (-1: the motion itself). Equal keys, same motion and model.
  struct Key {
    int generation = -1;
    int run = -1;
    bool operator==(const Key& other) const {
      return generation == other.generation && run == other.run;
    }
    bool operator!=(const Key& other) const { return !(*this == other); }
  };
  Key key;
};

/// What the report makes of a motion saved with its optimised trajectory (a stored spline), so
/// that the description says what it is about: the trajectory as saved (the library's what_if
/// flies it), or the keyframes interpolated anew (twist_sources drops the stored spline).
enum class SavedTrajectory { kFlown, kReinterpolated };

/// The subject for the workspace as it is; nullopt without a motion.
std::optional<ShownMotion> shown_motion_subject(const Workspace& workspace, SavedTrajectory saved);

/// What File > Save motion as… writes: the motion on screen. With a run shown in the "after"
/// stage, its optimised motion (OptimizationResult::optimized_motion: the keyframes at their
/// optimised times, the spline the result holds, its own take-off; loaded again it is the run's
/// "after"); otherwise the keyframes as given (edited or not). Its name and description are the
/// motion's.
struct MotionToSave {
  Motion motion;
  bool optimised = false;
  int run_number = 0;  ///< the run it comes from (optimised only)
  /// For the dialog: "the optimised motion of run 2 (keyframes at their optimised times, with
  /// its spline)", "the keyframes as given", "the keyframes as edited".
  std::string what;
  /// A file name for it: "M7-double-front-one-and-a-half-twists-run2-optimised.motion.json",
  /// "…-edited.motion.json", "….motion.json" (`stem`: the open file's name without
  /// ".motion.json").
  std::string file_name(const std::string& stem) const;
};

/// The motion on screen (above); nullopt without a motion.
std::optional<MotionToSave> motion_to_save(const Workspace& workspace);
/// The keyframes as given (File > Save given keyframes as…), whatever is shown.
std::optional<MotionToSave> given_keyframes_to_save(const Workspace& workspace);

}  // namespace saltus::gui
