#pragma once
/// @file
/// Runs a study's cases each in a child process of its own (POSIX fork), several at a time, so
/// that one case's crash or hang is that case's failure and the study goes on. A child inherits
/// the loaded motions and options; it runs one case, writes its own result and exits. The parent
/// only schedules: it must be single-threaded when it calls run_isolated (the CLI is).

#include <functional>
#include <string>
#include <vector>

namespace saltus {

/// How one child process ended.
struct WorkerExit {
  enum class Kind { kExited, kSignalled, kTimedOut };
  Kind kind = Kind::kExited;
  int code = 0;          ///< exit status (kExited) or the signal that ended it (kSignalled)
  double seconds = 0.0;  ///< wall time from start to end
  bool succeeded() const { return kind == Kind::kExited && code == 0; }
  /// "exit status 1", "killed by signal 11 (Segmentation fault)", "timed out after 600 s".
  std::string describe() const;
};

struct IsolatedRunOptions {
  int jobs = 1;               ///< children running at once (>= 1)
  double time_limit_s = 0.0;  ///< a child running longer is killed (SIGKILL); 0: no limit
};

/// What run_isolated did.
struct IsolatedRunSummary {
  int finished = 0;          ///< tasks whose child ended (each reported to `finished`)
  int interrupt_signal = 0;  ///< SIGINT, SIGTERM or SIGHUP that stopped the run early; 0: none
  bool interrupted() const { return interrupt_signal != 0; }
};

/// Runs work(task) in a forked child for every task, in the given order, at most options.jobs at
/// a time; the child exits with work's return value (1 if it throws; its message on stderr).
/// finished(task, exit) runs in the parent as each child ends, in the order they end.
/// SIGINT, SIGTERM or SIGHUP during the run stop it: running children are terminated (their
/// tasks are not reported), no new ones start, and the signal is returned in the summary.
/// A child dies with its parent (PR_SET_PDEATHSIG), so killing the parent leaves no orphan.
IsolatedRunSummary run_isolated(const std::vector<int>& tasks, const IsolatedRunOptions& options,
                                const std::function<int(int task)>& work,
                                const std::function<void(int task, const WorkerExit&)>& finished);

/// CPUs this process may run on (its affinity mask; under Slurm, its allocation), at least 1.
int available_cpus();

}  // namespace saltus
