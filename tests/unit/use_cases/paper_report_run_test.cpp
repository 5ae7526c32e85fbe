// Loading a paper folder (use_cases/paper_report_run.h): the bundled examples give Table 1's seven
// skills in label order, each with the paper's keyframe count, and the dive; a folder that is not
// one is refused by name. (The whole report: tests/paper/paper_report_test.cpp.)

#include "saltus/use_cases/paper_report_run.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "saltus/base/input_error.h"
#include "saltus/studies/paper_table1.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

TEST(LoadPaperMotions, FindsTheSevenSkillsInOrderAndTheDive) {
  const PaperMotions motions = load_paper_motions(std::string(SALTUS_EXAMPLES_DIR) + "/motions");
  ASSERT_EQ(motions.skills.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i) {
    const LabelledMotion& m = motions.skills[i];
    EXPECT_EQ(m.label, "M" + std::to_string(i + 1));
    EXPECT_EQ(static_cast<int>(m.file.motion.keyframes.size()), paper_table1(m.label)->keyframes)
        << m.label;
  }
  ASSERT_FALSE(motions.dives.empty());
  for (const LabelledMotion& m : motions.dives)
    EXPECT_EQ(m.label.rfind("dive", 0), 0u) << m.label;
}

TEST(LoadPaperMotions, RefusesAFolderWithoutSkills) {
  test::TempDir dir;
  std::filesystem::copy_file(
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/dive-5m-front-one-and-a-half-twists.motion.json",
      dir / "dive-5m.motion.json");
  try {
    load_paper_motions(dir.path().string());
    FAIL() << "a folder with a dive only is no paper folder";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), dir.path().string());
  }
  EXPECT_THROW(load_paper_motions(dir / "missing"), InputError);
}

}  // namespace
}  // namespace saltus
