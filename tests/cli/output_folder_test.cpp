// Output folders that cannot destroy anything (issue 16, items 1-3 and 6; docs/safety.md): a
// folder Saltus did not write is never replaced; a kill at any point leaves the old or the new
// complete folder; Ctrl+C and kills leave no litter that outlives the next run; a full disk and
// concurrent runs fail with exit status 4 and a reason, changing nothing.

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "saltus/formats/output_kind.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;
using test::names_in;
using test::read_json;
using test::run_cli;
using test::run_command;
using test::TempDir;

/// Hidden entries Saltus uses while writing DIR (temporaries, the lock).
std::set<std::string> hidden_in(const fs::path& folder) {
  std::set<std::string> found;
  for (const std::string& name : names_in(folder))
    if (!name.empty() && name[0] == '.') found.insert(name);
  return found;
}

const std::set<std::string> kEvaluateFiles = {"result.json", "trajectory.csv", "model.json",
                                              kFolderRecordName};

std::string evaluate(const std::string& out, int samples, const std::string& extra = "") {
  return "evaluate " + test::m1_path() + " --out " + out + " --samples " + std::to_string(samples) +
         " -q" + extra;
}

/// Starts `command` (one program, no shell features) and returns its pid.
pid_t spawn(const std::string& command) {
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", ("exec " + command + " >/dev/null 2>&1").c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

/// Waits until `folder` holds an entry starting with `prefix`; false after `seconds`.
bool wait_for_entry(const fs::path& folder, const std::string& prefix, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    for (const std::string& name : names_in(folder))
      if (name.compare(0, prefix.size(), prefix) == 0) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

std::string paper_command(const std::string& out) {
  return std::string(SALTUS_CLI_PATH) + " paper " + SALTUS_EXAMPLES_DIR + "/motions --out " + out +
         " --quick -q";
}

TEST(OutputFolder, NeverReplacesAFolderItDidNotWrite) {
  // Issue 16 item 1: another tool's result.json beside a user's files was taken for a result.
  TempDir dir;
  const fs::path thesis = dir.path() / "thesis";
  fs::create_directories(thesis / "src");
  test::write_text((thesis / "thesis.tex").string(), "\\documentclass{article}");
  test::write_text((thesis / "src/main.c").string(), "int main(void) { return 0; }");
  test::write_text((thesis / "result.json").string(), R"({"format": "other-tool/2"})");
  const std::set<std::string> before = names_in(thesis);

  const auto run = run_cli(evaluate(thesis.string(), 11, ""));
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("not overwriting this folder"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("--out folder that does not exist"), std::string::npos) << run.output;
  // `--out .` from inside it.
  const auto here =
      run_command("cd " + thesis.string() + " && " + SALTUS_CLI_PATH + " " + evaluate(".", 11, ""));
  EXPECT_EQ(here.status, 2) << here.output;
  EXPECT_EQ(names_in(thesis), before);
  EXPECT_EQ(test::read_text((thesis / "src/main.c").string()), "int main(void) { return 0; }");
  EXPECT_EQ(names_in(dir.path()), std::set<std::string>{"thesis"});
}

TEST(OutputFolder, ReplacesItsOwnResultsOnlyWhileTheyHoldOnlyItsFiles) {
  TempDir dir;
  const std::string out = dir / "out";
  ASSERT_EQ(run_cli(evaluate(out, 11)).status, 0);
  ASSERT_EQ(run_cli("simulate " + test::m1_path() + " --out " + out + " --samples 12 -q").status,
            0);
  EXPECT_EQ(read_json(out + "/result.json")["status"], "simulated");
  const auto optimize =
      run_cli("optimize " + test::m1_path() + " --out " + out + " --samples 13 --max-iter 2 -q");
  ASSERT_TRUE(optimize.status == 0 || optimize.status == 3) << optimize.output;
  ASSERT_EQ(run_cli(evaluate(out, 14)).status, 0);
  EXPECT_EQ(read_json(out + "/result.json")["samples"], 14);
  EXPECT_EQ(names_in(out), kEvaluateFiles);

  // A file of the user's inside an earlier result makes it the user's folder.
  test::write_text(out + "/notes.txt", "my notes");
  const auto refused = run_cli(evaluate(out, 15));
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("notes.txt"), std::string::npos) << refused.output;
  EXPECT_EQ(read_json(out + "/result.json")["samples"], 14);
  fs::remove(out + "/notes.txt");
  EXPECT_EQ(run_cli(evaluate(out, 15)).status, 0);

  // `--out .` from inside a result: replaced (the shell is left in the removed old folder, as
  // with any program that replaces the folder a shell is in; `cd "$PWD"` enters the new one).
  const auto here = run_command("cd " + out + " && " + SALTUS_CLI_PATH + " " + evaluate(".", 16) +
                                " && cd \"$PWD\" && cat result.json");
  EXPECT_EQ(here.status, 0) << here.output;
  EXPECT_NE(here.output.find("\"samples\": 16"), std::string::npos) << here.output;

  const std::string link = dir / "link";
  fs::create_directory_symlink(out, link);
  const auto linked = run_cli(evaluate(link, 17));
  EXPECT_EQ(linked.status, 2) << linked.output;
  EXPECT_NE(linked.output.find("symbolic link"), std::string::npos) << linked.output;
  EXPECT_EQ(hidden_in(dir.path()), std::set<std::string>{});
}

TEST(OutputFolder, ImportReplacesItsOwnResultAndNothingElse) {
  // `saltus import` writes a saltus-result/1 with status "imported" and five files: running it
  // again to the same --out replaces that folder; an evaluate result there is not replaced by
  // an import's files plus leftovers, and a user's file stops it.
  TempDir dir;
  const std::string bvh = dir / "m1.bvh";
  ASSERT_EQ(run_cli("export " + test::m1_path() + " --format bvh --out " + bvh + " -q").status, 0);
  const std::string out = dir / "imported";
  const auto first = run_cli("import " + bvh + " --out " + out + " -q");
  ASSERT_EQ(first.status, 0) << first.output;
  const std::set<std::string> files = names_in(out);
  EXPECT_EQ(read_json(out + "/result.json")["status"], "imported");
  const auto again = run_cli("import " + bvh + " --out " + out + " -q");
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_EQ(names_in(out), files);
  // Any verb may replace an import's folder, and an import may replace an earlier evaluate.
  ASSERT_EQ(run_cli(evaluate(out, 11)).status, 0);
  EXPECT_EQ(names_in(out), kEvaluateFiles);
  EXPECT_EQ(run_cli("import " + bvh + " --out " + out + " -q").status, 0);
  EXPECT_EQ(names_in(out), files);
  test::write_text(out + "/notes.txt", "mine");
  const auto refused = run_cli("import " + bvh + " --out " + out + " -q");
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("notes.txt"), std::string::npos) << refused.output;
  EXPECT_EQ(test::read_text(out + "/notes.txt"), "mine");
  EXPECT_EQ(hidden_in(dir.path()), std::set<std::string>{});
}

/// Killed by SIGKILL (the shell may report it as 128 + 9).
bool killed(const test::CliRun& run) {
  return run.status == -1 || run.status == 128 + SIGKILL;
}

/// Runs `saltus ARGS` with the rename fault injector preloaded (tests/support/rename_fault.c).
test::CliRun run_with_faults(const std::string& faults, const std::string& arguments) {
  return run_command(faults + " LD_PRELOAD=" + SALTUS_RENAME_FAULT_PATH + " " + SALTUS_CLI_PATH +
                     " " + arguments);
}

TEST(OutputFolder, AKillRightAfterTheSwapLeavesTheNewFolderAndTheNextRunCleansUp) {
  // Issue 16 item 2: the old commit renamed DIR away, then the new folder in; a kill between
  // left neither. Now one renameat2(RENAME_EXCHANGE) swaps them.
  TempDir dir;
  const std::string out = dir / "out";
  ASSERT_EQ(run_cli(evaluate(out, 50)).status, 0);
  const auto run_killed = run_with_faults("SALTUS_FAULT_KILL_AFTER_RENAME=1", evaluate(out, 60));
  EXPECT_TRUE(killed(run_killed)) << run_killed.status << ": " << run_killed.output;
  EXPECT_EQ(read_json(out + "/result.json")["samples"], 60);
  EXPECT_EQ(names_in(out), kEvaluateFiles);
  EXPECT_FALSE(hidden_in(dir.path()).empty()) << "the old folder, not yet removed";
  ASSERT_EQ(run_cli(evaluate(out, 70)).status, 0);
  EXPECT_EQ(names_in(dir.path()), std::set<std::string>{"out"});
}

TEST(OutputFolder, WithoutExchangeAKillBetweenTheTwoRenamesIsRepairedByTheNextRun) {
  // Where the file system cannot exchange, the fallback renames twice; a kill between leaves
  // the old folder at .out.old-*, which the next run puts back before it writes.
  TempDir dir;
  const std::string out = dir / "out";
  ASSERT_EQ(run_cli(evaluate(out, 50)).status, 0);
  const auto fallback = run_with_faults("SALTUS_FAULT_NO_EXCHANGE=1", evaluate(out, 55));
  ASSERT_EQ(fallback.status, 0) << fallback.output;
  EXPECT_EQ(read_json(out + "/result.json")["samples"], 55);
  EXPECT_EQ(names_in(dir.path()), std::set<std::string>{"out"});

  const auto run_killed = run_with_faults(
      "SALTUS_FAULT_NO_EXCHANGE=1 SALTUS_FAULT_KILL_AFTER_RENAME=1", evaluate(out, 60));
  EXPECT_TRUE(killed(run_killed)) << run_killed.status << ": " << run_killed.output;
  EXPECT_FALSE(fs::exists(out));
  bool old_kept = false;
  for (const std::string& name : hidden_in(dir.path()))
    if (name.rfind(".out.old-", 0) == 0)
      old_kept = read_json((dir.path() / name / "result.json").string())["samples"] == 55;
  EXPECT_TRUE(old_kept);
  // The next run takes the lock, puts the old folder back, then replaces it as usual.
  ASSERT_EQ(run_cli(evaluate(out, 70)).status, 0);
  EXPECT_EQ(read_json(out + "/result.json")["samples"], 70);
  EXPECT_EQ(names_in(dir.path()), std::set<std::string>{"out"});
}

TEST(OutputFolder, InterruptsRemoveTheTemporaryFolder) {
  // Issue 16 item 3: Ctrl+C during `saltus paper` left a hidden .REPORT.tmp-… of 2.4 MB. A
  // study stops by the signal itself and keeps only its visible, documented REPORT.partial (the
  // finished cases, for --resume); nothing hidden stays behind.
  for (const int signal_number : {SIGINT, SIGTERM}) {
    TempDir dir;
    const pid_t pid = spawn(paper_command(dir / "report"));
    ASSERT_TRUE(wait_for_entry(dir.path(), ".report.tmp-", 120)) << "no temporary folder";
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ASSERT_EQ(kill(pid, signal_number), 0);
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << status;
    EXPECT_EQ(names_in(dir.path()), std::set<std::string>{"report.partial"})
        << strsignal(signal_number);
  }
}

TEST(OutputFolder, TheNextRunRemovesWhatAKilledRunLeft) {
  TempDir dir;
  const pid_t pid = spawn(paper_command(dir / "report"));
  ASSERT_TRUE(wait_for_entry(dir.path(), ".report.tmp-", 120));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_FALSE(hidden_in(dir.path()).empty()) << "SIGKILL cannot be handled";
  ASSERT_EQ(run_cli(evaluate(dir / "report", 11)).status, 0);
  // The study's REPORT.partial is its progress for --resume, not litter: it stays.
  EXPECT_EQ(names_in(dir.path()), (std::set<std::string>{"report", "report.partial"}));
}

/// Runs `script` (sh) in a private mount namespace, so its mounts vanish with it: as root
/// directly, otherwise as root of a new user namespace.
test::CliRun run_in_mount_namespace(const std::string& script) {
  const std::string quoted = "'" + script + "'";
  if (geteuid() == 0) return run_command("unshare -m sh -c " + quoted);
  return run_command("unshare -Urm sh -c " + quoted);
}

TEST(OutputFolder, AFullDiskFailsWithTheReasonAndChangesNothing) {
  // Issue 16 item 6: a full disk gave exit 1 "writing the trajectory failed", naming the
  // deleted temporary and not the reason.
  TempDir dir;
  const std::string disk = dir / "disk";
  fs::create_directories(disk);
  const std::string cli = SALTUS_CLI_PATH;
  // 64 KiB: an 11-sample result (12 kB) fits, a 1001-sample one (2 MB) does not.
  const auto run = run_in_mount_namespace(
      "mount -t tmpfs -o size=64k tmpfs " + disk + " || exit 99; " + cli + " " +
      evaluate(disk + "/out", 11) + " || exit 98; cp " + disk + "/out/result.json " +
      (dir / "small.json") + "; " + cli + " " + evaluate(disk + "/out", 1001) +
      "; echo \"status=$?\"; cmp " + disk + "/out/result.json " + (dir / "small.json") +
      " && echo unchanged; ls -A " + disk + " | tr \"\\n\" \" \"; echo; ls -A " + disk + "/out");
  ASSERT_NE(run.status, 99) << "cannot mount a tmpfs (needs root or user namespaces): "
                            << run.output;
  ASSERT_NE(run.status, 98) << run.output;
  EXPECT_NE(run.output.find("status=4"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("No space left on device"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find(disk + "/out/"), std::string::npos) << "names DIR/file" << run.output;
  EXPECT_EQ(run.output.find(".tmp-"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("unchanged"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("\nout \n"), std::string::npos) << "no litter: " << run.output;
}

TEST(OutputFolder, ConcurrentRunsToOneFolderOneWinsTheOtherSaysSo) {
  // Issue 16 item 6: two runs to one --out raced on a rename and one exited 2, "bad input".
  TempDir dir;
  const std::string out = dir / "out";
  {
    // A run writing `out` right now holds its lock.
    const int fd = open((dir / ".out.lock").c_str(), O_RDWR | O_CREAT, 0644);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(flock(fd, LOCK_EX), 0);
    const std::string pid = std::to_string(getpid());
    ASSERT_EQ(write(fd, pid.data(), pid.size()), static_cast<ssize_t>(pid.size()));
    const auto busy = run_cli(evaluate(out, 11));
    EXPECT_EQ(busy.status, 4) << busy.output;
    EXPECT_NE(busy.output.find("another saltus run (pid " + pid + ") is writing " + out),
              std::string::npos)
        << busy.output;
    EXPECT_FALSE(fs::exists(out));
    close(fd);
    fs::remove(dir / ".out.lock");
  }
  // Many at once: each one either writes its complete result or says another run is writing.
  std::vector<std::thread> threads;
  std::vector<test::CliRun> runs(6);
  for (std::size_t i = 0; i < runs.size(); ++i)
    threads.emplace_back([&, i] { runs[i] = run_cli(evaluate(out, 20 + static_cast<int>(i))); });
  for (auto& t : threads)
    t.join();
  std::set<int> winners;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    EXPECT_TRUE(runs[i].status == 0 || runs[i].status == 4) << runs[i].output;
    if (runs[i].status == 0) winners.insert(20 + static_cast<int>(i));
    if (runs[i].status == 4) {
      EXPECT_NE(runs[i].output.find("another saltus run"), std::string::npos) << runs[i].output;
    }
  }
  EXPECT_FALSE(winners.empty());
  EXPECT_EQ(names_in(out), kEvaluateFiles);
  EXPECT_EQ(winners.count(read_json(out + "/result.json")["samples"].get<int>()), 1u);
  EXPECT_EQ(names_in(dir.path()), std::set<std::string>{"out"});
}

}  // namespace
}  // namespace saltus
