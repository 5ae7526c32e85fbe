#include "core/video_plan.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "saltus/base/text_format.h"
#include "saltus/use_cases/flag_bounds.h"

namespace saltus::gui {

namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(text[text.size() - suffix.size() + i])) !=
        suffix[i])
      return false;
  return true;
}

}  // namespace

std::optional<VideoFormat> video_format_for(const std::string& path) {
  if (ends_with(path, ".mp4")) return VideoFormat::kMp4;
  if (ends_with(path, ".gif")) return VideoFormat::kGif;
  return std::nullopt;
}

double default_fps(VideoFormat format) {
  return format == VideoFormat::kGif ? 20.0 : 30.0;
}

VideoPlan plan_video(double duration, double fps, double speed) {
  // saltus-gui's --fps and --speed bounds, the same whether given as flags or in the dialog.
  for (const auto& [flag, value] :
       {std::pair<const char*, double>{"--fps", fps}, {"--speed", speed}}) {
    const FlagBound& row = flag_bound(flag, "saltus-gui");
    const std::string problem = bound_problem(row.bound, value, row.why);
    if (!problem.empty()) throw std::invalid_argument(row.meaning + ": " + problem);
  }
  if (!(duration > 0) || !std::isfinite(duration))
    throw std::invalid_argument("the motion has no duration");
  VideoPlan plan;
  plan.fps = fps;
  plan.speed = speed;
  plan.duration = duration;
  const double step = speed / fps;
  // The last frame shows the landing: a frame beyond it (ceil) is moved onto it.
  const int intervals = static_cast<int>(std::ceil(duration / step - 1e-9));
  for (int i = 0; i <= intervals; ++i)
    plan.times.push_back(std::min(i * step, duration));
  return plan;
}

std::vector<std::string> ffmpeg_arguments(VideoFormat format, int width, int height, double fps,
                                          const std::string& output) {
  std::vector<std::string> args = {
      "-y",         "-hide_banner",
      "-loglevel",  "error",
      "-f",         "rawvideo",
      "-pix_fmt",   "rgb24",
      "-s",         std::to_string(width) + "x" + std::to_string(height),
      "-framerate", format_number("%g", fps),
      "-i",         "-"};
  if (format == VideoFormat::kMp4) {
    // yuv420p: what every player reads; +faststart: playable while it downloads.
    args.insert(args.end(), {"-c:v", "libx264", "-preset", "medium", "-crf", "20", "-pix_fmt",
                             "yuv420p", "-movflags", "+faststart"});
  } else {
    // One palette made from the whole clip, then used for every frame; loop forever.
    args.insert(args.end(), {"-vf",
                             "split[a][b];[a]palettegen=stats_mode=diff[p];"
                             "[b][p]paletteuse=dither=bayer:bayer_scale=4",
                             "-loop", "0"});
  }
  args.push_back(output);
  return args;
}

}  // namespace saltus::gui
