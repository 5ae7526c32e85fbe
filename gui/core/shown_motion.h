#pragma once
/// @file
/// The motion the 3D view shows, as the subject of a report that the library works out from it
/// (the Twist panel's twist sources, the What if panel's flights): the interpolated keyframes (or
/// a saved optimised trajectory), or with the "after" stage shown, the optimised motion of the
/// run shown; with a key that tells when it became another motion.

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

}  // namespace saltus::gui
