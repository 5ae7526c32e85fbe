#pragma once
/// @file
/// The command line of saltus-gui (batch flags included), parsed with CLI11 like `saltus`'s and
/// without Qt, so it is unit-tested:
///   saltus-gui [MOTION] [--optimize] [OPTIMISER OPTIONS] [--time T]
///              [--stage before|after] [--camera side|front|top|follow] [--size WxH]
///              [--screenshot FILE] [--screenshot-view FILE] [--save-result DIR]
///              [--export-figures DIR RESULT_DIR...] [--benchmark-playback [--seconds S]]
///              [--compare B] [--export-video FILE [--fps F] [--speed S]]
///              [--lecture-figure FILE [--poses N]]
/// The optimiser options are the option table's flags (`saltus optimize --help`: --max-iter,
/// --samples, --formulation, ...). Positional arguments before --export-figures name the
/// motion; after it, result folders.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/document.h"
#include "core/optimize_settings.h"
#include "core/scene_options.h"
#include "saltus/evaluation/stroboscope.h"

namespace saltus::gui {

struct CommandLine {
  std::string motion;                    ///< motion file to open ("" none)
  std::vector<std::string> result_dirs;  ///< `saltus optimize` folders for --export-figures
  bool optimize = false;
  /// Optimiser options given (option table name and value), applied over the panel's values.
  std::vector<std::pair<std::string, OptionValue>> options;
  std::optional<double> time;  ///< s
  std::optional<Stage> stage;
  std::optional<CameraPreset> camera;
  /// A panel brought to the front before the screenshot: "twist" (Where does the twist come
  /// from?, its analysis finished), "teaching" (Why it spins), "joints" (the Joint loads tab),
  /// "strength" (the Strength tab) or "model" (the Model panel, with "can this athlete land it?");
  /// "" none.
  std::string panel;
  int width = 1600;
  int height = 1000;
  std::string screenshot;       ///< whole window PNG
  std::string screenshot_view;  ///< 3D view PNG
  std::string save_result;      ///< output folder like the CLI's --out
  std::string lecture_figure;   ///< the stroboscopic side view's PNG (core/lecture_figure.h)
  int lecture_poses = kDefaultStroboscopePoses;  ///< poses in it
  std::string export_figures;                    ///< folder for the paper-style figures
  std::string compare;       ///< --screenshot shows the compare window against this
  std::string export_video;  ///< .mp4 or .gif of the 3D view
  double video_fps = 0.0;    ///< 0: the format's default
  double video_speed = 1.0;  ///< motion seconds per video second
  bool benchmark = false;
  double benchmark_seconds = 5.0;
  bool help = false;
  bool version = false;

  /// Whether the run writes files and exits by itself (no user interaction).
  bool batch() const {
    return !screenshot.empty() || !screenshot_view.empty() || !save_result.empty() ||
           !export_figures.empty() || !export_video.empty() || !lecture_figure.empty() || benchmark;
  }
  /// `settings` with the optimiser options given here set.
  OptimizeSettings applied_to(OptimizeSettings settings) const;
};

/// Parses the arguments after the program name. Throws std::invalid_argument with a message
/// for the user on bad usage (unknown flag, missing or bad value, flags needing a motion).
CommandLine parse_command_line(const std::vector<std::string>& args);

/// The --help text.
std::string usage_text();

}  // namespace saltus::gui
