// The Ipopt adapter (optim/ipopt_solver.h) alone, without the solve policy: it solves a problem
// with a published optimum, shows the observer every iteration with the iterate Ipopt holds,
// stops when the observer says so, starts where it is told and honours the iteration limit; and
// several solves run at once in one process (threads; MUMPS's calls take turns).

#include "saltus/optim/ipopt_solver.h"

#include <gtest/gtest.h>

#include <thread>

#include "saltus/optim/optimize.h"
#include "support/small_nlps.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(IpoptSolver, SolvesHockSchittkowski71AndShowsEveryIteration) {
  test::Hs71 nlp;
  IpoptSettings settings;
  std::vector<IpoptIteration> seen;
  std::vector<std::vector<double>> points;
  const IpoptRun run = run_ipopt(nlp, settings, nullptr, [&](const IpoptIteration& it) {
    seen.push_back(it);
    std::vector<double> x;
    EXPECT_TRUE(it.current_point(x));
    points.push_back(x);
    return true;
  });
  EXPECT_EQ(run.status, "solved");
  EXPECT_EQ(run.ipopt_status, "optimal");
  ASSERT_EQ(run.x.size(), 4u);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(run.x[i], test::Hs71::kOptimum[i], 1e-6);
  EXPECT_NEAR(run.objective, test::Hs71::kObjective, 1e-6);
  // Iterations 0 (the start) to the last, each once, each with the point the NLP evaluated.
  ASSERT_EQ(static_cast<int>(seen.size()), run.iterations + 1);
  for (std::size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].iteration, static_cast<int>(i));
    EXPECT_NEAR(nlp.f(points[i].data()), seen[i].objective, 1e-9 * std::abs(seen[i].objective));
  }
}

TEST(IpoptSolver, TheObserverStopsTheRunAndTheLimitIsKept) {
  test::Hs71 nlp;
  IpoptSettings settings;
  const IpoptRun stopped =
      run_ipopt(nlp, settings, nullptr, [](const IpoptIteration& it) { return it.iteration < 3; });
  EXPECT_EQ(stopped.status, "stopped");
  EXPECT_EQ(stopped.iterations, 3);
  settings.max_iterations = 2;
  test::Hs71 again;
  const IpoptRun limited = run_ipopt(again, settings, nullptr, {});
  EXPECT_EQ(limited.status, "max_iterations");
  EXPECT_EQ(limited.iterations, 2);
}

TEST(IpoptSolver, StartsWhereItIsTold) {
  test::Hs71 nlp;
  const std::vector<double> start = {1.5, 4.0, 3.5, 1.5};  // inside the bounds
  std::vector<double> first;
  run_ipopt(nlp, IpoptSettings{}, &start, [&](const IpoptIteration& it) {
    if (it.iteration == 0) it.current_point(first);
    return true;
  });
  ASSERT_EQ(first.size(), 4u);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(first[i], start[i], 1e-6);
}

TEST(IpoptSolver, SolvesAtOnceInSeveralThreadsAsAlone) {
  // Without the lock around MUMPS's calls two of these crashed in MUMPS's load balancing.
  const BodyModel model = test::bundled_model();
  const Motion motion = test::tuck_motion(model);
  OptimizeOptions options;
  options.automatic_resolution = false;
  options.nlp.joint_load_weight = 0.0;
  options.solver.max_iterations = 8;
  const OptimizationResult alone = optimize_motion(motion, model, options);
  std::vector<OptimizationResult> together(4);
  std::vector<std::thread> threads;
  for (OptimizationResult& r : together)
    threads.emplace_back([&] { r = optimize_motion(motion, model, options); });
  for (std::thread& t : threads)
    t.join();
  for (const OptimizationResult& r : together) {
    EXPECT_EQ(r.solve.iterations, alone.solve.iterations);
    EXPECT_EQ(r.solve.x, alone.solve.x);
  }
}

}  // namespace
}  // namespace saltus
