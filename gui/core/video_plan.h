#pragma once
/// @file
/// What an exported animation holds, decided without rendering anything: the motion times of
/// its frames (real time divided by the speed, the last frame on the landing), and the ffmpeg
/// command line that encodes raw RGB frames into an MP4 (H.264) or an animated GIF (one palette
/// for the whole clip).

#include <optional>
#include <string>
#include <vector>

namespace saltus::gui {

enum class VideoFormat { kMp4, kGif };

/// The format a file name asks for (".mp4" or ".gif", any case); nullopt for others.
std::optional<VideoFormat> video_format_for(const std::string& path);

struct VideoPlan {
  double fps = 30.0;          ///< frames per second of the video
  double speed = 1.0;         ///< motion seconds per video second (0.5: slow motion)
  double duration = 0.0;      ///< the motion's flight time, s
  std::vector<double> times;  ///< motion time of each frame, s: 0, speed/fps, ..., duration

  int frames() const { return static_cast<int>(times.size()); }
  /// How long the video plays: frames / fps.
  double video_seconds() const { return frames() / fps; }
};

/// Default frame rates: 30 for MP4; 20 for GIF, whose frame delays are whole hundredths of a
/// second (1/20 s is exact, 1/30 s is not).
double default_fps(VideoFormat format);

/// Frames every speed/fps seconds of motion from 0, plus one on the landing itself. Throws
/// std::invalid_argument for fps outside (0, 120], speed outside [0.05, 10] or duration <= 0.
VideoPlan plan_video(double duration, double fps, double speed);

/// ffmpeg's arguments (without the program) reading width × height RGB frames at `fps` from
/// standard input and writing `output` (replaced if it exists).
std::vector<std::string> ffmpeg_arguments(VideoFormat format, int width, int height, double fps,
                                          const std::string& output);

}  // namespace saltus::gui
