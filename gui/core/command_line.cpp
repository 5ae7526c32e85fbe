#include "core/command_line.h"

#include <cmath>
#include <stdexcept>

namespace saltus::gui {

namespace {

double parse_double(const std::string& flag, const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(value))
    throw std::invalid_argument(flag + ": \"" + text + "\" is not a number");
  return value;
}

int parse_int(const std::string& flag, const std::string& text) {
  const double value = parse_double(flag, text);
  if (value != std::floor(value) || std::abs(value) > 1e9)
    throw std::invalid_argument(flag + ": \"" + text + "\" is not a whole number");
  return static_cast<int>(value);
}

}  // namespace

CommandLine parse_command_line(const std::vector<std::string>& args) {
  CommandLine c;
  bool after_export = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size() || (args[i + 1].rfind("--", 0) == 0 && args[i + 1].size() > 2))
        throw std::invalid_argument(a + " needs a value");
      return args[++i];
    };
    if (a == "--help" || a == "-h") {
      c.help = true;
    } else if (a == "--version") {
      c.version = true;
    } else if (a == "--optimize") {
      c.optimize = true;
    } else if (a == "--max-iter") {
      c.max_iterations = parse_int(a, value());
      if (*c.max_iterations < 0) throw std::invalid_argument("--max-iter must be at least 0");
    } else if (a == "--samples") {
      c.samples = parse_int(a, value());
      if (*c.samples < 2) throw std::invalid_argument("--samples must be at least 2");
    } else if (a == "--time") {
      c.time = parse_double(a, value());
      if (*c.time < 0) throw std::invalid_argument("--time must not be negative");
    } else if (a == "--stage") {
      const std::string& v = value();
      if (v == "before")
        c.stage = Stage::kBefore;
      else if (v == "after")
        c.stage = Stage::kAfter;
      else
        throw std::invalid_argument("--stage must be before or after, not \"" + v + "\"");
    } else if (a == "--camera") {
      const std::string& v = value();
      c.camera = camera_preset_from_name(v);
      if (!c.camera)
        throw std::invalid_argument("--camera must be side, front, top or follow, not \"" + v +
                                    "\"");
    } else if (a == "--size") {
      const std::string& v = value();
      const std::size_t x = v.find('x');
      if (x == std::string::npos) throw std::invalid_argument("--size must look like 1600x1000");
      c.width = parse_int(a, v.substr(0, x));
      c.height = parse_int(a, v.substr(x + 1));
      if (c.width < 200 || c.height < 200 || c.width > 8000 || c.height > 8000)
        throw std::invalid_argument("--size must be between 200x200 and 8000x8000");
    } else if (a == "--screenshot") {
      c.screenshot = value();
    } else if (a == "--screenshot-view") {
      c.screenshot_view = value();
    } else if (a == "--save-result") {
      c.save_result = value();
    } else if (a == "--export-figures") {
      c.export_figures = value();
      after_export = true;
    } else if (a == "--compare") {
      c.compare = value();
    } else if (a == "--export-video") {
      c.export_video = value();
    } else if (a == "--fps") {
      c.video_fps = parse_double(a, value());
      if (!(c.video_fps > 0 && c.video_fps <= 120))
        throw std::invalid_argument("--fps must be in (0, 120]");
    } else if (a == "--speed") {
      c.video_speed = parse_double(a, value());
      if (!(c.video_speed >= 0.05 && c.video_speed <= 10))
        throw std::invalid_argument("--speed must be in [0.05, 10]");
    } else if (a == "--benchmark-playback") {
      c.benchmark = true;
    } else if (a == "--seconds") {
      c.benchmark_seconds = parse_double(a, value());
      if (!(c.benchmark_seconds > 0)) throw std::invalid_argument("--seconds must be positive");
    } else if (a.rfind("-", 0) == 0 && a.size() > 1) {
      throw std::invalid_argument("unknown option " + a + " (see --help)");
    } else if (after_export) {
      c.result_dirs.push_back(a);
    } else if (c.motion.empty()) {
      c.motion = a;
    } else {
      throw std::invalid_argument("only one motion file can be opened (got \"" + c.motion +
                                  "\" and \"" + a + "\")");
    }
  }
  if (c.help || c.version) return c;
  if (!c.export_figures.empty() && c.result_dirs.empty())
    throw std::invalid_argument("--export-figures DIR needs at least one RESULT_DIR after it");
  if (!c.compare.empty() && c.screenshot.empty())
    throw std::invalid_argument(
        "--compare B needs --screenshot FILE (the compare window's picture)");
  const bool needs_motion = c.optimize || c.time || c.stage || !c.screenshot.empty() ||
                            !c.screenshot_view.empty() || !c.save_result.empty() || c.benchmark ||
                            !c.export_video.empty() || !c.compare.empty();
  if (needs_motion && c.motion.empty() && c.batch())
    throw std::invalid_argument("give a motion file to show (saltus-gui MOTION ...)");
  return c;
}

std::string usage_text() {
  return R"(Usage: saltus-gui [MOTION] [options]

Opens the desktop app, showing MOTION (*.motion.json, or a .bvh capture imported onto the
model) if given. With any of --screenshot, --screenshot-view, --save-result, --export-figures,
--export-video or --benchmark-playback it runs without
user interaction: it renders (under an X display; use xvfb-run on a headless machine), writes
the files and exits (status 0 ok, 2 bad input or usage, 1 other failure).

  --optimize              optimise the motion (relaxed model) before anything else
  --max-iter N            iteration limit of --optimize (default 100)
  --samples N             time samples of the optimisation grid (default 101)
  --time T                show time T (s) of the flight
  --stage before|after    show the interpolated or the optimised motion (after: default once
                          optimised)
  --camera side|front|top|follow
  --size WxH              window size for screenshots and the benchmark (default 1600x1000)
  --screenshot FILE       save the whole window as PNG
  --screenshot-view FILE  save the 3D view as PNG
  --save-result DIR       write the result folder the CLI would (optimize or evaluate)
  --export-figures DIR RESULT_DIR...
                          draw paper-style figures (root force/moment and keyframe times
                          before/after, average root force) from `saltus optimize` folders,
                          and joint loads given vs scaled (Fig. 8) from `saltus study mass`
                          folders
  --compare B             with --screenshot: the compare window of MOTION against B (a motion
                          file or a result folder) instead of the main window
  --export-video FILE     the 3D view's animation as .mp4 or .gif (time and residual in the
                          picture; needs the ffmpeg program)
  --fps F                 frames per second of the video (default 30, GIF 20)
  --speed S               motion seconds per video second (default 1; 0.5 = slow motion)
  --benchmark-playback    play the motion for a few seconds and print frames per second
  --seconds S             length of the benchmark (default 5)
  --help, --version
)";
}

}  // namespace saltus::gui
