// The strength tables as compiled in: every row read, and numbers checked against the
// publications' printed values (Anderson et al. 2007, Table 3; the gymnast's set).

#include <gtest/gtest.h>

#include "saltus/body/strength_tables.h"

namespace saltus {
namespace {

TEST(StrengthTables, ReadsEveryMeanRowOfAndersonsTable3) {
  const std::vector<AndersonRow>& table = anderson2007_table3();
  // 3 joints x 2 directions x 2 sexes x 3 age groups.
  ASSERT_EQ(table.size(), 36u);
  const AndersonRow& first = table.front();
  EXPECT_EQ(first.joint, "hip");
  EXPECT_EQ(first.direction, "extension");
  EXPECT_EQ(first.sex, "male");
  EXPECT_EQ(first.age_group, "18-25");
  EXPECT_DOUBLE_EQ(first.c1, 0.161);
  EXPECT_DOUBLE_EQ(first.c3, 0.932);
  EXPECT_DOUBLE_EQ(first.k2, 5.91);
  const AndersonRow& last = table.back();
  EXPECT_EQ(last.joint, "ankle");
  EXPECT_EQ(last.direction, "flexion");
  EXPECT_EQ(last.sex, "female");
  EXPECT_EQ(last.age_group, "over-65");
  EXPECT_DOUBLE_EQ(last.c1, 0.022);
  EXPECT_DOUBLE_EQ(last.b1, 2.35e-05);
}

TEST(StrengthTables, ReadsTheGymnastsTwentyTwoRows) {
  const std::vector<GymnastRow>& table = gymnast_whole_body();
  ASSERT_EQ(table.size(), 22u);
  EXPECT_EQ(table[2].joint, "knee");
  EXPECT_EQ(table[2].direction, "extension");
  EXPECT_DOUBLE_EQ(table[2].max_isometric_moment_Nm, 285.619);
  EXPECT_EQ(table[14].joint, "elbow");
  EXPECT_EQ(table[14].direction, "flexion");
  EXPECT_DOUBLE_EQ(table[14].max_isometric_moment_Nm, 101.384);
  // The lumbar speeds are the add-on's architectural estimate (resources/strength/README.md).
  EXPECT_EQ(table[20].joint, "lumbar");
  EXPECT_DOUBLE_EQ(table[20].max_angular_velocity_rad_s, 7.98695);
}

}  // namespace
}  // namespace saltus
