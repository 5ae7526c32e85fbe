#pragma once
/// @file
/// Comparing two runs side by side (before vs after, a second motion, a second model, a saved
/// result folder): where the second run comes from, the shared timeline and the root wrench of
/// both overlaid in one chart. The runs themselves are Documents loaded and evaluated by the
/// library exactly as the main view's.

#include <array>
#include <string>

#include "core/chart_spec.h"
#include "core/plot_series.h"
#include "saltus/body/body_model.h"

namespace saltus::gui {

/// What to load for a run read from a result folder: `saltus optimize` folders give their
/// optimized.motion.json (which names the model.json beside it); `saltus evaluate` folders give
/// result.json's "motion_file" with the model.json beside it.
struct FolderRun {
  std::string motion_path;
  std::string model_path;  ///< model override for Document::load; "" uses the motion's own
  std::string label;       ///< the folder's name, plus "(optimised)" for optimize folders
  /// What the run is: "optimised motion (saltus optimize folder)" or "interpolated keyframes
  /// (saltus evaluate folder)". Loaded, either is the folder's motion as written: an
  /// optimised motion's stored spline is the optimised motion itself, not a "before".
  std::string description;
};
/// Throws InputError naming the file that is missing or malformed.
FolderRun folder_run(const std::string& dir);

/// The shared timeline runs over the longer flight; each view shows its own run at min(t, T).
double compare_duration(double duration_a, double duration_b);
double run_time(double t, double duration);

/// Colour of run 0 or 1: blue shades for the first, orange for the second, x darkest and z
/// palest, so both the run and the component can be read off a line.
Rgb compare_colour(int run, int component);

/// Root force or moment of two runs on the same axes, in the plots' one style (plot_series.h):
/// run 0 dashed and paler, run 1 solid, each in its own colour (blue, orange), as resultants
/// (legend "<label>") or components (legend "x <label>").
ChartSpec compare_root_chart(const RootChartStyle& style,
                             const std::array<const WrenchSeries*, 2>& runs,
                             const std::array<std::string, 2>& labels);

/// The force (`moment` false, N) or moment (N·m) magnitude at the joint of `segment` in two runs
/// (same model topology), on the same axes: the paper's Fig. 8, explorable for any joint.
ChartSpec compare_joint_chart(const BodyModel& model, int segment, bool moment,
                              const std::array<const std::vector<SampleRecord>*, 2>& runs,
                              const std::array<std::string, 2>& labels);

}  // namespace saltus::gui
