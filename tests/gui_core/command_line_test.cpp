// saltus-gui's command line: batch flags, positional motion vs result folders, bad usage.

#include <gtest/gtest.h>

#include "core/command_line.h"

namespace saltus::gui {
namespace {

TEST(CommandLine, InteractiveWithAMotion) {
  const CommandLine c = parse_command_line({"m.motion.json"});
  EXPECT_EQ(c.motion, "m.motion.json");
  EXPECT_FALSE(c.batch());
  EXPECT_FALSE(parse_command_line({}).batch());
  EXPECT_TRUE(parse_command_line({"m.json", "--optimize"}).optimize);
  EXPECT_FALSE(parse_command_line({"m.json", "--optimize"}).batch());
}

TEST(CommandLine, ScreenshotRunIsBatch) {
  const CommandLine c = parse_command_line({"m.json", "--optimize", "--max-iter", "5", "--time",
                                            "1.25", "--screenshot", "s.png", "--size", "800x600",
                                            "--camera", "follow", "--stage", "before"});
  EXPECT_TRUE(c.batch());
  EXPECT_EQ(c.max_iterations, 5);
  EXPECT_DOUBLE_EQ(*c.time, 1.25);
  EXPECT_EQ(c.screenshot, "s.png");
  EXPECT_EQ(c.width, 800);
  EXPECT_EQ(c.height, 600);
  EXPECT_EQ(c.camera, CameraPreset::kFollow);
  EXPECT_EQ(c.stage, Stage::kBefore);
}

TEST(CommandLine, ExportFiguresTakesTheFoldersAfterIt) {
  const CommandLine only = parse_command_line({"--export-figures", "figs", "out1", "out2"});
  EXPECT_TRUE(only.batch());
  EXPECT_EQ(only.export_figures, "figs");
  EXPECT_EQ(only.result_dirs, (std::vector<std::string>{"out1", "out2"}));
  EXPECT_TRUE(only.motion.empty());
  const CommandLine both =
      parse_command_line({"m.json", "--screenshot", "a.png", "--export-figures", "f", "r"});
  EXPECT_EQ(both.motion, "m.json");
  EXPECT_EQ(both.result_dirs, std::vector<std::string>{"r"});
}

TEST(CommandLine, CompareAndVideoAreBatchJobs) {
  const CommandLine compare =
      parse_command_line({"a.motion.json", "--compare", "b_out", "--screenshot", "c.png"});
  EXPECT_TRUE(compare.batch());
  EXPECT_EQ(compare.compare, "b_out");
  EXPECT_THROW(parse_command_line({"a.json", "--compare", "b.json"}), std::invalid_argument);
  EXPECT_THROW(parse_command_line({"--compare", "b.json", "--screenshot", "c.png"}),
               std::invalid_argument);
  const CommandLine video = parse_command_line(
      {"capture.bvh", "--export-video", "v.gif", "--fps", "12", "--speed", "0.5"});
  EXPECT_TRUE(video.batch());
  EXPECT_EQ(video.motion, "capture.bvh");
  EXPECT_EQ(video.export_video, "v.gif");
  EXPECT_DOUBLE_EQ(video.video_fps, 12.0);
  EXPECT_DOUBLE_EQ(video.video_speed, 0.5);
  EXPECT_THROW(parse_command_line({"a.json", "--export-video", "v.mp4", "--fps", "0"}),
               std::invalid_argument);
  EXPECT_THROW(parse_command_line({"a.json", "--export-video", "v.mp4", "--speed", "20"}),
               std::invalid_argument);
  EXPECT_THROW(parse_command_line({"--export-video", "v.mp4"}), std::invalid_argument);
}

TEST(CommandLine, BenchmarkWithSeconds) {
  const CommandLine c = parse_command_line({"m.json", "--benchmark-playback", "--seconds", "3"});
  EXPECT_TRUE(c.benchmark);
  EXPECT_DOUBLE_EQ(c.benchmark_seconds, 3.0);
}

TEST(CommandLine, RejectsBadUsage) {
  for (const std::vector<std::string>& bad : std::vector<std::vector<std::string>>{
           {"--export-figures", "figs"},
           {"--screenshot", "s.png"},
           {"m.json", "--time"},
           {"m.json", "--time", "abc"},
           {"m.json", "--time", "-1"},
           {"m.json", "--max-iter", "2.5"},
           {"m.json", "--samples", "1"},
           {"m.json", "--size", "800"},
           {"m.json", "--size", "10x10"},
           {"m.json", "--camera", "diagonal"},
           {"m.json", "--stage", "middle"},
           {"m.json", "--frobnicate"},
           {"a.json", "b.json"},
           {"m.json", "--screenshot", "--optimize"},
       })
    EXPECT_THROW(parse_command_line(bad), std::invalid_argument) << bad.back();
  EXPECT_TRUE(parse_command_line({"--help"}).help);
  EXPECT_NE(usage_text().find("--export-figures DIR RESULT_DIR"), std::string::npos);
}

}  // namespace
}  // namespace saltus::gui
