#pragma once
/// @file
/// A fixed set of threads that run the parts of one task together, for the optimiser's
/// per-iteration evaluations (root wrench over the grid, keyframe derivatives, Hessian blocks).
/// The threads are started once and wait between tasks: an evaluation takes a few milliseconds
/// and is called several times per iteration, so starting threads for each would add up.

#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace saltus {

class WorkerPool {
 public:
  /// `parts` = how many parts every task is cut into: part 0 runs on the calling thread, the
  /// others on parts − 1 pool threads.
  explicit WorkerPool(int parts);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int parts() const { return parts_; }

  /// Runs task(p) for every part p in [0, parts()) and returns when all are done. Not
  /// re-entrant: one task at a time. An exception thrown by a part is rethrown here (the first
  /// one, after every part has finished).
  void run(const std::function<void(int part)>& task);

 private:
  void work(int part);

  int parts_;
  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  const std::function<void(int)>* task_ = nullptr;
  long generation_ = 0;  ///< bumped per task: a worker runs each generation once
  int pending_ = 0;      ///< parts of the current task still running on pool threads
  bool stopping_ = false;
  std::exception_ptr error_;
};

}  // namespace saltus
