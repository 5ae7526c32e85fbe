// The twist analysis's files (formats/twist_files.h) from sources written out by hand: result.json
// carries every share and the sentence, twist.csv one tilt column per flight with its rows, and
// twist.md the sentence and the table; a folder read back gives the same sources, flights named
// as the library names them, and a broken one names its file and field.

#include "saltus/formats/twist_files.h"

#include <gtest/gtest.h>

#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/formats/csv_table.h"
#include "support/cli_runner.h"
#include "support/input_errors.h"

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

/// The three files of `saltus analyse twist` written into `dir` as the CLI writes them.
void write_folder(const std::string& dir, const TwistSources& s) {
  MotionFile file;
  file.path = "m.motion.json";
  file.motion.name = "layout full twist";
  std::filesystem::create_directories(dir);
  test::write_text(dir + "/result.json", twist_result_json(file, s).dump(2));
  test::write_text(dir + "/twist.csv", twist_csv(s));
  test::write_text(dir + "/twist.md", twist_markdown(file, s));
}

TEST(TwistFiles, AFolderReadBackHoldsTheSourcesAsWritten) {
  test::TempDir dir;
  TwistSources s = hand_made();
  s.shares.push_back({"legs", 0.0, 0.0});
  s.flight_names = {"actual", "take-off only", "without right arm"};
  write_folder(dir / "twist", s);
  ASSERT_TRUE(is_twist_analysis_folder(dir / "twist"));
  const TwistFolder f = read_twist_analysis_folder(dir / "twist");
  EXPECT_EQ(f.name, "twist");
  EXPECT_EQ(f.motion, "layout full twist");
  const TwistSources& r = f.sources;
  EXPECT_EQ(r.sentence, s.sentence);
  EXPECT_DOUBLE_EQ(r.total_tilt_deg, s.total_tilt_deg);
  EXPECT_DOUBLE_EQ(r.reference_time_s, s.reference_time_s);
  EXPECT_DOUBLE_EQ(r.twists, s.twists);
  ASSERT_EQ(r.shares.size(), s.shares.size());
  for (std::size_t i = 0; i < s.shares.size(); ++i) {
    EXPECT_EQ(r.shares[i].source, s.shares[i].source);
    EXPECT_DOUBLE_EQ(r.shares[i].tilt_deg, s.shares[i].tilt_deg);
    EXPECT_DOUBLE_EQ(r.shares[i].percent, s.shares[i].percent);
  }
  // "take-off only" and "without right arm", not "take off only": the chart matches on them.
  EXPECT_EQ(r.flight_names, s.flight_names);
  EXPECT_EQ(r.times, s.times);
  EXPECT_EQ(r.tilt_deg, s.tilt_deg);
}

TEST(TwistFiles, ABrokenFolderNamesItsFileAndField) {
  test::TempDir dir;
  // What the reader says when it refuses the folder ("" if it reads it).
  const auto refusal = [&](const char* folder) {
    return test::input_error([&] { read_twist_analysis_folder(dir / folder); });
  };
  write_folder(dir / "a", hand_made());
  std::filesystem::remove(dir.path() / "a" / "twist.csv");
  EXPECT_NE(refusal("a").find("twist.csv"), std::string::npos) << refusal("a");
  write_folder(dir / "b", hand_made());
  test::write_text(dir / "b/twist.csv", "t,actual\n0,1\n");
  EXPECT_NE(refusal("b").find("actual"), std::string::npos) << refusal("b");
  write_folder(dir / "c", hand_made());
  test::write_text(dir / "c/result.json",
                   "{\"format\": \"saltus-analysis/1\", \"analysis\": \"twist\", \"motion\": 3}");
  EXPECT_NE(refusal("c").find("/motion"), std::string::npos) << refusal("c");
  write_folder(dir / "d", hand_made());
  nlohmann::json later = test::read_json(dir / "d/result.json");
  later["format"] = "saltus-analysis/2";
  test::write_text(dir / "d/result.json", later.dump());
  EXPECT_NE(refusal("d").find("/format"), std::string::npos) << refusal("d");
  // Not a twist folder at all: false, so another reader can say what it is.
  test::write_text(dir / "c/result.json", "{\"analysis\": \"what-if\"}");
  EXPECT_FALSE(is_twist_analysis_folder(dir / "c"));
  EXPECT_FALSE(is_twist_analysis_folder(dir / "no-such-folder"));
}

}  // namespace
}  // namespace saltus
