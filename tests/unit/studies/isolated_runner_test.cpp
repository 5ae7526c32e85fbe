// run_isolated: every task in a process of its own, at most `jobs` at once; a crash, an
// exception or a hang is that task's failure and the others go on; a signal to the parent stops
// the run and leaves no child behind.

#include "saltus/studies/isolated_runner.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <thread>

#include "support/cli_runner.h"

namespace saltus {
namespace {

std::map<int, WorkerExit> run(const std::vector<int>& tasks, const IsolatedRunOptions& options,
                              const std::function<int(int)>& work,
                              IsolatedRunSummary* summary = nullptr) {
  std::map<int, WorkerExit> exits;
  const IsolatedRunSummary s =
      run_isolated(tasks, options, work, [&](int task, const WorkerExit& e) {
        EXPECT_EQ(exits.count(task), 0u) << "task " << task << " reported twice";
        exits[task] = e;
      });
  if (summary) *summary = s;
  return exits;
}

TEST(IsolatedRunner, ACrashAnExceptionAndAnExitStatusAreTheirTasksAlone) {
  IsolatedRunOptions options;
  options.jobs = 2;
  const auto exits = run({0, 1, 2, 3, 4}, options, [](int task) {
    if (task == 1) {
      // Die by the signal as a real crash does: AddressSanitizer's own SIGSEGV handler would
      // report it and exit with a status instead.
      signal(SIGSEGV, SIG_DFL);
      raise(SIGSEGV);
    }
    if (task == 2) throw std::runtime_error("case failed");
    if (task == 3) return 7;
    return 0;
  });
  ASSERT_EQ(exits.size(), 5u);
  EXPECT_TRUE(exits.at(0).succeeded());
  EXPECT_TRUE(exits.at(4).succeeded());
  EXPECT_EQ(exits.at(1).kind, WorkerExit::Kind::kSignalled);
  EXPECT_EQ(exits.at(1).code, SIGSEGV);
  EXPECT_NE(exits.at(1).describe().find("killed by signal 11"), std::string::npos);
  EXPECT_EQ(exits.at(2).kind, WorkerExit::Kind::kExited);
  EXPECT_EQ(exits.at(2).code, 1);
  EXPECT_EQ(exits.at(3).code, 7);
  EXPECT_EQ(exits.at(3).describe(), "exit status 7");
}

TEST(IsolatedRunner, AHangIsKilledAtTheTimeLimit) {
  IsolatedRunOptions options;
  options.jobs = 2;
  options.time_limit_s = 0.3;
  const auto start = std::chrono::steady_clock::now();
  const auto exits = run({0, 1}, options, [](int task) {
    if (task == 0)
      for (;;)
        pause();  // never returns
    return 0;
  });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(exits.size(), 2u);
  EXPECT_EQ(exits.at(0).kind, WorkerExit::Kind::kTimedOut);
  EXPECT_EQ(exits.at(0).describe(), "timed out after 0.3 s");
  EXPECT_TRUE(exits.at(1).succeeded());
  EXPECT_LT(seconds, 10.0);
}

TEST(IsolatedRunner, NeverMoreThanJobsChildrenAtOnce) {
  // Each child claims the lowest free slot file (O_EXCL) while it runs and exits with the slot
  // number: with jobs = 3 no child may find slots 0-2 all taken.
  test::TempDir dir;
  const std::string slots = dir.path().string();
  for (int jobs : {1, 3}) {
    IsolatedRunOptions options;
    options.jobs = jobs;
    std::vector<int> tasks(12);
    for (int i = 0; i < 12; ++i)
      tasks[i] = i;
    const auto exits = run(tasks, options, [&](int) {
      for (int slot = 0;; ++slot) {
        const std::string path = slots + "/slot" + std::to_string(slot);
        const int fd = open(path.c_str(), O_CREAT | O_EXCL | O_WRONLY, 0644);
        if (fd < 0) continue;
        close(fd);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        unlink(path.c_str());
        return slot;
      }
    });
    ASSERT_EQ(exits.size(), 12u);
    int highest = 0;
    for (const auto& [task, exit] : exits) {
      ASSERT_EQ(exit.kind, WorkerExit::Kind::kExited);
      highest = std::max(highest, exit.code);
    }
    EXPECT_LT(highest, jobs);
    if (jobs == 3) {
      EXPECT_EQ(highest, 2) << "three children never ran at once";
    }
  }
}

TEST(IsolatedRunner, ASignalToTheParentStopsTheRunAndItsChildren) {
  test::TempDir dir;
  const std::string marker = dir / "started";
  IsolatedRunOptions options;
  options.jobs = 2;
  IsolatedRunSummary summary;
  const auto exits = run(
      {0, 1, 2, 3, 4, 5}, options,
      [&](int task) {
        if (task == 1) {
          // What Ctrl+C or scancel does to the study: the parent gets a signal.
          kill(getppid(), SIGTERM);
          for (;;)
            pause();
        }
        if (task == 0) {
          test::write_text(marker + std::to_string(getpid()), "");
          for (;;)
            pause();
        }
        return 0;
      },
      &summary);
  EXPECT_TRUE(summary.interrupted());
  EXPECT_EQ(summary.interrupt_signal, SIGTERM);
  // Neither running task counts as finished, and no later one started.
  EXPECT_EQ(exits.size(), 0u);
  // Task 0's child is gone (reaped): no process with its pid is left.
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    const std::string name = entry.path().filename().string();
    const pid_t pid = std::stoi(name.substr(std::string("started").size()));
    EXPECT_NE(kill(pid, 0), 0) << "child " << pid << " still running";
  }
  // The parent's own handlers are back: the test process is still here to say so.
  struct sigaction now {};
  sigaction(SIGTERM, nullptr, &now);
  EXPECT_EQ(now.sa_handler, SIG_DFL);
}

TEST(IsolatedRunner, AvailableCpusIsAtLeastOne) {
  EXPECT_GE(available_cpus(), 1);
}

}  // namespace
}  // namespace saltus
