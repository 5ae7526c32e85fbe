// saltus-gui's command line: batch flags, positional motion vs result folders, the option
// table's optimiser flags, bad usage.

#include <gtest/gtest.h>

#include <cmath>

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
  ASSERT_EQ(c.options.size(), 1u);
  EXPECT_EQ(c.options[0].first, "max_iterations");
  EXPECT_EQ(c.options[0].second, OptionValue(5));
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

TEST(CommandLine, LectureFigureIsABatchJobWithItsPoses) {
  const CommandLine c = parse_command_line({"m.json", "--lecture-figure", "f.png"});
  EXPECT_TRUE(c.batch());
  EXPECT_EQ(c.lecture_figure, "f.png");
  EXPECT_EQ(c.lecture_poses, kDefaultStroboscopePoses);
  EXPECT_EQ(
      parse_command_line({"m.json", "--lecture-figure", "f.png", "--poses", "12"}).lecture_poses,
      12);
  EXPECT_THROW(parse_command_line({"m.json", "--lecture-figure", "f.png", "--poses", "1"}),
               std::invalid_argument);
  EXPECT_THROW(parse_command_line({"--lecture-figure", "f.png"}), std::invalid_argument);
}

TEST(CommandLine, BenchmarkWithSeconds) {
  const CommandLine c = parse_command_line({"m.json", "--benchmark-playback", "--seconds", "3"});
  EXPECT_TRUE(c.benchmark);
  EXPECT_DOUBLE_EQ(c.benchmark_seconds, 3.0);
}

/// A value of the option other than its default.
OptionValue other_value(const OptionSpec& spec) {
  const OptionValue standard = spec.default_value();
  switch (spec.kind) {
    case OptionKind::kSwitch:
      return !std::get<bool>(standard);
    case OptionKind::kChoice:
      return spec.choices[std::get<std::string>(standard) == spec.choices[0] ? 1 : 0];
    case OptionKind::kInteger:
      return standard == OptionValue(static_cast<int>(spec.min)) ? static_cast<int>(spec.min) + 1
                                                                 : static_cast<int>(spec.min);
    case OptionKind::kReal:
      break;
  }
  const double low = spec.min_exclusive ? spec.min + 0.5 : spec.min;
  return standard == OptionValue(low) ? low + 1 : low;
}

TEST(CommandLine, TakesEveryOptimiserOptionOfTheTable) {
  std::vector<std::string> args{"m.json", "--optimize"};
  OptimizeSettings panel;  // what the Optimise panel shows
  panel.set("samples", 31);
  OptimizeSettings expected = panel;
  for (const OptionSpec& spec : option_table()) {
    const OptionValue value = other_value(spec);
    args.push_back(spec.flag);
    if (spec.kind != OptionKind::kSwitch) args.push_back(option_value_text(value));
    expected.set(spec.name, value);
  }
  const CommandLine c = parse_command_line(args);
  EXPECT_EQ(c.options.size(), option_table().size());
  EXPECT_EQ(c.applied_to(panel), expected);
  // Only what is given changes the panel's values; a word stands for itself.
  const CommandLine some = parse_command_line({"m.json", "--max-iter", "9", "--threads", "auto"});
  OptimizeSettings changed = panel;
  changed.set("max_iterations", 9);
  changed.set("threads", std::string("auto"));
  EXPECT_EQ(some.applied_to(panel), changed);
  // Knots: a number, or auto (the automatic resolution) over a panel that had a number.
  OptimizeSettings numbered = panel;
  numbered.set("knots_per_interval", 3);
  const CommandLine automatic = parse_command_line({"m.json", "--knots-per-interval", "auto"});
  EXPECT_TRUE(automatic.applied_to(numbered).optimize_options().automatic_resolution);
  EXPECT_EQ(automatic.applied_to(numbered), panel);
  // The help text lists the table's flags with their defaults.
  const std::string usage = usage_text();
  for (const OptionSpec& spec : option_table())
    EXPECT_NE(usage.find(spec.flag), std::string::npos) << spec.flag;
  EXPECT_NE(usage.find("--max-iter INT=300"), std::string::npos) << usage;
}

TEST(CommandLine, OptionValuesAreCheckedByTheTable) {
  for (const OptionSpec& spec : option_table()) {
    if (spec.kind == OptionKind::kSwitch) continue;
    // Not a value of any option; and for numbers, just past the range.
    std::vector<std::string> bad{"nonsense"};
    if (spec.kind == OptionKind::kInteger) bad.push_back(std::to_string(int(spec.min) - 1));
    if (spec.kind == OptionKind::kReal && !std::isinf(spec.max))
      bad.push_back(option_value_text(spec.max + 1));
    for (const std::string& text : bad) {
      try {
        parse_command_line({"m.json", spec.flag, text});
        ADD_FAILURE() << "accepted " << spec.flag << " " << text;
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(spec.flag), std::string::npos) << e.what();
      }
    }
  }
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
           {"m.json", "--seconds", "0"},
           {"m.json", "--size", "800x"},
           {"m.json", "--size", "x600"},
           {"m.json", "--size", "800x600x2"},
       })
    EXPECT_THROW(parse_command_line(bad), std::invalid_argument) << bad.back();
  EXPECT_TRUE(parse_command_line({"--help"}).help);
  EXPECT_TRUE(parse_command_line({"-h"}).help);
  EXPECT_TRUE(parse_command_line({"--version"}).version);
  EXPECT_NE(usage_text().find("--export-figures DIR RESULT_DIR"), std::string::npos);
}

}  // namespace
}  // namespace saltus::gui
