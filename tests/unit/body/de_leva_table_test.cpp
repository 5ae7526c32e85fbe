// Tests for de Leva's Table 4 as copied (body/de_leva_table.h): its own sums and its trunk's
// three parts against its whole trunk, and the male lengths against the relative lengths other
// sources print (a typo in a copied number breaks one of these).

#include "saltus/body/de_leva_table.h"

#include <gtest/gtest.h>

#include <cmath>

namespace saltus {
namespace {

using P = DeLevaPart;

bool dl_paired(P part) {
  return part != P::kHead && part != P::kUpperTrunk && part != P::kMiddleTrunk &&
         part != P::kLowerTrunk && part != P::kTrunk && part != P::kTrunkMids;
}

TEST(DeLevaTable, MassFractionsOfTheWholeBodySumToOne) {
  for (const Sex sex : {Sex::kMale, Sex::kFemale}) {
    double percent = 0.0;
    for (const DeLevaRow& row : de_leva_rows(sex)) {
      if (row.part == P::kTrunk || row.part == P::kTrunkMids) continue;
      percent += (dl_paired(row.part) ? 2.0 : 1.0) * row.mass_percent;
    }
    // As printed: 100.00 % male, 99.99 % female (rounding of the printed fractions).
    EXPECT_NEAR(percent, sex == Sex::kMale ? 100.0 : 99.99, 1e-9) << sex_name(sex);
  }
}

TEST(DeLevaTable, TheTrunksThreePartsComposeIntoTheWholeTrunk) {
  for (const Sex sex : {Sex::kMale, Sex::kFemale}) {
    const DeLevaRow& whole = de_leva_row(sex, P::kTrunk);
    double mass = 0.0;
    double length = 0.0;
    double moment = 0.0;  // Σ m·y, y from SUPR
    struct Piece {
      double m, y, r_sag, r_trans, r_long;
    };
    std::vector<Piece> pieces;
    for (const P part : {P::kUpperTrunk, P::kMiddleTrunk, P::kLowerTrunk}) {
      const DeLevaRow& r = de_leva_row(sex, part);
      const double y = length + r.com_percent / 100.0 * r.length_mm;
      pieces.push_back({r.mass_percent, y, r.r_sagittal / 100.0 * r.length_mm,
                        r.r_transverse / 100.0 * r.length_mm,
                        r.r_longitudinal / 100.0 * r.length_mm});
      mass += r.mass_percent;
      moment += r.mass_percent * y;
      length += r.length_mm;
    }
    EXPECT_NEAR(mass, whole.mass_percent, 1e-9) << sex_name(sex);
    EXPECT_NEAR(length, whole.length_mm, 1e-9) << sex_name(sex);
    const double com = moment / mass;
    // de Leva's male trunk CoM is 0.55 % of its length from his parts' (his own rounding).
    EXPECT_NEAR(100.0 * com / length, whole.com_percent, 0.6) << sex_name(sex);
    // Radii of gyration by the parallel-axis theorem: within 0.05 % of the length.
    double sag = 0.0, trans = 0.0, lon = 0.0;
    for (const Piece& p : pieces) {
      sag += p.m * (p.r_sag * p.r_sag + (p.y - com) * (p.y - com));
      trans += p.m * (p.r_trans * p.r_trans + (p.y - com) * (p.y - com));
      lon += p.m * p.r_long * p.r_long;
    }
    EXPECT_NEAR(100.0 * std::sqrt(sag / mass) / length, whole.r_sagittal, 0.05) << sex_name(sex);
    EXPECT_NEAR(100.0 * std::sqrt(trans / mass) / length, whole.r_transverse, 0.05)
        << sex_name(sex);
    EXPECT_NEAR(100.0 * std::sqrt(lon / mass) / length, whole.r_longitudinal, 0.05)
        << sex_name(sex);
  }
}

TEST(DeLevaTable, MaleLengthsOverHisStatureAreThePublishedRelativeLengths) {
  // Relative segment lengths (length / stature) as other open sources print them for the male.
  const struct {
    P part;
    double relative;
  } published[] = {{P::kThigh, 0.2425}, {P::kUpperArm, 0.1618}, {P::kForearm, 0.1544},
                   {P::kHand, 0.0495},  {P::kShank, 0.2529},    {P::kTrunk, 0.3055},
                   {P::kFoot, 0.1482},  {P::kHead, 0.1168}};
  for (const auto& p : published)
    EXPECT_NEAR(de_leva_row(Sex::kMale, p.part).length_mm / 1000.0 / de_leva_stature(Sex::kMale),
                p.relative, 6e-5)
        << de_leva_row(Sex::kMale, p.part).name;
}

TEST(DeLevaTable, RowsAreInPartOrderForBothSexes) {
  for (const Sex sex : {Sex::kMale, Sex::kFemale}) {
    const auto& rows = de_leva_rows(sex);
    ASSERT_EQ(rows.size(), 12u);
    for (std::size_t i = 0; i < rows.size(); ++i)
      EXPECT_EQ(static_cast<std::size_t>(rows[i].part), i);
  }
  EXPECT_EQ(sex_name(Sex::kFemale), "female");
  EXPECT_DOUBLE_EQ(de_leva_stature(Sex::kFemale), 1.735);
}

}  // namespace
}  // namespace saltus
