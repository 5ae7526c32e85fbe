// `saltus analyse twist` as a program: on a bundled twisting skill it writes its three files and
// prints the sentence it wrote; bad input exits 2 naming the file, and writes nothing.
// `saltus analyse what-if`: a tucked back somersault opened later turns further, the change as
// given is recorded, and a change the motion does not allow exits 2 with the library's reason.

#include <gtest/gtest.h>

#include <cmath>
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
  EXPECT_LT(std::abs(r["interaction_deg"].get<double>()), 1e-9);  // Shapley shares add up
  EXPECT_NE(run.output.find(r["sentence"].get<std::string>()), std::string::npos) << run.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "twist/twist.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "twist/twist.md"));
  // Run again into its own folder: replaced.
  EXPECT_EQ(test::run_cli("analyse twist " + motion + " --out " + (dir / "twist") + " -q").status,
            0);

  // The bundled aerial twist: the arms, not the take-off, in the sentence printed and written.
  const auto aerial = test::run_cli(
      "analyse twist " + std::string(SALTUS_EXAMPLES_DIR) +
      "/motions/full-twisting-back-somersault-from-the-arms.motion.json --out " + (dir / "aerial"));
  ASSERT_EQ(aerial.status, 0) << aerial.output;
  const std::string said = test::read_json(dir / "aerial/result.json")["sentence"];
  EXPECT_NE(said.find("left arm"), std::string::npos) << said;
  EXPECT_EQ(said.find("take-off"), std::string::npos) << said;
  EXPECT_NE(aerial.output.find(said), std::string::npos) << aerial.output;

  test::write_text(dir / "bad.motion.json", "{\"format\": \"saltus-motion/1\"");
  const auto bad =
      test::run_cli("analyse twist " + (dir / "bad.motion.json") + " --out " + (dir / "b"));
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("bad.motion.json"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "b"));
}

TEST(CliAnalyseWhatIf, OpeningATuckedSomersaultLaterTurnsItFurther) {
  test::TempDir dir;
  const std::string m2 =
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/M2-tucked-back-somersault.motion.json";
  const auto run = test::run_cli("analyse what-if " + m2 + " --open-later 0.05 --out " +
                                 (dir / "later") + " --samples 41");
  ASSERT_EQ(run.status, 0) << run.output;
  const nlohmann::json r = test::read_json(dir / "later/result.json");
  EXPECT_EQ(r["analysis"], "what-if");
  EXPECT_DOUBLE_EQ(r["change"]["open_later_s"].get<double>(), 0.05);
  EXPECT_GT(std::abs(r["landing"]["somersaults"].get<double>()),
            std::abs(r["as_is"]["somersaults"].get<double>()));
  EXPECT_GT(r["somersault_vs_as_is_deg"].get<double>(), 0.0);
  EXPECT_NE(run.output.find(r["sentence"].get<std::string>()), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("--open-later"), std::string::npos) << run.output;  // its range
  for (const char* name : {"what_if.csv", "trajectory.csv", "model.json"})
    EXPECT_TRUE(std::filesystem::exists(dir / (std::string("later/") + name))) << name;

  // Earlier, as a negative number, and tighter: the library's words for it.
  const auto earlier =
      test::run_cli("analyse what-if " + m2 + " --tuck-later -0.03 --tuck-scale 1.1 -q --out " +
                    (dir / "earlier"));
  ASSERT_EQ(earlier.status, 0) << earlier.output;
  EXPECT_EQ(test::read_json(dir / "earlier/result.json")["change_words"],
            "tucking 0.03 s earlier, tuck 10 % tighter");

  // Out of the motion's range, or a straight motion: exit 2, the library's reason, no folder.
  const auto far =
      test::run_cli("analyse what-if " + m2 + " --open-later 0.9 --out " + (dir / "far"));
  EXPECT_EQ(far.status, 2) << far.output;
  EXPECT_NE(far.output.find("--open-later: The opening can move from"), std::string::npos)
      << far.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "far"));
  const std::string m1 =
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/M1-straight-back-somersault.motion.json";
  const auto straight =
      test::run_cli("analyse what-if " + m1 + " --tuck-scale 1.1 --out " + (dir / "m1"));
  EXPECT_EQ(straight.status, 2) << straight.output;
  EXPECT_NE(straight.output.find("--tuck-scale: "), std::string::npos) << straight.output;
  EXPECT_NE(straight.output.find("no tuck to change"), std::string::npos) << straight.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "m1"));
}

}  // namespace
}  // namespace saltus
