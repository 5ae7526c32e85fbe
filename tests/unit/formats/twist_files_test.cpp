// The twist analysis's files (formats/twist_files.h) from sources written out by hand: result.json
// carries every share and the sentence, twist.csv one tilt column per flight with its rows, and
// twist.md the sentence and the table.

#include "saltus/formats/twist_files.h"

#include <gtest/gtest.h>

#include <sstream>

#include "saltus/formats/csv_table.h"

namespace saltus {
namespace {

TwistSources hand_made() {
  TwistSources s;
  s.reference_time_s = 0.75;
  s.total_tilt_deg = 20.0;
  s.twists = 1.5;
  s.shares = {{"take-off", 14.0, 70.0}, {"right arm", 5.5, 27.5}, {"left arm", 0.5, 2.5}};
  s.interaction_deg = 0.0;
  s.times = {0.0, 0.75, 1.5};
  s.flight_names = {"actual", "take-off only", "without right arm"};
  s.tilt_deg = {{0.0, 20.0, 22.0}, {0.0, 14.0, 15.0}, {0.0, 15.0, 16.0}};
  s.sentence =
      "Of the 20° of tilt at mid-flight, 70 % came from the take-off, 28 % from the right arm.";
  return s;
}

TEST(TwistFiles, ResultJsonCsvAndMarkdownSayWhatTheSourcesSay) {
  MotionFile file;
  file.path = "m.motion.json";
  file.motion.name = "layout full twist";
  file.model.name = "zatsiorsky-66kg";
  const TwistSources s = hand_made();
  const nlohmann::json r = twist_result_json(file, s);
  EXPECT_EQ(r["format"], kAnalysisFormat);
  EXPECT_EQ(r["analysis"], "twist");
  EXPECT_EQ(r["shares"].size(), 3u);
  EXPECT_EQ(r["shares"][1]["source"], "right arm");
  EXPECT_DOUBLE_EQ(r["shares"][1]["tilt_deg"].get<double>(), 5.5);
  EXPECT_DOUBLE_EQ(r["interaction_deg"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(r["total_tilt_deg"].get<double>(), 20.0);
  EXPECT_EQ(r["sentence"], s.sentence);

  std::stringstream csv(twist_csv(s));
  const CsvTable table = parse_csv_table(csv, "twist.csv");
  EXPECT_EQ(table.columns,
            (std::vector<std::string>{"t", "actual_tilt_deg", "take_off_only_tilt_deg",
                                      "without_right_arm_tilt_deg"}));
  ASSERT_EQ(table.rows.size(), 3u);
  EXPECT_DOUBLE_EQ(table.rows[1][0], 0.75);
  EXPECT_DOUBLE_EQ(table.rows[2][3], 16.0);

  const std::string md = twist_markdown(file, s);
  EXPECT_NE(md.find(s.sentence), std::string::npos);
  EXPECT_NE(md.find("| right arm | 5.5 | 28 % |"), std::string::npos) << md;
  // The shares add up to the total, the table's last row.
  EXPECT_NE(md.find("| left arm | 0.5 | 2 % |\n| total | 20.0 | 100 % |\n"), std::string::npos)
      << md;
  EXPECT_EQ(md.find("together"), std::string::npos) << md;
}

}  // namespace
}  // namespace saltus
