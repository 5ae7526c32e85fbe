#pragma once
/// @file
/// Reading `saltus optimize` output folders (DESIGN §6) and the paper-style figures that
/// `saltus-gui --export-figures` draws from them: root force and moment before/after, keyframe
/// times before/after, and the average root force of every folder side by side.

#include <string>
#include <vector>

#include "core/chart_spec.h"
#include "core/plot_series.h"

namespace saltus::gui {

struct ResultFolder {
  std::string path;
  std::string name;    ///< the folder's own name, used in figure file names
  std::string motion;  ///< result.json "motion"
  std::string status;
  std::string formulation;
  WrenchSeries before;  ///< trajectory_before.csv
  WrenchSeries after;   ///< trajectory_after.csv
  std::vector<double> keyframe_times_before;
  std::vector<double> keyframe_times_after;
  double avg_root_force_before = 0.0;  ///< N, sqrt(J/6)
  double avg_root_force_after = 0.0;
  int iterations = 0;
  double solve_seconds = 0.0;
};

/// Reads result.json, trajectory_before.csv and trajectory_after.csv of a `saltus optimize`
/// output folder. Throws InputError naming the file (and field) that is missing or malformed.
ResultFolder read_result_folder(const std::string& dir);

/// A figure to write: file name (inside the output folder) and what it shows.
struct Figure {
  std::string file_name;
  ChartSpec chart;
};

/// Keyframe times before (given) and after (optimised) against keyframe number.
ChartSpec keyframe_times_chart(const ResultFolder& folder);
/// Average root force before and after, one pair of bars per folder.
ChartSpec average_force_chart(const std::vector<ResultFolder>& folders);

/// For each folder <name>_root_force.png, <name>_root_moment.png, <name>_keyframe_times.png,
/// then average_root_force.png for all of them. Names are made file-safe and unique.
std::vector<Figure> paper_figures(const std::vector<ResultFolder>& folders);

}  // namespace saltus::gui
