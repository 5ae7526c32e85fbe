#pragma once
/// @file
/// Result folders as the figures read them (core/figures.h draws them): a `saltus optimize`
/// folder read by the library (saltus/formats/result_json.h), its keyframe-times chart, and
/// the figure records that `saltus-gui --export-figures` writes.

#include <string>
#include <vector>

#include "core/chart_spec.h"
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

/// A figure of several charts in a grid, row by row (`columns` per row).
struct FigureGrid {
  std::string file_name;
  std::vector<ChartSpec> panels;
  int columns = 2;
};

}  // namespace saltus::gui
