#include "saltus/studies/isolated_runner.h"

#include <sched.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "saltus/base/text_format.h"

namespace saltus {

namespace {

using Clock = std::chrono::steady_clock;

volatile std::sig_atomic_t g_interrupt = 0;

extern "C" void remember_interrupt(int signal) {
  g_interrupt = signal;
}

constexpr int kHandledSignals[] = {SIGINT, SIGTERM, SIGHUP};

/// Installs remember_interrupt for the run and puts the previous handlers back afterwards.
class InterruptHandlers {
 public:
  InterruptHandlers() {
    g_interrupt = 0;
    struct sigaction action {};
    action.sa_handler = remember_interrupt;
    sigemptyset(&action.sa_mask);
    for (int i = 0; i < 3; ++i)
      sigaction(kHandledSignals[i], &action, &previous_[i]);
  }
  ~InterruptHandlers() {
    for (int i = 0; i < 3; ++i)
      sigaction(kHandledSignals[i], &previous_[i], nullptr);
  }
  InterruptHandlers(const InterruptHandlers&) = delete;
  InterruptHandlers& operator=(const InterruptHandlers&) = delete;

 private:
  struct sigaction previous_[3];
};

struct Child {
  pid_t pid = 0;
  int task = 0;
  Clock::time_point start;
  bool killed_for_time = false;
};

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

[[noreturn]] void run_child(int task, pid_t parent, const std::function<int(int)>& work) {
  for (int signal : kHandledSignals)
    std::signal(signal, SIG_DFL);
  // Die with the parent: a killed study leaves no case running on.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(1);
  int code = 1;
  try {
    code = work(task);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "saltus: case %d: %s\n", task, e.what());
  } catch (...) {
    std::fprintf(stderr, "saltus: case %d: unknown error\n", task);
  }
  std::fflush(nullptr);
  _exit(code);  // no atexit handlers or static destructors: they belong to the parent
}

/// Terminates and reaps every child still running: SIGTERM, then SIGKILL after a grace period.
void stop_children(std::vector<Child>& children) {
  for (const Child& c : children)
    kill(c.pid, SIGTERM);
  const Clock::time_point start = Clock::now();
  while (!children.empty()) {
    for (auto it = children.begin(); it != children.end();) {
      int status = 0;
      if (waitpid(it->pid, &status, WNOHANG) == it->pid)
        it = children.erase(it);
      else
        ++it;
    }
    if (children.empty()) break;
    if (seconds_since(start) > 2.0)
      for (const Child& c : children)
        kill(c.pid, SIGKILL);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace

std::string WorkerExit::describe() const {
  switch (kind) {
    case Kind::kExited:
      return "exit status " + std::to_string(code);
    case Kind::kSignalled:
      return "killed by signal " + std::to_string(code) + " (" + strsignal(code) + ")";
    case Kind::kTimedOut:
      return format_number("timed out after %g s", seconds);
  }
  return "";
}

IsolatedRunSummary run_isolated(const std::vector<int>& tasks, const IsolatedRunOptions& options,
                                const std::function<int(int)>& work,
                                const std::function<void(int, const WorkerExit&)>& finished) {
  if (options.jobs < 1) throw std::invalid_argument("jobs must be at least 1");
  if (!(options.time_limit_s >= 0)) throw std::invalid_argument("time limit must be >= 0");
  IsolatedRunSummary summary;
  InterruptHandlers handlers;
  const pid_t parent = getpid();
  std::vector<Child> children;
  std::size_t next = 0;
  try {
    while (!g_interrupt) {
      while (static_cast<int>(children.size()) < options.jobs && next < tasks.size()) {
        std::fflush(nullptr);  // else the child would write the parent's buffered output again
        const pid_t pid = fork();
        if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
        if (pid == 0) run_child(tasks[next], parent, work);
        children.push_back({pid, tasks[next], Clock::now(), false});
        ++next;
      }
      if (children.empty()) break;
      bool reaped = false;
      for (auto it = children.begin(); it != children.end();) {
        int status = 0;
        if (waitpid(it->pid, &status, WNOHANG) != it->pid) {
          if (options.time_limit_s > 0 && !it->killed_for_time &&
              seconds_since(it->start) > options.time_limit_s) {
            kill(it->pid, SIGKILL);
            it->killed_for_time = true;
          }
          ++it;
          continue;
        }
        WorkerExit exit;
        exit.seconds = seconds_since(it->start);
        if (it->killed_for_time) {
          exit.kind = WorkerExit::Kind::kTimedOut;
          exit.seconds = options.time_limit_s;
        } else if (WIFSIGNALED(status)) {
          exit.kind = WorkerExit::Kind::kSignalled;
          exit.code = WTERMSIG(status);
        } else {
          exit.code = WEXITSTATUS(status);
        }
        const int task = it->task;
        it = children.erase(it);
        reaped = true;
        // A child ended by the user's Ctrl+C or a scheduler's SIGTERM (the whole process group
        // gets it) is not a result; the parent's own signal may arrive a moment later.
        if (exit.kind == WorkerExit::Kind::kSignalled && !g_interrupt &&
            (exit.code == SIGINT || exit.code == SIGTERM || exit.code == SIGHUP))
          std::this_thread::sleep_for(std::chrono::milliseconds(200));
        if (g_interrupt) break;
        ++summary.finished;
        finished(task, exit);
      }
      if (!reaped) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  } catch (...) {
    stop_children(children);
    throw;
  }
  stop_children(children);
  summary.interrupt_signal = g_interrupt;
  return summary;
}

int available_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) {
    const int count = CPU_COUNT(&set);
    if (count > 0) return count;
  }
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware > 0 ? static_cast<int>(hardware) : 1;
}

}  // namespace saltus
