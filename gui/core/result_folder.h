#pragma once
/// @file
/// The paper-style figures that `saltus-gui --export-figures` draws from result folders, read
/// by the library (saltus/formats/result_json.h, mass_files.h): root force and moment
/// before/after, keyframe times before/after and the average root force of every `saltus
/// optimize` folder side by side; joint loads with the given and the scaled mass parameters
/// from `saltus study mass` folders (the paper's Fig. 8).

#include <string>
#include <vector>

#include "core/chart_spec.h"
#include "core/plot_series.h"
#include "saltus/formats/mass_files.h"
#include "saltus/formats/result_json.h"

namespace saltus::gui {

/// Reads a `saltus optimize` output folder (read_result_folder). Throws InputError naming the
/// file and field that is missing or malformed, or result.json's "/after" when the folder holds
/// an evaluation or a simulation.
ResultFolder read_optimization_folder(const std::string& dir);

/// A figure to write: file name (inside the output folder) and what it shows.
struct Figure {
  std::string file_name;
  ChartSpec chart;
};

/// Keyframe times before (given) and after (optimised) against keyframe number.
ChartSpec keyframe_times_chart(const ResultFolder& folder);
/// Average root force before and after, one pair of bars per folder.
ChartSpec average_force_chart(const std::vector<ResultFolder>& folders);

/// For each folder (optimisation results) <name>_root_force.png, <name>_root_moment.png,
/// <name>_keyframe_times.png, then average_root_force.png for all of them. Names are made
/// file-safe and unique.
std::vector<Figure> paper_figures(const std::vector<ResultFolder>& folders);

/// Joint force (`moment` false, N) or moment (N·m) magnitude of load segment `index` of the
/// folder's mass.csv against time, given and scaled runs on the same axes, named by the runs'
/// labels.
ChartSpec mass_load_chart(const MassStudyFolder& folder, std::size_t index, bool moment);

/// A figure of several charts in a grid, row by row (`columns` per row).
struct FigureGrid {
  std::string file_name;
  std::vector<ChartSpec> panels;
  int columns = 2;
};

/// <name>_loads.png per folder: one row per load segment, force left and moment right.
std::vector<FigureGrid> mass_study_figures(const std::vector<MassStudyFolder>& folders);

}  // namespace saltus::gui
