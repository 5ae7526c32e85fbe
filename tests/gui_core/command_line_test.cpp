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

TEST(CommandLine, BenchmarkWithSeconds) {
  const CommandLine c = parse_command_line({"m.json", "--benchmark-playback", "--seconds", "3"});
  EXPECT_TRUE(c.benchmark);
  EXPECT_DOUBLE_EQ(c.benchmark_seconds, 3.0);
}

TEST(CommandLine, TakesEveryOptimiserOptionOfTheTable) {
  const CommandLine c = parse_command_line({"m.json",
                                            "--optimize",
                                            "--formulation",
                                            "strict",
                                            "--epsilon",
                                            "20",
                                            "--no-timing",
                                            "--knots-per-interval",
                                            "2",
                                            "--samples",
                                            "61",
                                            "--max-iter",
                                            "0",
                                            "--tol",
                                            "1e-6",
                                            "--objective-change-tol",
                                            "0",
                                            "--max-time-shift",
                                            "0.1",
                                            "--regularization",
                                            "2",
                                            "--max-joint-turn",
                                            "90",
                                            "--threads",
                                            "auto"});
  EXPECT_EQ(c.options.size(), option_table().size());
  // Over the panel's values (or the defaults in batch runs), the given ones win.
  OptimizeSettings panel;
  panel.set("samples", 31);
  panel.set("max_iterations", 9);
  const OptimizeOptions o = to_optimize_options(c.applied_to(panel));
  EXPECT_EQ(o.nlp.formulation, Formulation::kStrict);
  EXPECT_EQ(o.nlp.epsilon, 20.0);
  EXPECT_FALSE(o.nlp.optimize_timing);
  EXPECT_EQ(o.nlp.knots_per_interval, 2);
  EXPECT_EQ(o.nlp.samples, 61);
  EXPECT_EQ(o.solver.max_iterations, 0);
  EXPECT_EQ(o.solver.tolerance, 1e-6);
  EXPECT_EQ(o.solver.objective_change_tolerance, 0.0);
  EXPECT_EQ(o.nlp.max_time_shift, 0.1);
  EXPECT_EQ(o.nlp.regularization, 2.0);
  EXPECT_NEAR(o.nlp.joint_turn_limit, M_PI / 2, 1e-15);
  EXPECT_EQ(o.nlp.threads, 0);
  // Only what is given changes the panel's values.
  const OptimizeSettings kept = parse_command_line({"m.json", "--samples", "41"}).applied_to(panel);
  EXPECT_EQ(kept.integer("samples"), 41);
  EXPECT_EQ(kept.integer("max_iterations"), 9);
  // The help text lists the table's flags with their defaults.
  const std::string usage = usage_text();
  for (const OptionSpec& spec : option_table())
    EXPECT_NE(usage.find(spec.flag), std::string::npos) << spec.flag;
  EXPECT_NE(usage.find("--max-iter INT=300"), std::string::npos) << usage;
}

TEST(CommandLine, OptionValuesAreCheckedByTheTable) {
  for (const std::vector<std::string>& bad : std::vector<std::vector<std::string>>{
           {"m.json", "--samples", "100001"},
           {"m.json", "--max-iter", "-1"},
           {"m.json", "--epsilon", "0"},
           {"m.json", "--formulation", "loose"},
           {"m.json", "--threads", "0"},
           {"m.json", "--max-joint-turn", "abc"},
       }) {
    try {
      parse_command_line(bad);
      ADD_FAILURE() << "accepted " << bad[1] << " " << bad[2];
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(bad[1]), std::string::npos) << e.what();
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
