// A study folder's files (formats/study_folder.h): study.json reads back to what was written,
// a difference is named by its first field, records are refused when beyond the study, of
// another case or twice; shards partition the cases.

#include "saltus/formats/study_folder.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "saltus/base/input_error.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

StudyManifest a_manifest() {
  StudyManifest m;
  m.study = "convergence";
  m.cases = 4;
  m.shard = StudyShard{2, 3};
  m.definition = {{"seed", 7}, {"optimize", {{"samples", 101}, {"knots_per_interval", 1}}}};
  return m;
}

CaseRecord a_record(int index, const std::string& name) {
  CaseRecord r;
  r.index = index;
  r.name = name;
  r.role = "convergence";
  r.motion = "M1";
  r.convergence.study_case.motion = "M1";
  r.convergence.status = "solved";
  r.convergence.solved = true;
  return r;
}

TEST(StudyShard, ParsesIOfNAndRefusesTheRest) {
  const StudyShard s = parse_study_shard("2/4");
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 4);
  EXPECT_TRUE(s.holds(1));
  EXPECT_TRUE(s.holds(5));
  EXPECT_FALSE(s.holds(2));
  for (const char* bad : {"0/4", "5/4", "2", "2/", "/4", "a/4", "2/4x", "-1/4", "1/0", ""})
    EXPECT_THROW(parse_study_shard(bad), InputError) << bad;
  // Every case is in exactly one shard.
  for (int n = 1; n <= 5; ++n)
    for (int i = 0; i < 20; ++i) {
      int holders = 0;
      for (int k = 1; k <= n; ++k)
        holders += StudyShard{k, n}.holds(i) ? 1 : 0;
      EXPECT_EQ(holders, 1);
    }
}
TEST(StudyFolder, TheManifestAndRecordsReadBack) {
  test::TempDir dir;
  const StudyManifest m = a_manifest();
  write_study_folder(dir.path().string(), m, {{1, a_record(1, "one")}, {3, a_record(3, "three")}});
  const StudyManifest back = read_study_manifest(dir.path().string());
  EXPECT_EQ(back.study, m.study);
  EXPECT_EQ(back.cases, m.cases);
  EXPECT_EQ(back.shard.text(), "2/3");
  EXPECT_EQ(back.definition, m.definition);
  const auto records = read_case_records(dir.path().string(), m.cases, nullptr);
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records.at(3).name, "three");
  EXPECT_NO_THROW(require_same_study(dir.path().string(), m, false, "itself"));
}

TEST(StudyFolder, ADifferentSettingIsNamedByItsField) {
  test::TempDir dir;
  StudyManifest m = a_manifest();
  write_study_folder(dir.path().string(), m, {});
  StudyManifest other = m;
  other.definition["optimize"]["samples"] = 201;
  try {
    require_same_study(dir.path().string(), other, false, "this command's study");
    FAIL() << "accepted another study";
  } catch (const InputError& e) {
    EXPECT_EQ(e.json_path(), "/definition/optimize/samples") << e.what();
  }
  // Another shard of the same study: refused for a resume, accepted for a merge.
  StudyManifest shard = m;
  shard.shard = StudyShard{1, 3};
  EXPECT_THROW(require_same_study(dir.path().string(), shard, false, "x"), InputError);
  EXPECT_NO_THROW(require_same_study(dir.path().string(), shard, true, "x"));
}

TEST(StudyFolder, RecordsBeyondTheStudyOfAnotherCaseOrTwiceAreRefused) {
  test::TempDir dir;
  write_study_folder(dir.path().string(), a_manifest(), {{1, a_record(1, "one")}});
  const std::vector<std::string> names = {"zero", "one", "two", "three"};
  EXPECT_EQ(read_case_records(dir.path().string(), 4, &names).size(), 1u);
  const std::vector<std::string> renamed = {"zero", "uno", "two", "three"};
  EXPECT_THROW(read_case_records(dir.path().string(), 4, &renamed), InputError);
  EXPECT_THROW(read_case_records(dir.path().string(), 1, nullptr), InputError);
  write_case_record((dir.path() / "cases/9999.json").string(), a_record(1, "one"));
  EXPECT_THROW(read_case_records(dir.path().string(), 4, nullptr), InputError);
  EXPECT_THROW(read_study_manifest((dir.path() / "cases").string()), InputError);
}

}  // namespace
}  // namespace saltus
