// Animation export decided before rendering: frame times (real time / speed, the landing
// included), formats by file name, ffmpeg's command line.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/video_plan.h"

namespace saltus::gui {
namespace {

TEST(VideoPlan, FramesEverySpeedOverFpsSecondsAndOneOnTheLanding) {
  const VideoPlan plan = plan_video(2.04, 30.0, 0.5);
  // 2.04 s at half speed is 4.08 s of video: 123 frame intervals, 124 frames.
  EXPECT_EQ(plan.frames(), 124);
  EXPECT_DOUBLE_EQ(plan.times.front(), 0.0);
  EXPECT_DOUBLE_EQ(plan.times.back(), 2.04);
  EXPECT_NEAR(plan.times[1], 0.5 / 30.0, 1e-15);
  EXPECT_TRUE(std::is_sorted(plan.times.begin(), plan.times.end()));
  EXPECT_NEAR(plan.video_seconds(), 124 / 30.0, 1e-12);
  // An exact multiple: no extra frame.
  EXPECT_EQ(plan_video(2.0, 20.0, 1.0).frames(), 41);
}

TEST(VideoPlan, FormatsAndDefaults) {
  EXPECT_EQ(video_format_for("a/b/clip.MP4"), VideoFormat::kMp4);
  EXPECT_EQ(video_format_for("clip.gif"), VideoFormat::kGif);
  EXPECT_FALSE(video_format_for("clip.avi"));
  EXPECT_FALSE(video_format_for("gif"));
  EXPECT_DOUBLE_EQ(default_fps(VideoFormat::kGif), 20.0);  // whole hundredths of a second
  EXPECT_DOUBLE_EQ(default_fps(VideoFormat::kMp4), 30.0);
}

TEST(VideoPlan, RejectsWhatCannotBeAVideo) {
  EXPECT_THROW(plan_video(2.0, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(plan_video(2.0, 30.0, 0.0), std::invalid_argument);
  EXPECT_THROW(plan_video(0.0, 30.0, 1.0), std::invalid_argument);
  EXPECT_THROW(plan_video(NAN, 30.0, 1.0), std::invalid_argument);
}

TEST(VideoPlan, FfmpegReadsRawRgbFramesAndWritesTheFormat) {
  const auto mp4 = ffmpeg_arguments(VideoFormat::kMp4, 1280, 720, 30.0, "out.mp4");
  auto after = [&](const std::vector<std::string>& args, const std::string& flag) {
    const auto it = std::find(args.begin(), args.end(), flag);
    return it == args.end() || it + 1 == args.end() ? std::string() : *(it + 1);
  };
  EXPECT_EQ(after(mp4, "-f"), "rawvideo");
  EXPECT_EQ(after(mp4, "-pix_fmt"), "rgb24");
  EXPECT_EQ(after(mp4, "-s"), "1280x720");
  EXPECT_EQ(after(mp4, "-framerate"), "30");
  EXPECT_EQ(after(mp4, "-i"), "-");
  EXPECT_EQ(after(mp4, "-c:v"), "libx264");
  EXPECT_EQ(mp4.back(), "out.mp4");
  const auto gif = ffmpeg_arguments(VideoFormat::kGif, 640, 640, 20.0, "out.gif");
  EXPECT_NE(after(gif, "-vf").find("palettegen"), std::string::npos);
  EXPECT_EQ(after(gif, "-loop"), "0");
  EXPECT_EQ(gif.back(), "out.gif");
}

}  // namespace
}  // namespace saltus::gui
