#pragma once
// Shared by the `cluster` tests: a small convergence study (12 cases, seconds) and a private
// single-machine Slurm (tools/cluster/local_slurm.sh) that is stopped when the test ends, and by
// the script's watcher if the test is killed.

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.h"

namespace saltus::test {

inline std::string cluster_study(const std::string& out) {
  return "study convergence " + m1_path() + " --out " + out +
         " --epsilons 1,100 --mass-errors -10,0 --timing-errors 0,0.05 --samples 41 "
         "--max-iter 60 --quiet";
}

inline bool have_command(const std::string& name) {
  return run_command("command -v " + name).status == 0;
}

class LocalSlurm {
 public:
  LocalSlurm(const std::string& dir, int nodes) : dir_(dir) {
    const CliRun start = run_command(
        "bash " + std::string(SALTUS_TOOLS_DIR) + "/cluster/local_slurm.sh start " + dir +
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
    run_command("bash " + std::string(SALTUS_TOOLS_DIR) + "/cluster/local_slurm.sh stop " + dir_);
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
