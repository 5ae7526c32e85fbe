// The athletes study's files (formats/athletes_files.h): a record goes through its JSON and
// back unchanged, athletes.csv holds each record's numbers in ten significant digits, a case
// whose process failed is a row that says so, and a record of another study is refused.

#include "saltus/formats/athletes_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/base/text_format.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

CaseRecord athlete_record(int index, const std::string& name, double force_after) {
  CaseRecord r;
  r.index = index;
  r.name = "M1 on " + name;
  r.kind = CaseKind::kAthlete;
  r.role = "athlete";
  r.motion = "M1";
  AthleteOutcome& o = r.athlete;
  o.athlete = name;
  o.takeoff = index == 0 ? "own model" : "same spin";
  o.mass_kg = 38.0 + index;
  o.height_m = 1.45 + 0.1 * index;
  o.takeoff_angular_momentum = Eigen::Vector3d(-31.25 * (index + 1), 0.5, 1.0 / 3.0);
  o.status = "solved";
  o.solved = true;
  o.iterations = 17;
  o.seconds = 0.75;
  o.avg_root_force_before_N = 123.456789012345;
  o.avg_root_force_after_N = force_after;
  o.max_root_force_after_N = 2.5;
  o.landing_error_before_deg = 12.5;
  o.landing_error_after_deg = 0.25;
  o.somersaults_before = -0.97;
  o.twists_before = 0.01;
  o.somersaults_after = -1.0;
  o.twists_after = -0.001;
  o.peak_moment_joint = "hip_r";
  o.peak_moment_Nm = 80.0;
  o.peak_force_joint = "shoulder_l";
  o.peak_force_N = 300.0;
  o.peak_force_pct_bw = 80.4;
  o.joint_rise_joint = index == 1 ? "ankle_l" : "hip_l";
  o.joint_rise = index == 1 ? 14.375 : 1.25;
  return r;
}

TEST(AthletesFiles, ARecordRoundTripsThroughItsJson) {
  const CaseRecord r = athlete_record(1, "junior", 0.123);
  const CaseRecord back = parse_case_record(case_record_to_json(r), "cases/0001.json");
  EXPECT_EQ(back.kind, CaseKind::kAthlete);
  EXPECT_TRUE(back.solved());
  EXPECT_EQ(case_record_to_json(back), case_record_to_json(r));
  EXPECT_EQ(back.athlete.takeoff_angular_momentum, r.athlete.takeoff_angular_momentum);
  EXPECT_EQ(back.athlete.peak_force_joint, "shoulder_l");
  EXPECT_EQ(back.athlete.joint_rise_joint, "ankle_l");
  EXPECT_DOUBLE_EQ(back.athlete.joint_rise, 14.375);
  // A case file written before the joint rise was recorded reads as unknown (0).
  nlohmann::json older = case_record_to_json(r);
  older["athlete"].erase("joint_rise");
  older["athlete"].erase("joint_rise_joint");
  const CaseRecord old_back = parse_case_record(older, "cases/0001.json");
  EXPECT_EQ(old_back.athlete.joint_rise, 0.0);
  EXPECT_EQ(old_back.athlete.joint_rise_joint, "");
}

TEST(AthletesFiles, TheTablesHoldEveryRecordAndNameAFailure) {
  std::vector<CaseRecord> records = {athlete_record(0, "zatsiorsky-66kg", 0.2),
                                     athlete_record(1, "junior", 0.123)};
  CaseRecord failed = athlete_record(2, "senior", 0.0);
  failed.failure = "killed by signal 9 (Killed)";
  failed.athlete.status = "crashed";
  records.push_back(failed);

  const test::TempDir temporary;
  const std::string dir = temporary / "athletes";
  MotionFile own;
  own.model.name = "zatsiorsky-66kg";
  const nlohmann::json definition = athletes_definition(
      "M1", own, "same-spin", {{"zatsiorsky-66kg", "a"}, {"junior", "b"}, {"senior", "c"}},
      OptimizeOptions{});
  const nlohmann::json result = write_athletes_files(dir, records, definition);
  EXPECT_EQ(result["study"], "athletes");
  EXPECT_EQ(result["failed"], 1);
  ASSERT_EQ(result["cases"].size(), 3u);
  EXPECT_EQ(result["cases"][2]["failure"], "killed by signal 9 (Killed)");

  std::istringstream csv(test::read_text(dir + "/athletes.csv"));
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("athlete,takeoff,mass_kg,height_m,takeoff_L_x,", 0), 0u) << header;
  std::vector<std::string> lines;
  while (std::getline(csv, line))
    lines.push_back(line);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[1].rfind("junior,same spin,39,1.55,-62.5,0.5,0.3333333333,solved,1,17,0.75,"
                           "123.456789,0.123,2.5,12.5,0.25,-0.97,0.01,-1,-0.001,hip_r,80,"
                           "shoulder_l,300,80.4,ankle_l,14.375",
                           0),
            0u)
      << lines[1];
  const auto commas = [](const std::string& s) { return std::count(s.begin(), s.end(), ','); };
  EXPECT_EQ(commas(lines[2]), commas(header)) << lines[2];
  EXPECT_NE(lines[2].find("crashed"), std::string::npos) << lines[2];

  const std::string md = test::read_text(dir + "/athletes.md");
  EXPECT_NE(md.find("# M1 on 3 athletes"), std::string::npos) << md;
  EXPECT_NE(md.find("| zatsiorsky-66kg (own model) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| junior | 39.0 | 1.550 |"), std::string::npos) << md;
  EXPECT_NE(md.find("did not finish: killed by signal 9"), std::string::npos) << md;
  EXPECT_NE(md.find("| 80 (hip_r) | 80 (shoulder_l) | 1.25x (hip_l) |"), std::string::npos) << md;
  // Above 1.5x the table says the load is not the athlete's.
  EXPECT_NE(md.find("| 14.38x (ankle_l), not the athlete's |"), std::string::npos) << md;

  CaseRecord other = records[0];
  other.kind = CaseKind::kMassStudy;
  EXPECT_THROW(write_athletes_files(dir, {other}, definition), InputError);
}

/// The cells of a GFM table row, split on the pipes no backslash escapes, each trimmed and
/// unescaped (GFM's backslash escapes of ASCII punctuation).
std::vector<std::string> markdown_row_cells(const std::string& row) {
  std::vector<std::string> cells;
  std::string cell;
  bool open = false;
  for (std::size_t i = 0; i < row.size(); ++i) {
    const char c = row[i];
    if (c == '\\' && i + 1 < row.size() && std::ispunct(static_cast<unsigned char>(row[i + 1]))) {
      cell += row[++i];
    } else if (c == '|') {
      if (open)
        cells.push_back(cell.substr(cell.find_first_not_of(' ') == std::string::npos
                                        ? cell.size()
                                        : cell.find_first_not_of(' ')));
      open = true;
      cell.clear();
    } else {
      cell += c;
    }
  }
  for (std::string& c : cells)
    while (!c.empty() && c.back() == ' ')
      c.pop_back();
  return cells;
}

TEST(AthletesFiles, NamesWithCommasQuotesNewlinesPipesAndEscapesKeepTheirRows) {
  // The files read back with independent parsers: Python's csv module (RFC 4180) and a GFM row
  // splitter; once a comma, quote, newline or | in a name shifted the row.
  const std::vector<std::string> names = {"Smith, Anna", "the \"rocket\"",  "two\nlines",
                                          "pipe|name",   "red \x1b[31mESC", "ends\\"};
  std::vector<CaseRecord> records;
  for (std::size_t i = 0; i < names.size(); ++i)
    records.push_back(athlete_record(static_cast<int>(i), names[i], 0.1));
  records.back().athlete.peak_force_joint = "knee|l";
  CaseRecord failed = athlete_record(static_cast<int>(names.size()), "a,b|c", 0.0);
  failed.failure = "signal 9 | \"Killed\"\nafter 3 s";
  failed.athlete.status = "crashed";
  records.push_back(failed);
  const test::TempDir temporary;
  const std::string csv_path = temporary / "athletes.csv";
  test::write_text(csv_path, athletes_csv(records));
  const auto python = test::run_command(
      "/usr/bin/python3 -c 'import csv, json, sys; "
      "rows = list(csv.reader(open(sys.argv[1], newline=\"\"), strict=True)); "
      "print(json.dumps(rows))' " +
      csv_path);
  ASSERT_EQ(python.status, 0) << python.output;
  const nlohmann::json rows = nlohmann::json::parse(python.output);
  ASSERT_EQ(rows.size(), records.size() + 1);
  for (std::size_t i = 0; i < records.size(); ++i) {
    ASSERT_EQ(rows[i + 1].size(), rows[0].size()) << i;
    EXPECT_EQ(rows[i + 1][0], records[i].athlete.athlete) << i;
    EXPECT_EQ(rows[i + 1][1], records[i].athlete.takeoff) << i;
  }
  EXPECT_EQ(rows[names.size()][22], "knee|l");

  std::istringstream md(athletes_markdown(records));
  std::string line;
  std::vector<std::vector<std::string>> table;
  while (std::getline(md, line))
    table.push_back(markdown_row_cells(line));
  ASSERT_EQ(table.size(), records.size() + 2) << athletes_markdown(records);
  for (std::size_t i = 0; i < records.size(); ++i) {
    ASSERT_EQ(table[i + 2].size(), table[0].size()) << i << ": " << athletes_markdown(records);
    EXPECT_EQ(table[i + 2][0],
              printable(records[i].athlete.athlete) + (i == 0 ? " (own model)" : ""));
  }
  EXPECT_EQ(table[names.size() + 1][12], "80 (knee|l)");
  EXPECT_EQ(table.back()[3], "did not finish: " + printable(failed.failure));
  EXPECT_EQ(athletes_markdown(records).find('\x1b'), std::string::npos);
}

}  // namespace
}  // namespace saltus
