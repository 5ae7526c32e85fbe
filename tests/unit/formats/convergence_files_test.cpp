// The convergence study's tables and files (formats/convergence_files.h): every case counted
// once in each breakdown, one CSV row per case, the folder written all or nothing, the summary
// per formulation as numbers, and a study's folder (finished or interrupted) read back from its
// records.

#include "saltus/formats/convergence_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "saltus/base/input_error.h"
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
  options.strict_checkpoints = {{80, 20.0}};
  options.optimize.nlp.samples = 57;
  const nlohmann::json result =
      write_convergence_files(dir / "conv", outcomes, convergence_definition({}, options));
  EXPECT_EQ(result["study"], "convergence");
  EXPECT_EQ(result["seed"], 42);
  EXPECT_EQ(result["samples"], 57);
  EXPECT_EQ(result["strict_checkpoints"], nlohmann::json::parse("[[80, 20.0]]"));
  ASSERT_EQ(result["cases"].size(), 3u);
  EXPECT_EQ(result["cases"][2]["motion"], "M3");
  EXPECT_EQ(result["cases"][2]["iterations"], 30);
  EXPECT_EQ(nlohmann::json::parse(test::read_text(dir / "conv/result.json")), result);
  EXPECT_EQ(test::read_text(dir / "conv/convergence.csv"), convergence_csv(outcomes));
  EXPECT_NE(test::read_text(dir / "conv/convergence.md").find(convergence_markdown(outcomes)),
            std::string::npos);
}

/// Six cases of M1: relaxed (solved: 10, 30, 20 iterations) and strict ε=50 (one solved, one not,
/// one crashed).
std::vector<StudyOutcome> six_outcomes() {
  std::vector<StudyOutcome> outcomes(6);
  for (int i = 0; i < 6; ++i) {
    StudyOutcome& o = outcomes[i];
    o.study_case.motion = "M1";
    o.study_case.mass_segment = "all";
    o.study_case.timing_error_s = 0.05 * (i % 3);
    o.study_case.formulation = i < 3 ? Formulation::kRelaxed : Formulation::kStrict;
    o.study_case.epsilon = i < 3 ? 0.0 : 50.0;
    o.knots_per_interval = 1;
  }
  const int iterations[6] = {10, 30, 20, 80, 150, 0};
  const double seconds[6] = {1.0, 3.0, 2.0, 8.0, 15.0, 900.0};
  const double force[6] = {0.5, 0.25, 0.125, 2.0, 40.0, 0.0};
  const char* status[6] = {"solved", "solved", "solved", "solved", "stopped_infeasible", "crashed"};
  for (int i = 0; i < 6; ++i) {
    outcomes[i].iterations = iterations[i];
    outcomes[i].seconds = seconds[i];
    outcomes[i].avg_force_after = force[i];
    outcomes[i].status = status[i];
    outcomes[i].solved = outcomes[i].status == "solved";
  }
  return outcomes;
}

TEST(ConvergenceTables, SummaryGivesTheMarkdownTablesNumbers) {
  const std::vector<StudyOutcome> outcomes = six_outcomes();
  const std::vector<ConvergenceSummaryRow> rows = convergence_summary(outcomes);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].model, "relaxed");
  EXPECT_EQ(rows[0].cases, 3);
  EXPECT_EQ(rows[0].solved, 3);
  EXPECT_EQ(rows[0].median_iterations, 20.0);
  EXPECT_EQ(rows[0].median_seconds, 2.0);
  EXPECT_EQ(rows[0].median_force_after_N, 0.25);
  EXPECT_EQ(rows[0].worst_force_after_N, 0.5);
  // The crashed case counts among the cases, not in the medians.
  EXPECT_EQ(rows[1].model, "strict ε=50");
  EXPECT_EQ(rows[1].cases, 3);
  EXPECT_EQ(rows[1].solved, 1);
  EXPECT_EQ(rows[1].median_iterations, 115.0);
  EXPECT_EQ(rows[1].median_seconds, 11.5);
  EXPECT_EQ(rows[1].median_force_after_N, 21.0);
  EXPECT_EQ(rows[1].worst_force_after_N, 2.0);
  EXPECT_EQ(convergence_summary_cells(rows[0]),
            (std::vector<std::string>{"relaxed", "3", "3 (100 %)", "20", "2.00", "0.25", "0.5"}));
  EXPECT_EQ(convergence_summary_headings().size(), convergence_summary_cells(rows[0]).size());
  const std::string md = convergence_markdown(outcomes);
  EXPECT_NE(md.find("| model | cases | solved | median iterations | median time (s) | median avg "
                    "root force after (N) | worst avg root force after, solved cases (N) |\n"
                    "|---|---|---|---|---|---|---|\n"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| relaxed | 3 | 3 (100 %) | 20 | 2.00 | 0.25 | 0.5 |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| strict ε=50 | 3 | 1 (33 %) | 115 | 11.50 | 21 | 2 |"), std::string::npos)
      << md;

  // A formulation with nothing solved has no worst; with nothing finished, no medians.
  std::vector<StudyOutcome> failed(outcomes.begin() + 5, outcomes.end());
  const std::vector<ConvergenceSummaryRow> none = convergence_summary(failed);
  ASSERT_EQ(none.size(), 1u);
  EXPECT_EQ(none[0].solved, 0);
  EXPECT_TRUE(std::isnan(none[0].median_iterations));
  EXPECT_TRUE(std::isnan(none[0].worst_force_after_N));
  EXPECT_NE(
      convergence_markdown(failed).find("| strict ε=50 | 1 | 0 (0 %) | nan | nan | nan | – |"),
      std::string::npos)
      << convergence_markdown(failed);
}

/// A study folder as the runner leaves it: study.json and the records of `recorded` cases of
/// `outcomes`, and the tables when every case is there.
void write_study(const std::string& dir, const std::vector<StudyOutcome>& outcomes, int recorded,
                 const std::string& study = "convergence", StudyShard shard = StudyShard{}) {
  ConvergenceStudyOptions options;
  StudyManifest manifest;
  manifest.study = study;
  manifest.cases = static_cast<int>(outcomes.size());
  manifest.shard = shard;
  manifest.definition = convergence_definition({}, options);
  std::map<int, CaseRecord> records;
  for (int i = 0; i < recorded; ++i) {
    CaseRecord r;
    r.index = i;
    r.name = study_case_label(outcomes[i].study_case);
    r.role = "convergence";
    r.motion = outcomes[i].study_case.motion;
    r.failure = outcomes[i].status == "crashed" ? "killed by signal 11 (Segmentation fault)" : "";
    r.convergence = outcomes[i];
    records.emplace(i, r);
  }
  std::filesystem::create_directories(dir);
  write_study_folder(dir, manifest, records);
  if (recorded == manifest.cases) write_convergence_files(dir, outcomes, manifest.definition);
}

TEST(ConvergenceStudyFolder, ReadsAFinishedStudyBackFromItsRecords) {
  test::TempDir tmp;
  const std::string dir = tmp / "study";
  const std::vector<StudyOutcome> outcomes = six_outcomes();
  write_study(dir, outcomes, 6);
  const ConvergenceStudyFolder folder = read_convergence_study_folder(dir);
  EXPECT_EQ(folder.path, dir);
  EXPECT_EQ(folder.cases, 6);
  EXPECT_TRUE(folder.complete());
  EXPECT_EQ(folder.unfinished, 1);
  ASSERT_EQ(folder.outcomes.size(), 6u);
  // What the tables were written from, case by case.
  EXPECT_EQ(convergence_csv(folder.outcomes), convergence_csv(outcomes));
  EXPECT_EQ(convergence_markdown(folder.outcomes), convergence_markdown(outcomes));
  ASSERT_EQ(folder.summary.size(), 2u);
  EXPECT_EQ(folder.summary[1].model, "strict ε=50");
  EXPECT_EQ(folder.summary[1].solved, 1);
  EXPECT_EQ(folder.markdown_path, dir + "/convergence.md");
  EXPECT_EQ(folder.csv_path, dir + "/convergence.csv");
}

TEST(ConvergenceStudyFolder, ReadsAnInterruptedStudysFinishedCases) {
  test::TempDir tmp;
  const std::string dir = tmp / "study.partial";
  write_study(dir, six_outcomes(), 2);
  const ConvergenceStudyFolder folder = read_convergence_study_folder(dir);
  EXPECT_EQ(folder.cases, 6);
  EXPECT_FALSE(folder.complete());
  ASSERT_EQ(folder.outcomes.size(), 2u);
  EXPECT_EQ(folder.outcomes[1].iterations, 30);
  ASSERT_EQ(folder.summary.size(), 1u);
  EXPECT_EQ(folder.summary[0].cases, 2);
  EXPECT_TRUE(folder.markdown_path.empty());
  EXPECT_TRUE(folder.csv_path.empty());
}

TEST(ConvergenceStudyFolder, RefusesWhatIsNotAWholeConvergenceStudy) {
  test::TempDir tmp;
  auto message = [](const std::string& dir) {
    try {
      read_convergence_study_folder(dir);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::filesystem::create_directories(tmp / "empty");
  EXPECT_NE(message(tmp / "empty").find("empty"), std::string::npos) << message(tmp / "empty");
  write_study(tmp / "paper", six_outcomes(), 1, "paper");
  EXPECT_NE(message(tmp / "paper").find("not a convergence study"), std::string::npos)
      << message(tmp / "paper");
  write_study(tmp / "shard", six_outcomes(), 1, "convergence", StudyShard{1, 2});
  EXPECT_NE(message(tmp / "shard").find("merge the shards"), std::string::npos)
      << message(tmp / "shard");
  // A record of another kind is named by its file.
  write_study(tmp / "mixed", six_outcomes(), 2);
  CaseRecord other = read_case_record(tmp / "mixed/cases/0001.json");
  other.kind = CaseKind::kMassStudy;
  write_case_record(tmp / "mixed/cases/0001.json", other);
  EXPECT_NE(message(tmp / "mixed").find("0001.json"), std::string::npos) << message(tmp / "mixed");
}

}  // namespace
}  // namespace saltus
