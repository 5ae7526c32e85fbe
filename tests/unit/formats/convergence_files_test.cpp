// The convergence study's tables and files (formats/convergence_files.h): every case counted
// once in each breakdown, one CSV row per case, and the folder written all or nothing.

#include "saltus/formats/convergence_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "support/cli_runner.h"

namespace saltus {
namespace {

TEST(ConvergenceTables, CountEveryCaseOnceInEachBreakdown) {
  std::vector<StudyOutcome> outcomes;
  for (int i = 0; i < 4; ++i) {
    StudyOutcome o;
    o.study_case.motion = i < 2 ? "M1" : "M7";
    o.study_case.formulation = i % 2 ? Formulation::kStrict : Formulation::kRelaxed;
    o.study_case.epsilon = i % 2 ? 10 : 0;
    o.study_case.mass_segment = "all";
    o.solved = i != 3;  // strict fails on M7
    o.status = o.solved ? "solved" : "max_iterations";
    outcomes.push_back(o);
  }
  const std::string md = convergence_markdown(outcomes);
  EXPECT_NE(md.find("| relaxed | 2 | 2 (100 %)"), std::string::npos) << md;
  EXPECT_NE(md.find("| strict ε=10 | 2 | 1 (50 %)"), std::string::npos) << md;
  EXPECT_NE(md.find("| M7 | 1/1 | 0/1 |"), std::string::npos) << md;
  const std::string csv = convergence_csv(outcomes);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);  // header + 4 cases
  EXPECT_NE(csv.find("M7,strict,10,all,0,0,max_iterations,0,"), std::string::npos) << csv;
}

TEST(ConvergenceFiles, FolderHoldsTheTablesAndOneResultEntryPerCase) {
  std::vector<StudyOutcome> outcomes(3);
  for (int i = 0; i < 3; ++i) {
    outcomes[i].study_case.motion = "M" + std::to_string(i + 1);
    outcomes[i].study_case.mass_segment = "all";
    outcomes[i].status = "solved";
    outcomes[i].solved = true;
    outcomes[i].iterations = 10 * (i + 1);
  }
  ConvergenceStudyOptions options;
  options.seed = 42;
  test::TempDir dir;
  const nlohmann::json result = write_convergence_outputs(dir / "conv", outcomes, options);
  EXPECT_EQ(result["study"], "convergence");
  EXPECT_EQ(result["seed"], 42);
  ASSERT_EQ(result["cases"].size(), 3u);
  EXPECT_EQ(result["cases"][2]["motion"], "M3");
  EXPECT_EQ(result["cases"][2]["iterations"], 30);
  EXPECT_EQ(nlohmann::json::parse(test::read_text(dir / "conv/result.json")), result);
  EXPECT_EQ(test::read_text(dir / "conv/convergence.csv"), convergence_csv(outcomes));
  EXPECT_NE(test::read_text(dir / "conv/convergence.md").find(convergence_markdown(outcomes)),
            std::string::npos);
}

}  // namespace
}  // namespace saltus
