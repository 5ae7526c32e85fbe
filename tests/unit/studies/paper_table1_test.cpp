// The paper's Table 1 as transcribed (studies/paper_table1.h), checked against the paper's own
// definitions rather than against itself: the average root force is sqrt(J/6) before and after
// (to the table's three digits), and each keyframe adds the same 18 constraints.

#include "saltus/studies/paper_table1.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace saltus {
namespace {

TEST(PaperTable1, FindsTheSevenSkillsByLabelAndNothingElse) {
  for (int i = 0; i < 7; ++i) {
    const std::string label = "M" + std::to_string(i + 1);
    const PaperTableRow* row = paper_table1(label);
    ASSERT_NE(row, nullptr) << label;
    EXPECT_EQ(row, &kPaperTable1[i]);
    EXPECT_EQ(row->label, label);
  }
  for (const char* other : {"M0", "M8", "m1", "dive-5m", ""})
    EXPECT_EQ(paper_table1(other), nullptr) << other;
}

TEST(PaperTable1, AverageForcesAreTheRootOfASixthOfTheObjective) {
  for (const PaperTableRow& row : kPaperTable1) {
    // Both columns are rounded to three digits in the paper: 1 % covers their rounding.
    EXPECT_NEAR(row.force_before, std::sqrt(row.objective_before / 6), 0.01 * row.force_before)
        << row.label;
    EXPECT_NEAR(row.force_after, std::sqrt(row.objective_after / 6), 0.01 * row.force_after)
        << row.label;
    EXPECT_LT(row.objective_after, row.objective_before) << row.label;
  }
}

TEST(PaperTable1, EachKeyframeAddsEighteenConstraints) {
  // The counts were copied one by one; the paper's grow by 18 per keyframe (M1: 89 at 5
  // keyframes, M7: 233 at 13), so a mistyped one shows.
  for (const PaperTableRow& row : kPaperTable1)
    EXPECT_EQ(row.constraints, 89 + 18 * (row.keyframes - 5)) << row.label;
}

}  // namespace
}  // namespace saltus
