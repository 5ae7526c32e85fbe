// `saltus analyse twist` as a program: on a bundled twisting skill it writes its three files and
// prints the sentence it wrote; bad input exits 2 naming the file, and writes nothing.

#include <gtest/gtest.h>

#include <filesystem>

#include "support/cli_runner.h"

namespace saltus {
namespace {

TEST(CliAnalyseTwist, WritesTheSharesAndSaysWhereTheTwistComesFrom) {
  test::TempDir dir;
  const std::string motion = std::string(SALTUS_EXAMPLES_DIR) +
                             "/motions/M5-front-somersault-one-and-a-half-twists.motion.json";
  const auto run = test::run_cli("analyse twist " + motion + " --out " + (dir / "twist"));
  ASSERT_EQ(run.status, 0) << run.output;
  const nlohmann::json r = test::read_json(dir / "twist/result.json");
  EXPECT_EQ(r["analysis"], "twist");
  EXPECT_GT(std::abs(r["total_tilt_deg"].get<double>()), 10.0);
  EXPECT_GT(std::abs(r["twists"].get<double>()), 1.0);
  double sum = r["interaction_deg"].get<double>();
  for (const auto& share : r["shares"])
    sum += share["tilt_deg"].get<double>();
  EXPECT_NEAR(sum, r["total_tilt_deg"].get<double>(), 1e-9);
  EXPECT_NE(run.output.find(r["sentence"].get<std::string>()), std::string::npos) << run.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "twist/twist.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "twist/twist.md"));
  // Run again into its own folder: replaced.
  EXPECT_EQ(test::run_cli("analyse twist " + motion + " --out " + (dir / "twist") + " -q").status,
            0);

  test::write_text(dir / "bad.motion.json", "{\"format\": \"saltus-motion/1\"");
  const auto bad =
      test::run_cli("analyse twist " + (dir / "bad.motion.json") + " --out " + (dir / "b"));
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("bad.motion.json"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "b"));
}

}  // namespace
}  // namespace saltus
