#pragma once
// Shared by the `cluster` tests: a small convergence study (12 cases, seconds) and a private
// single-machine Slurm (tools/cluster/local_slurm.sh) that is stopped when the test ends, and by
// the script's watcher if the test is killed.

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.h"

namespace saltus::test {

inline std::string cluster_study(const std::string& out) {
  return "study convergence " + m1_path() + " --out " + out +
         " --epsilons 1,100 --mass-errors -10,0 --timing-errors 0,0.05 --samples 41 "
         "--max-iter 60 --case-time-limit 120 --quiet";
}

/// Every step of a cluster test is bounded (each case takes about a second; a whole step well
/// under a minute on two busy cores): a hung scheduler or daemon fails the test instead of CI.
inline constexpr int kStepTimeLimitSeconds = 300;

/// `command_line` killed after kStepTimeLimitSeconds (exit status 124 then).
inline std::string bounded(const std::string& command_line) {
  return "timeout --kill-after=10 " + std::to_string(kStepTimeLimitSeconds) + " " + command_line;
}

inline bool have_command(const std::string& name) {
  return run_command("command -v " + name).status == 0;
}

/// Processes (other than this one) whose command line names `dir` or whose working folder lies
/// in it, as "pid: command line": what a test run in `dir` would leave running.
inline std::vector<std::string> processes_in(const std::string& dir) {
  namespace fs = std::filesystem;
  std::vector<std::string> found;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator("/proc", error)) {
    const std::string pid = entry.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos || pid == std::to_string(getpid()))
      continue;
    std::ifstream in(entry.path() / "cmdline");
    std::string command((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (char& c : command)
      if (c == '\0') c = ' ';
    const std::string cwd = fs::read_symlink(entry.path() / "cwd", error).string();
    if (command.find(dir) != std::string::npos || (!error && cwd.rfind(dir, 0) == 0))
      found.push_back(pid + ": " + command);
  }
  return found;
}

class LocalSlurm {
 public:
  LocalSlurm(const std::string& dir, int nodes) : dir_(dir) {
    const CliRun start = run_command(
        bounded("bash ") + std::string(SALTUS_TOOLS_DIR) + "/cluster/local_slurm.sh start " + dir +
        " --nodes " + std::to_string(nodes) + " --watch " + std::to_string(getpid()));
    output_ = start.output;
    if (start.status != 0) return;
    std::ifstream pids(dir + "/pids");
    std::string name;
    pid_t pid;
    while (pids >> name >> pid)
      pids_.push_back(pid);
    started_ = true;
  }
  ~LocalSlurm() { stop(); }
  LocalSlurm(const LocalSlurm&) = delete;
  LocalSlurm& operator=(const LocalSlurm&) = delete;

  bool started() const { return started_; }
  const std::string& output() const { return output_; }
  /// Prefix for commands that talk to this cluster.
  std::string env() const { return "SLURM_CONF=" + dir_ + "/slurm.conf "; }
  /// Stops the cluster; true when none of its processes is left.
  bool stop() {
    if (!started_) return true;
    started_ = false;
    run_command(bounded("bash ") + std::string(SALTUS_TOOLS_DIR) + "/cluster/local_slurm.sh stop " +
                dir_);
    for (pid_t pid : pids_)
      if (kill(pid, 0) == 0) return false;
    return true;
  }

 private:
  std::string dir_;
  std::string output_;
  std::vector<pid_t> pids_;
  bool started_ = false;
};

}  // namespace saltus::test
