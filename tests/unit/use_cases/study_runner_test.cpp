// The study runner and its folders (use_cases/study_runner.h) on a synthetic study whose cases
// compute nothing (each outcome is a function of the case index), so that sharding, merging,
// resuming, crashes and the refusals can be checked quickly and exactly.

#include "saltus/use_cases/study_runner.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <set>

#include "saltus/base/input_error.h"
#include "saltus/formats/convergence_files.h"
#include "saltus/use_cases/convergence_run.h"
#include "support/cli_runner.h"
#include "support/study_compare.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

/// A convergence "study" of `cases` cases. Case i's outcome depends on i alone; each run of a
/// case leaves a file ran-<i>-<pid> in `log` so tests can count what ran. `crash` cases raise
/// SIGSEGV, `interrupt_at` sends SIGINT to the study before returning.
StudyJob synthetic_job(int cases, const std::string& log, std::set<int> crash = {},
                       int interrupt_at = -1, double epsilon = 50) {
  std::vector<StudyCase> list;
  for (int i = 0; i < cases; ++i) {
    StudyCase c;
    c.motion = "M" + std::to_string(1 + i % 3);
    c.formulation = i % 2 ? Formulation::kStrict : Formulation::kRelaxed;
    c.epsilon = i % 2 ? epsilon : 0.0;
    c.mass_segment = "all";
    c.mass_error = 0.1 * (i % 5 - 2);
    c.timing_error_s = 0.05 * (i % 4);
    list.push_back(c);
  }
  ConvergenceStudyOptions options;
  options.epsilons = {epsilon};
  StudyJob job;
  job.study = "convergence";
  job.definition = convergence_definition({}, options);
  job.definition["cases"] = cases;
  for (const StudyCase& c : list)
    job.case_names.push_back(study_case_label(c) + " #" + std::to_string(&c - list.data()));
  job.run_case = [list, log, crash, interrupt_at](int i, const std::string&) {
    test::write_text(log + "/ran-" + std::to_string(i) + "-" + std::to_string(getpid()), "");
    if (crash.count(i)) {
      // Die by the signal as a real crash does: AddressSanitizer's own SIGSEGV handler would
      // report it and exit with a status instead.
      signal(SIGSEGV, SIG_DFL);
      raise(SIGSEGV);
    }
    if (i == interrupt_at) {
      kill(getppid(), SIGINT);  // the study is interrupted and this case dies with it
      raise(SIGINT);
    }
    StudyOutcome o;
    o.study_case = list[i];
    o.status = i % 7 ? "solved" : "max_iterations";
    o.solved = i % 7 != 0;
    o.iterations = 10 + i;
    o.seconds = 0.01 * i;
    o.variables = 297;
    o.constraints = 84;
    o.avg_force_before = 10.0 + i / 3.0;
    o.avg_force_after = 0.5 + i / 7.0;
    o.max_force_after = 3.0 + i;
    o.max_quaternion_error = 0.049;
    CaseRecord r = convergence_case_record(i, o, "");
    r.name += " #" + std::to_string(i);
    return r;
  };
  job.unfinished_case = [list](int i, const WorkerExit& exit) {
    CaseRecord r =
        convergence_case_record(i, unfinished_outcome(list[i], "crashed", 0.0), exit.describe());
    r.name += " #" + std::to_string(i);
    return r;
  };
  return job;
}

int files_starting(const std::string& dir, const std::string& prefix) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    n += e.path().filename().string().rfind(prefix, 0) == 0 ? 1 : 0;
  return n;
}

StudyRunOptions quiet_options(int jobs, StudyShard shard = {}) {
  StudyRunOptions o;
  o.jobs = jobs;
  o.shard = shard;
  return o;
}

TEST(StudyRunner, ShardsMergeToWhatOneRunWrites) {
  test::TempDir dir;
  const StudyJob job = synthetic_job(23, dir.path().string());
  const StudyRunResult whole = run_study(job, dir / "whole", quiet_options(3));
  ASSERT_TRUE(whole.complete);
  EXPECT_EQ(whole.cases_run, 23);
  EXPECT_EQ(files_starting(dir.path().string(), "ran-"), 23);
  for (int k = 1; k <= 4; ++k)
    ASSERT_TRUE(run_study(job, dir / ("s" + std::to_string(k)), quiet_options(2, {k, 4})).complete);
  const nlohmann::json merged =
      merge_study_folders({dir / "s4", dir / "s2", dir / "s1", dir / "s3"}, dir / "merged");
  EXPECT_EQ(merged, whole.result);
  // Byte for byte, the synthetic seconds being the same too.
  for (const char* file : {"convergence.csv", "convergence.md", "result.json", "study.json",
                           "cases/0000.json", "cases/0022.json"})
    EXPECT_EQ(test::read_text(dir / ("merged/" + std::string(file))),
              test::read_text(dir / ("whole/" + std::string(file))))
        << file;
  std::string differences;
  for (const std::string& d : test::study_folder_differences(dir / "whole", dir / "merged"))
    differences += d + "\n";
  EXPECT_EQ(differences, "");
  // A shard folder holds its own cases only.
  int in_shard = 0;
  for (const auto& e : fs::directory_iterator(dir / "s2/cases"))
    in_shard += e.path().extension() == ".json" ? 1 : 0;
  EXPECT_EQ(in_shard, 6);  // 1, 5, 9, 13, 17, 21
}

TEST(StudyRunner, MergeRefusesMissingDoubledAndForeignCases) {
  test::TempDir dir;
  const StudyJob job = synthetic_job(9, dir.path().string());
  for (int k = 1; k <= 3; ++k)
    ASSERT_TRUE(run_study(job, dir / ("s" + std::to_string(k)), quiet_options(2, {k, 3})).complete);
  try {
    merge_study_folders({dir / "s1", dir / "s2"}, dir / "m");
    ADD_FAILURE() << "merged with a shard missing";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("3 of the study's 9 cases are in none of the folders (2, "
                                         "5, 8)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(merge_study_folders({dir / "s1", dir / "s2", dir / "s3", dir / "s1"}, dir / "m"),
               InputError);
  const StudyJob other = synthetic_job(9, dir.path().string(), {}, -1, 60);
  ASSERT_TRUE(run_study(other, dir / "o3", quiet_options(1, {3, 3})).complete);
  try {
    merge_study_folders({dir / "s1", dir / "s2", dir / "o3"}, dir / "m");
    ADD_FAILURE() << "merged another study's shard";
  } catch (const InputError& e) {
    EXPECT_EQ(e.json_path(), "/definition/epsilons/0") << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "m"));
  EXPECT_THROW(merge_study_folders({dir / "nothing"}, dir / "m"), InputError);
}

TEST(StudyRunner, ACrashedCaseIsRecordedAndTheStudyGoesOn) {
  test::TempDir dir;
  const StudyJob job = synthetic_job(8, dir.path().string(), {2, 5});
  const StudyRunResult run = run_study(job, dir / "c", quiet_options(2));
  ASSERT_TRUE(run.complete);
  EXPECT_EQ(run.failed, 2);
  const CaseRecord crashed = read_case_record(dir / "c/cases/0005.json");
  EXPECT_FALSE(crashed.finished());
  EXPECT_EQ(crashed.convergence.status, "crashed");
  EXPECT_NE(crashed.failure.find("signal 11"), std::string::npos) << crashed.failure;
  EXPECT_TRUE(read_case_record(dir / "c/cases/0006.json").finished());
  EXPECT_EQ(run.result["failed"], 2);
}

TEST(StudyRunner, AnInterruptKeepsTheFinishedCasesAndResumeRunsTheRest) {
  test::TempDir dir;
  const std::string log = dir / "log";
  fs::create_directories(log);
  // Case 4 interrupts the study (as Ctrl+C would); one case at a time, in the runner's order.
  const StudyJob interrupted = synthetic_job(12, log, {}, 4);
  const StudyRunResult first = run_study(interrupted, dir / "r", quiet_options(1));
  EXPECT_FALSE(first.complete);
  EXPECT_EQ(first.interrupt_signal, SIGINT);
  EXPECT_FALSE(fs::exists(dir / "r"));
  ASSERT_TRUE(fs::exists(dir / "r.partial/study.json"));
  std::set<int> kept;
  for (const auto& e : fs::directory_iterator(dir / "r.partial/cases"))
    kept.insert(read_case_record(e.path().string()).index);
  EXPECT_EQ(kept.count(4), 0u) << "the interrupted case is not a result";
  EXPECT_EQ(static_cast<int>(kept.size()), first.cases_run);

  const StudyJob job = synthetic_job(12, log);
  // Without --resume the kept cases are not thrown away.
  EXPECT_THROW(run_study(job, dir / "r", quiet_options(2)), InputError);
  // Another study's --resume is refused, naming what differs.
  try {
    StudyRunOptions o = quiet_options(2);
    o.resume = true;
    run_study(synthetic_job(12, log, {}, -1, 70), dir / "r", o);
    ADD_FAILURE() << "resumed another study";
  } catch (const InputError& e) {
    EXPECT_EQ(e.json_path(), "/definition/epsilons/0") << e.what();
  }
  for (const auto& e : fs::directory_iterator(log))
    fs::remove(e.path());
  StudyRunOptions resume = quiet_options(2);
  resume.resume = true;
  std::vector<int> done_counts;
  resume.progress = [&](const StudyProgress& p) { done_counts.push_back(p.done); };
  const StudyRunResult second = run_study(job, dir / "r", resume);
  ASSERT_TRUE(second.complete);
  EXPECT_EQ(second.cases_run, 12 - static_cast<int>(kept.size()));
  for (int index : kept)
    EXPECT_EQ(files_starting(log, "ran-" + std::to_string(index) + "-"), 0)
        << index << " ran again";
  ASSERT_FALSE(done_counts.empty());
  EXPECT_EQ(done_counts.front(), static_cast<int>(kept.size()) + 1);
  EXPECT_EQ(done_counts.back(), 12);
  EXPECT_FALSE(fs::exists(dir / "r.partial"));

  // The same as an uninterrupted run.
  ASSERT_TRUE(run_study(job, dir / "fresh", quiet_options(3)).complete);
  for (const char* file : {"convergence.csv", "result.json", "study.json"})
    EXPECT_EQ(test::read_text(dir / ("r/" + std::string(file))),
              test::read_text(dir / ("fresh/" + std::string(file))))
        << file;
  // Resuming a complete study runs nothing.
  const StudyRunResult third = run_study(job, dir / "r", resume);
  EXPECT_TRUE(third.already_complete);
  EXPECT_EQ(third.cases_run, 0);
}

TEST(StudyRunner, AStudyUnderTheLongestLegalNameKeepsItsCasesBesideItAndResumes) {
  test::TempDir dir;
  const std::string log = dir / "log";
  fs::create_directories(log);
  const std::string out = dir / std::string(255, 's');  // DIR.partial would be 263 bytes
  const std::string partial = study_partial_folder(out);
  EXPECT_EQ(study_partial_folder(dir / "r"), dir / "r.partial");
  EXPECT_EQ(fs::path(partial).parent_path(), dir.path());
  const StudyRunResult first = run_study(synthetic_job(4, log, {}, 2), out, quiet_options(1));
  EXPECT_FALSE(first.complete);
  EXPECT_EQ(first.partial_dir, partial);
  ASSERT_TRUE(fs::exists(partial + "/study.json"));
  StudyRunOptions resume = quiet_options(1);
  resume.resume = true;
  ASSERT_TRUE(run_study(synthetic_job(4, log), out, resume).complete);
  EXPECT_TRUE(fs::exists(out + "/convergence.csv"));
  EXPECT_FALSE(fs::exists(partial));
}

TEST(StudyRunner, NeverReplacesAFolderSaltusDidNotWrite) {
  test::TempDir dir;
  fs::create_directories(dir / "mine");
  test::write_text(dir / "mine/notes.txt", "keep me");
  const StudyJob job = synthetic_job(3, dir.path().string());
  EXPECT_THROW(run_study(job, dir / "mine", quiet_options(1)), InputError);
  EXPECT_EQ(files_starting(dir.path().string(), "ran-"), 0) << "cases ran before the refusal";
  EXPECT_EQ(test::read_text(dir / "mine/notes.txt"), "keep me");
  fs::create_directories(dir / "x.partial");
  test::write_text(dir / "x.partial/notes.txt", "mine too");
  StudyRunOptions resume = quiet_options(1);
  resume.resume = true;
  EXPECT_THROW(run_study(job, dir / "x", resume), InputError);
  EXPECT_EQ(test::read_text(dir / "x.partial/notes.txt"), "mine too");
}

TEST(StudyRunner, AStudyOfAnUnknownKindIsRefusedBeforeAnyCaseRuns) {
  test::TempDir dir;
  fs::create_directories(dir.path() / "log");
  StudyJob job = synthetic_job(3, (dir.path() / "log").string());
  job.study = "convergance";
  try {
    run_study(job, (dir.path() / "out").string(), quiet_options(1));
    FAIL() << "an unknown kind ran";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown study \"convergance\""), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(files_starting((dir.path() / "log").string(), "ran-"), 0);
  EXPECT_FALSE(fs::exists(dir.path() / "out.partial"));
}

}  // namespace
}  // namespace saltus
