#pragma once
/// @file
/// Exported figures: every one titled with the motion and the settings it was made with, in the
/// plots' one style (plot_series.h). From the app (File > Export plots) and from `saltus
/// optimize` and `saltus study mass` folders (`saltus-gui --export-figures`): the resultant root
/// force |F| (with % of body weight) and moment |M| before and after on a log axis, as the
/// paper's Figs. 4 and 5 plot them but with the "after" curve readable, their components, the
/// keyframe times, the average root force of every folder, the mass study's joint loads
/// (Fig. 8) named as people name the joints, and where a twist comes from (`saltus analyse
/// twist` folders).

#include <string>
#include <vector>

#include "core/chart_spec.h"
#include "core/result_folder.h"
#include "saltus/formats/mass_files.h"
#include "saltus/formats/twist_files.h"

namespace saltus::gui {

/// A file-safe stem of a name ("M1 straight back somersault" -> "M1_straight_back_somersault").
std::string figure_stem(const std::string& name);

/// The chart with its title on the first line and "<motion> · <settings>" on a second one, or
/// the motion and the settings on a line each when that is too long (`settings` may be
/// empty).
ChartSpec titled_figure(ChartSpec chart, const std::string& motion, const std::string& settings);

/// One line of a result folder's settings: "relaxed, K = 1, 101 samples · solved in 25
/// iterations".
std::string folder_settings(const ResultFolder& folder);

/// Curves are drawn from a dense grid where the folder's motions can be evaluated again (its
/// optimized.motion.json, and the motion file result.json names), else from its CSVs.
/// For each folder <name>_root_force.png (|F|, log axis, % of body weight when the folder's
/// model.json reads), <name>_root_moment.png (|M|), <name>_root_force_components.png,
/// <name>_root_moment_components.png and <name>_keyframe_times.png; then
/// average_root_force.png for all of them. Names are file-safe and unique.
std::vector<Figure> result_figures(const std::vector<ResultFolder>& folders);

/// Average root force before and after on a log axis, a pair of points per folder (after
/// optimisation it is hundreds of times smaller: a linear axis hid it), each pair labelled with
/// a short name (the folder name's first word, e.g. "M1", when those are unique; else a number
/// with the names listed in the title).
ChartSpec average_root_force_figure(const std::vector<ResultFolder>& folders);

/// <name>_loads.png per mass-study folder: per load segment a row, joint force left and joint
/// moment right, the given and the scaled model's optimised motions on the same axes, named
/// "right hip" rather than thigh_r.
std::vector<FigureGrid> mass_study_load_figures(const std::vector<MassStudyFolder>& folders);

/// <name>_twist.png per `saltus analyse twist` folder: the Twist panel's chart (tilt over time of
/// the actual free flight and of the same take-off with each movement made symmetric, mid-flight
/// marked) under the folder's sentence, the motion and its tilt and twists.
std::vector<Figure> twist_figures(const std::vector<TwistFolder>& folders);

}  // namespace saltus::gui
