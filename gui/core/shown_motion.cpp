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

}  // namespace saltus::gui
