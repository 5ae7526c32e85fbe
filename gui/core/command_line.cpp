#include "core/command_line.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "flags/flag_bound_checks.h"
#include "flags/option_flags.h"
#include "saltus/base/text_format.h"

namespace saltus::gui {

namespace {

constexpr const char* kDescription =
    "Opens the desktop app, showing MOTION (*.motion.json, or a .bvh capture imported onto the\n"
    "model) if given. With any of --screenshot, --screenshot-view, --save-result,\n"
    "--export-figures, --export-video or --benchmark-playback it runs without user\n"
    "interaction: it renders (under an X display; use xvfb-run on a headless machine),\n"
    "writes the files and exits (status 0 ok, 2 bad input or usage, 1 other failure).\n"
    "--optimize takes the optimiser options of `saltus optimize` (the library's defaults in\n"
    "batch runs, the Optimise panel's values otherwise).";

/// CLI11 gives an option its required value even when that looks like a flag
/// ("--screenshot --optimize"): for file and folder names that is a mistake, not a name.
const CLI::Validator kNotAFlag(
    [](std::string& value) -> std::string {
      return value.rfind("--", 0) == 0 ? "needs a value, not the flag " + value : "";
    },
    "", "not a flag");

/// A number flag of the app checked against its row of the library's table of bounds.
CLI::Validator bounded(const std::string& flag) {
  return cli::flag_bound_check(flag, "saltus-gui");
}

/// saltus-gui's command line as a CLI11 app writing into `c`; the option table's flags go to
/// `flags`, which must outlive the parse.
std::unique_ptr<CLI::App> make_app(CommandLine& c, cli::OptionFlags& flags,
                                   std::vector<std::string>& figures) {
  auto app = std::make_unique<CLI::App>(kDescription, "saltus-gui");
  app->set_help_flag("-h,--help", "print this help and exit");
  app->add_flag("--version", c.version, "print the version and exit");
  app->add_option("MOTION", c.motion, "motion file to open (*.motion.json) or capture (*.bvh)");
  app->add_flag("--optimize", c.optimize, "optimise the motion before anything else");
  flags.add(app.get(), cli::all_option_names());
  app->add_option("--time", c.time, "show time T (s) of the flight")
      ->type_name("T")
      ->check(bounded("--time"));
  app->add_option_function<std::string>(
         "--stage",
         [&c](const std::string& v) { c.stage = v == "before" ? Stage::kBefore : Stage::kAfter; },
         "show the interpolated or the optimised motion (after: the default once optimised)")
      ->type_name("before|after")
      ->check(CLI::IsMember({"before", "after"}).description(""));
  app->add_option_function<std::string>(
         "--camera", [&c](const std::string& v) { c.camera = camera_preset_from_name(v); },
         "camera preset")
      ->type_name("side|front|top|follow")
      ->check(CLI::IsMember({"side", "front", "top", "follow"}).description(""));
  app->add_option("--panel", c.panel,
                  "bring a panel to the front for the screenshot: twist (where the twist comes "
                  "from, its analysis finished), teaching (why it spins), joints (the joint "
                  "loads), strength (every joint's share of the athlete's strength) or model "
                  "(the Model panel: can this athlete land it?)")
      ->type_name("twist|teaching|joints|strength|model")
      ->check(CLI::IsMember({"twist", "teaching", "joints", "strength", "model"}).description(""));
  app->add_option_function<std::string>(
         "--size",
         [&c](const std::string& v) {
           const std::size_t x = v.find('x');
           c.width = std::stoi(v.substr(0, x));
           c.height = std::stoi(v.substr(x + 1));
         },
         "window size for screenshots and the benchmark (default 1600x1000)")
      ->type_name("WxH")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            const std::size_t x = v.find('x');
            int w = 0, h = 0;
            std::size_t used_w = 0, used_h = 0;
            try {
              w = std::stoi(v.substr(0, x), &used_w);
              h = std::stoi(v.substr(x + 1), &used_h);
            } catch (const std::exception&) {
              return "must look like 1600x1000";
            }
            if (x == std::string::npos || used_w != x || used_h != v.size() - x - 1)
              return "must look like 1600x1000";
            if (w < 200 || h < 200 || w > 8000 || h > 8000)
              return "must be between 200x200 and 8000x8000";
            return "";
          },
          "", "WxH"));
  app->add_option("--screenshot", c.screenshot, "save the whole window as PNG")
      ->type_name("FILE")
      ->check(kNotAFlag);
  app->add_option("--screenshot-view", c.screenshot_view, "save the 3D view as PNG")
      ->type_name("FILE")
      ->check(kNotAFlag);
  app->add_option("--lecture-figure", c.lecture_figure,
                  "the stroboscopic side view of the stage shown as PNG: poses at equal time "
                  "steps along the CoM's path, coloured by the whole-body spin rate (as File > "
                  "Export lecture figure…; 1800x900, --poses N)")
      ->type_name("FILE")
      ->check(kNotAFlag);
  app->add_option("--poses", c.lecture_poses, "poses in the lecture figure (default 10)")
      ->type_name("N")
      ->check(bounded("--poses"));
  app->add_option("--save-result", c.save_result,
                  "write the result folder the CLI would (optimize or evaluate)")
      ->type_name("DIR")
      ->check(kNotAFlag);
  app->add_option("--export-figures", figures,
                  "draw paper-style figures (root force/moment and keyframe times before/after, "
                  "average root force) from `saltus optimize` folders, joint loads given vs "
                  "scaled (Fig. 8) from `saltus study mass` folders, and the tilt over the flight "
                  "from `saltus analyse twist` folders")
      ->type_name("DIR RESULT_DIR")
      ->check(kNotAFlag)
      ->expected(1, CLI::detail::expected_max_vector_size);
  app->add_option("--compare", c.compare,
                  "with --screenshot: the compare window of MOTION against B instead of the main "
                  "window; B is a motion file, a body model file (the same motion flown by that "
                  "athlete, its take-off by the same spin as `saltus simulate --model`) or a "
                  "result folder")
      ->type_name("B")
      ->check(kNotAFlag);
  app->add_option("--export-video", c.export_video,
                  "the 3D view's animation as .mp4 or .gif (time and residual in the picture; "
                  "needs the ffmpeg program)")
      ->type_name("FILE")
      ->check(kNotAFlag);
  app->add_option("--fps", c.video_fps, "frames per second of the video (default 30, GIF 20)")
      ->type_name("F")
      ->check(bounded("--fps"));
  app->add_option("--speed", c.video_speed,
                  "motion seconds per video second (default 1; 0.5 = slow motion)")
      ->type_name("S")
      ->check(bounded("--speed"));
  app->add_flag("--benchmark-playback", c.benchmark,
                "play the motion for a few seconds and print frames per second");
  app->add_option("--seconds", c.benchmark_seconds, "length of the benchmark (default 5)")
      ->type_name("S")
      ->check(bounded("--seconds"));
  return app;
}

}  // namespace

OptimizeSettings CommandLine::applied_to(OptimizeSettings settings) const {
  for (const auto& [name, value] : options)
    settings.set(name, value);
  return settings;
}

CommandLine parse_command_line(const std::vector<std::string>& args) {
  CommandLine c;
  cli::OptionFlags flags;
  std::vector<std::string> figures;
  const std::unique_ptr<CLI::App> app = make_app(c, flags, figures);
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  try {
    app->parse(reversed);
  } catch (const CLI::CallForHelp&) {
    c.help = true;
    return c;
  } catch (const CLI::ParseError& e) {
    if (c.version) return c;
    throw std::invalid_argument(e.what());
  }
  c.options = flags.given();
  if (c.help || c.version) return c;
  if (!figures.empty()) {
    c.export_figures = figures.front();
    c.result_dirs.assign(figures.begin() + 1, figures.end());
    if (c.result_dirs.empty())
      throw std::invalid_argument("--export-figures DIR needs at least one RESULT_DIR after it");
  }
  if (!c.compare.empty() && c.screenshot.empty())
    throw std::invalid_argument(
        "--compare B needs --screenshot FILE (the compare window's picture)");
  const bool needs_motion = c.optimize || c.time || c.stage || !c.screenshot.empty() ||
                            !c.screenshot_view.empty() || !c.save_result.empty() || c.benchmark ||
                            !c.export_video.empty() || !c.compare.empty() ||
                            !c.lecture_figure.empty();
  if (needs_motion && c.motion.empty() && c.batch())
    throw std::invalid_argument("give a motion file to show (saltus-gui MOTION ...)");
  return c;
}

std::string usage_text() {
  CommandLine c;
  cli::OptionFlags flags;
  std::vector<std::string> figures;
  return make_app(c, flags, figures)->help();
}

}  // namespace saltus::gui
