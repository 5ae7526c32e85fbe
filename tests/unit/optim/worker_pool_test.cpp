// The optimiser's thread pool (optim/worker_pool.h): every part of every task runs once, on
// distinct threads, and a part's exception reaches the caller after all parts have finished.

#include "saltus/optim/worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace saltus {
namespace {

TEST(WorkerPool, RunsEveryPartOfEveryTaskOnceOnItsOwnThread) {
  for (int parts : {1, 2, 3}) {
    WorkerPool pool(parts);
    ASSERT_EQ(pool.parts(), parts);
    for (int task = 0; task < 200; ++task) {  // many short tasks: no lost or repeated wake-up
      std::vector<int> runs(parts, 0);
      std::vector<std::thread::id> ids(parts);
      pool.run([&](int part) {
        ++runs[part];
        ids[part] = std::this_thread::get_id();
      });
      for (int p = 0; p < parts; ++p)
        ASSERT_EQ(runs[p], 1) << "part " << p << " of task " << task;
      EXPECT_EQ(ids[0], std::this_thread::get_id());  // part 0 is the caller's
      EXPECT_EQ(std::set<std::thread::id>(ids.begin(), ids.end()).size(),
                static_cast<std::size_t>(parts));
    }
  }
}

TEST(WorkerPool, RethrowsAPartsExceptionAfterEveryPartFinished) {
  WorkerPool pool(3);
  std::atomic<int> finished{0};
  EXPECT_THROW(pool.run([&](int part) {
    if (part == 2) throw std::runtime_error("part 2 failed");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ++finished;
  }),
               std::runtime_error);
  EXPECT_EQ(finished.load(), 2);
  // The pool is still usable afterwards.
  std::atomic<int> runs{0};
  pool.run([&](int) { ++runs; });
  EXPECT_EQ(runs.load(), 3);
}

}  // namespace
}  // namespace saltus
