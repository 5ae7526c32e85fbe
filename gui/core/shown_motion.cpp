#include "core/shown_motion.h"

namespace saltus::gui {

std::optional<ShownMotion> shown_motion_subject(const Workspace& workspace, SavedTrajectory saved) {
  if (!workspace.loaded()) return std::nullopt;
  const Document& d = workspace.document();
  ShownMotion s;
  s.model = d.file().model;
  s.options = d.evaluate_options();
  s.key.generation = workspace.generation();
  const std::optional<int> run = workspace.shown_run();
  if (run && workspace.stage() == Stage::kAfter && d.has_optimization()) {
    s.motion = d.optimization().optimized_motion;
    s.description =
        "the optimised motion of run " + std::to_string(workspace.runs().at(*run).number);
    s.key.run = *run;
  } else {
    s.motion = d.file().motion;
    s.description = s.motion.spline && saved == SavedTrajectory::kFlown
                        ? "the optimised trajectory, as saved"
                        : "the interpolated keyframes";
  }
  return s;
}

std::optional<MotionToSave> given_keyframes_to_save(const Workspace& workspace) {
  if (!workspace.loaded()) return std::nullopt;
  MotionToSave out;
  out.motion = workspace.document().file().motion;
  out.what = workspace.motion_unsaved() ? "the keyframes as edited" : "the keyframes as given";
  return out;
}

std::optional<MotionToSave> motion_to_save(const Workspace& workspace) {
  const std::optional<int> run = workspace.shown_run();
  const Document& d = workspace.document();
  if (!(workspace.loaded() && run && workspace.stage() == Stage::kAfter && d.has_optimization()))
    return given_keyframes_to_save(workspace);
  MotionToSave out;
  out.motion = d.optimization().optimized_motion;
  out.optimised = true;
  out.run_number = workspace.runs().at(*run).number;
  out.what = "the optimised motion of run " + std::to_string(out.run_number) +
             " (keyframes at their optimised times, with its spline)";
  return out;
}

std::string MotionToSave::file_name(const std::string& stem) const {
  if (optimised) return stem + "-run" + std::to_string(run_number) + "-optimised.motion.json";
  if (what == "the keyframes as edited") return stem + "-edited.motion.json";
  return stem + ".motion.json";
}

}  // namespace saltus::gui
