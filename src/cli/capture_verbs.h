#pragma once
/// @file
/// `saltus import` (a BVH capture onto the body model) and `saltus export --format bvh|html`: their
/// options, and running them. main.cpp registers them and dispatches to them.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace saltus_cli {

struct ImportArgs {
  std::string capture_path;
  std::string out_dir;
  std::string model;
  std::string mapping;
  std::string keyframes;             ///< "" (automatic), a count, or "all"
  std::string flight;                ///< "" or "START:END" in seconds
  std::optional<double> frame_time;  ///< none: the file's
  bool quiet = false;
};

struct ExportArgs {
  std::string source;
  std::string format;
  std::string out_path;
  std::optional<double> fps;  ///< none: default_export_fps
  std::string capture;        ///< html: the capture beside the athlete, "" = the source's own
  bool quiet = false;
};

struct CaptureVerbs {
  ImportArgs import_args;
  ExportArgs export_args;
  CLI::App* import_command = nullptr;
  CLI::App* export_command = nullptr;
};

/// Adds the `import` and `export` subcommands to `app`; `verbs` receives their options and must
/// outlive parsing.
void add_capture_verbs(CLI::App& app, CaptureVerbs& verbs);

/// Runs whichever of the two was parsed and returns its exit status; nullopt when neither was.
/// Bad input throws saltus::InputError (exit status 2 in main).
std::optional<int> run_capture_verbs(const CaptureVerbs& verbs);

}  // namespace saltus_cli
