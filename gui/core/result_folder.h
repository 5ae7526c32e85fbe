#pragma once
/// @file
/// Reading `saltus optimize` output folders (DESIGN §6) and the paper-style figures that
/// `saltus-gui --export-figures` draws from them: root force and moment before/after, keyframe
/// times before/after, and the average root force of every folder side by side. Also
/// `saltus study mass` folders (the paper's Fig. 8): joint loads with the given and the scaled
/// mass parameters.

#include <array>
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

/// True if DIR/result.json exists, parses and says `"study": "mass"` (a `saltus study mass`
/// folder). Anything else is false, so read_result_folder reports what is wrong with it.
bool is_mass_study_folder(const std::string& dir);

/// The joint loads of one segment in a mass study: index 0 the given model's run, 1 the scaled.
struct SegmentLoadSeries {
  std::string segment;
  std::array<std::vector<double>, 2> force;   ///< |joint force| (N), one value per time
  std::array<std::vector<double>, 2> moment;  ///< |joint moment| (N·m)
};

struct MassLoadSeries {
  std::vector<double> time;  ///< s
  std::vector<SegmentLoadSeries> segments;
};

/// Extracts time and, per load segment, the force and moment magnitudes of both runs from
/// mass.csv (columns t, given.<segment>.force_N, given.<segment>.moment_Nm, scaled.<...>).
/// Throws InputError naming `file` and the missing column.
MassLoadSeries mass_load_series(const CsvTable& table, const std::vector<std::string>& segments,
                                const std::string& file);

struct MassStudyFolder {
  std::string path;
  std::string name;    ///< the folder's own name, used in the figure's file name
  std::string motion;  ///< result.json "motion"
  std::array<std::string, 2> run_labels{"given", "scaled"};  ///< result.json runs[i].label
  MassLoadSeries loads;                                      ///< mass.csv
};

/// Reads result.json and mass.csv of a `saltus study mass` output folder. Throws InputError
/// naming the file (and field) that is missing or malformed.
MassStudyFolder read_mass_study_folder(const std::string& dir);

/// Joint force (`moment` false, N) or moment (N·m) magnitude of segment `index` of
/// folder.loads.segments against time, given and scaled runs on the same axes.
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
