// The solve policy (optim/solve_policy.h) and Ipopt under it on small NLPs written out by hand:
// problems with known answers (Hock–Schittkowski 71, a bounded QP whose active set is worked out
// below) and problems built so that each of the policies has to act: the "acceptable" exit on
// objective change, the restart from the best feasible iterate after a stall, returning the best
// feasible rather than the last iterate, the iteration budget shared by restarts, cancellation,
// progress reports, the quasi-Newton fallback, the derivative checker's report and the ignored
// ipopt.opt. Expectations come from the problems' closed forms or from the path the NLP itself
// observed, never from counts copied out of an earlier run.

#include "saltus/optim/solve_policy.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "support/small_nlps.h"
#include "support/temp_path.h"

namespace saltus {
namespace {

using test::BoundedQp;
using test::DenseNlp;
using test::FlatMinimum;
using test::Hs71;
using test::Infeasible;
using test::Iterate;
using test::Overshoot;
using test::radius;
using test::Rosenbrock;

// ---------------------------------------------------------------------------------------------
// Running a solve and reading its path.

struct Solve {
  SolveReport report;
  std::vector<ProgressInfo> progress;
};

/// Solves `nlp`, collecting every progress report; `on_progress` may act on each (cancel).
Solve solve(DenseNlp& nlp, const SolverOptions& options,
            const std::function<void(const ProgressInfo&)>& on_progress = {},
            const std::atomic<bool>* cancel = nullptr) {
  Solve s;
  s.report = solve_nlp(
      nlp, options,
      [&](const ProgressInfo& p) {
        s.progress.push_back(p);
        if (on_progress) on_progress(p);
      },
      cancel);
  // The NLP saw the same iterates the progress reports describe, one step_taken() each.
  EXPECT_EQ(s.progress.size(), nlp.iterates.size());
  for (std::size_t i = 0; i < std::min(s.progress.size(), nlp.iterates.size()); ++i)
    EXPECT_EQ(s.progress[i].objective, nlp.iterates[i].objective) << "iterate " << i;
  // The report's objective is the NLP's at the reported x, up to Ipopt's last step: it solves
  // with every bound relaxed by 1e-8 (bound_relax_factor) and puts x back inside the original
  // bounds after it evaluated the objective, a change of ~|∇f|·1e-8.
  EXPECT_EQ(static_cast<int>(s.report.x.size()), nlp.variable_count());
  if (!s.report.x.empty()) {
    EXPECT_NEAR(nlp.f(s.report.x.data()), s.report.objective, 1e-7 * std::abs(s.report.objective));
  }
  return s;
}

/// Index of the lowest-objective iterate whose violation (Ipopt's, as reported in progress) is
/// within `tolerance`; −1 if none.
int best_feasible(const Solve& s, double tolerance) {
  int best = -1;
  for (std::size_t i = 0; i < s.progress.size(); ++i)
    if (s.progress[i].constraint_violation <= tolerance &&
        (best < 0 || s.progress[i].objective < s.progress[best].objective))
      best = static_cast<int>(i);
  return best;
}

// ---------------------------------------------------------------------------------------------
// Known answers.

TEST(SolvePolicy, SolvesHockSchittkowski71ToItsPublishedOptimum) {
  Hs71 nlp;
  SolverOptions options;
  options.objective_change_tolerance = 0;  // Ipopt's own optimality test decides
  const Solve s = solve(nlp, options);
  EXPECT_EQ(s.report.status, "solved");
  EXPECT_EQ(s.report.ipopt_status, "optimal");
  EXPECT_TRUE(s.report.solved);
  EXPECT_EQ(s.report.restarts, 0);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(s.report.x[i], Hs71::kOptimum[i], 1e-6) << i;
  EXPECT_NEAR(s.report.objective, Hs71::kObjective, 1e-6);
  EXPECT_LT(nlp.violation(s.report.x.data()), 1e-6);
  EXPECT_EQ(s.report.iterations, nlp.iterates.back().iteration);
  EXPECT_GT(s.report.seconds, 0.0);
}

TEST(SolvePolicy, SolvesABoundedQpOnItsKnownActiveSet) {
  BoundedQp nlp;
  SolverOptions options;
  options.objective_change_tolerance = 0;
  const Solve s = solve(nlp, options);
  ASSERT_TRUE(s.report.solved) << s.report.status;
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(s.report.x[i], BoundedQp::kOptimum[i], 1e-6) << i;
  EXPECT_NEAR(s.report.objective, BoundedQp::kObjective, 1e-6);
  // The active set: both bounds and the sum constraint hold within the interior point's distance.
  EXPECT_NEAR(s.report.x[0] + s.report.x[1] + s.report.x[2] + s.report.x[3], 2.5, 1e-6);
  for (double v : s.report.x) {
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1.0);
  }
}

/// Hock–Schittkowski 71 from a given point.
class Hs71From : public Hs71 {
 public:
  explicit Hs71From(std::vector<double> start) : start_(std::move(start)) {}
  void initial_point(double* x) const override { std::copy(start_.begin(), start_.end(), x); }

 private:
  std::vector<double> start_;
};

TEST(SolvePolicy, AWarmStartBeginsWhereItIsTold) {
  // From 1e-5 or less inside active bounds (the QP's x1, x2, x4; HS71's x1 = 1): a cold start
  // pushes x at least 1e-2 off its bounds before the first iterate (Ipopt's bound_push) and
  // walks back; a warm start (SolverOptions::warm_start) begins at the given point. Both reach
  // the known optimum. (Iteration counts are not compared: on these small problems they are
  // within one of each other either way.)
  for (bool warm : {false, true}) {
    SCOPED_TRACE(warm ? "warm" : "cold");
    SolverOptions options;
    options.objective_change_tolerance = 0;
    options.warm_start = warm;

    const std::vector<double> near = {1 - 1e-5, 1e-5, 0.5, 1 - 1e-5};
    BoundedQp qp(near);
    const Solve q = solve(qp, options);
    ASSERT_TRUE(q.report.solved) << q.report.status;
    double moved = 0.0;
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(q.report.x[i], BoundedQp::kOptimum[i], 1e-6) << i;
      moved = std::max(moved, std::abs(qp.iterates.front().x[i] - near[i]));
    }
    if (warm) {
      EXPECT_LT(moved, 1e-5);
    } else {
      EXPECT_GT(moved, 5e-3);
    }

    Hs71From hs71({1 + 1e-6, 4.743, 3.821, 1.3794});
    const Solve h = solve(hs71, options);
    ASSERT_TRUE(h.report.solved) << h.report.status;
    EXPECT_NEAR(h.report.objective, Hs71::kObjective, 1e-6);
    if (warm) {
      EXPECT_LT(hs71.iterates.front().x[0] - 1.0, 1e-5);
    } else {
      EXPECT_GT(hs71.iterates.front().x[0] - 1.0, 5e-3);
    }
  }
}

TEST(SolvePolicy, WithoutAHessianSolvesByQuasiNewtonAndNeverAsksForOne) {
  Hs71 nlp;
  nlp.exact_hessian = false;
  SolverOptions options;
  options.objective_change_tolerance = 0;
  const Solve s = solve(nlp, options);
  EXPECT_EQ(nlp.hessian_structure_calls, 0);
  EXPECT_TRUE(nlp.hessian_points.empty());
  ASSERT_TRUE(s.report.solved) << s.report.status;
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(s.report.x[i], Hs71::kOptimum[i], 1e-5) << i;
  EXPECT_NEAR(s.report.objective, Hs71::kObjective, 1e-6);
}

TEST(SolvePolicy, WithoutAHessianFollowsRosenbrocksValleyByQuasiNewton) {
  // Curvature, even approximated from gradients, is what gets along the valley in tens of steps
  // (Ipopt's exact-Hessian mode fed an empty Hessian diverges here).
  Rosenbrock nlp;
  nlp.exact_hessian = false;
  SolverOptions options;
  options.objective_change_tolerance = 0;
  options.max_iterations = 100;
  const Solve s = solve(nlp, options);
  EXPECT_EQ(nlp.hessian_structure_calls, 0);
  ASSERT_TRUE(s.report.solved) << s.report.status;
  EXPECT_NEAR(s.report.x[0], 1.0, 1e-6);
  EXPECT_NEAR(s.report.x[1], 1.0, 1e-6);
}

TEST(SolvePolicy, ReportsInfeasibleProblemsAsSuch) {
  Infeasible nlp;
  const Solve s = solve(nlp, SolverOptions{});
  EXPECT_EQ(s.report.status, "infeasible");
  EXPECT_FALSE(s.report.solved);
  // On the way Ipopt entered its restoration phase, and the NLP was told (StepTaken).
  EXPECT_TRUE(std::any_of(nlp.steps.begin(), nlp.steps.end(),
                          [](const StepTaken& step) { return step.restoration; }));
}

// ---------------------------------------------------------------------------------------------
// Iterations, progress and the NLP's view of them.

TEST(SolvePolicy, ReportsProgressOncePerIterationBeforeThatIterationsHessian) {
  Hs71 nlp;
  const Solve s = solve(nlp, SolverOptions{});
  ASSERT_TRUE(s.report.solved);
  ASSERT_EQ(static_cast<int>(s.progress.size()), s.report.iterations + 1);
  for (std::size_t i = 0; i < s.progress.size(); ++i) {
    EXPECT_EQ(s.progress[i].iteration, static_cast<int>(i));
    EXPECT_EQ(nlp.steps[i].iteration, static_cast<int>(i));
    EXPECT_FALSE(nlp.steps[i].restoration);
    EXPECT_GE(nlp.steps[i].line_search_trials, i == 0 ? 0 : 1);
    if (i > 0) {
      EXPECT_GE(s.progress[i].elapsed_seconds, s.progress[i - 1].elapsed_seconds);
    }
  }
  EXPECT_LE(s.progress.back().elapsed_seconds, s.report.seconds);
  // Each Hessian is asked for at the iterate the NLP has just been told about (nlp.h: step_taken
  // comes "before that iterate's Hessian"), one per iteration.
  ASSERT_EQ(nlp.hessian_points.size(), s.progress.size() - 1);
  for (std::size_t h = 0; h < nlp.hessian_points.size(); ++h) {
    EXPECT_EQ(nlp.hessian_after_iterate[h], static_cast<int>(h));
    EXPECT_EQ(nlp.hessian_points[h], nlp.iterates[h].x) << "Hessian " << h;
  }
}

TEST(SolvePolicy, ProgressGivesTheConstraintViolationOfTheIterate) {
  // With one equality constraint Ipopt's primal infeasibility is |g(x)|, computed here from x.
  Overshoot nlp;
  SolverOptions options;
  options.stall_iterations = 0;
  const Solve s = solve(nlp, options);
  ASSERT_TRUE(s.report.solved);
  for (std::size_t i = 0; i < s.progress.size(); ++i)
    EXPECT_NEAR(s.progress[i].constraint_violation, nlp.iterates[i].violation,
                1e-12 + 1e-9 * nlp.iterates[i].violation)
        << i;
}

TEST(SolvePolicy, StopsAtTheIterationLimit) {
  for (int limit : {0, 3}) {
    Hs71 nlp;
    SolverOptions options;
    options.max_iterations = limit;
    const Solve s = solve(nlp, options);
    EXPECT_EQ(s.report.status, "max_iterations") << limit;
    EXPECT_EQ(s.report.ipopt_status, "maximum iterations exceeded");
    EXPECT_FALSE(s.report.solved);
    EXPECT_EQ(s.report.iterations, limit);
    EXPECT_EQ(nlp.iterates.back().iteration, limit);
  }
}

// ---------------------------------------------------------------------------------------------
// The acceptable exit (SolverOptions::objective_change_tolerance).

/// The first iteration at which the last `count` relative objective changes,
/// |f_k − f_(k−1)| / max(1, |f_k|), were all within `tolerance`; −1 if none.
int first_settled_iteration(const std::vector<Iterate>& iterates, double tolerance, int count) {
  int run_length = 0;
  for (std::size_t k = 1; k < iterates.size(); ++k) {
    const double f = iterates[k].objective;
    const double change = std::abs(f - iterates[k - 1].objective) / std::max(1.0, std::abs(f));
    run_length = change <= tolerance ? run_length + 1 : 0;
    if (run_length >= count) return iterates[k].iteration;
  }
  return -1;
}

TEST(SolvePolicy, AcceptsOnceTheObjectiveHasSettledForTheGivenIterations) {
  FlatMinimum optimal_nlp;
  SolverOptions optimal;
  optimal.objective_change_tolerance = 0;
  const Solve reference = solve(optimal_nlp, optimal);
  ASSERT_EQ(reference.report.ipopt_status, "optimal");

  for (double tolerance : {1e-3, 1e-5}) {
    for (int count : {3, 5}) {
      FlatMinimum nlp;
      SolverOptions options;
      options.objective_change_tolerance = tolerance;
      options.acceptable_iterations = count;
      const Solve s = solve(nlp, options);
      SCOPED_TRACE("tolerance " + std::to_string(tolerance) + ", " + std::to_string(count));
      EXPECT_EQ(s.report.status, "solved");
      EXPECT_EQ(s.report.ipopt_status, "acceptable");
      // The run follows the same path as the optimal one and stops exactly where the objective
      // had changed by less than the tolerance `count` times in a row.
      const int settled = first_settled_iteration(optimal_nlp.iterates, tolerance, count);
      ASSERT_GT(settled, 0);
      EXPECT_LT(settled, reference.report.iterations);
      EXPECT_EQ(s.report.iterations, settled);
      EXPECT_EQ(first_settled_iteration(nlp.iterates, tolerance, count), settled);
    }
  }
}

TEST(SolvePolicy, AcceptableExitNeedsTheConstraintsMet) {
  // Overshoot's objective changes by less than 1 % per iteration only from radius ~1.01 on, where
  // the violation is below 1e-5: with an acceptable violation of 1e-9 the acceptable exit must
  // wait for the constraint, so it cannot come before the first iterate that meets it.
  Overshoot nlp(1.5);
  SolverOptions options;
  options.objective_change_tolerance = 1e-2;
  options.acceptable_iterations = 1;
  options.acceptable_constraint_violation = 1e-9;
  options.stall_iterations = 0;
  const Solve s = solve(nlp, options);
  ASSERT_TRUE(s.report.solved) << s.report.status;
  const int settled = first_settled_iteration(nlp.iterates, 1e-2, 1);
  ASSERT_GT(settled, 0);
  int met = -1;
  for (const Iterate& it : nlp.iterates)
    if (met < 0 && it.violation <= 1e-9) met = it.iteration;
  ASSERT_GT(met, settled) << "the case must make the constraint the later condition";
  EXPECT_GE(s.report.iterations, met);
}

// ---------------------------------------------------------------------------------------------
// Stalls, restarts and which iterate is returned (SolverOptions::stall_iterations).

/// Overshoot's path from radius 0.1 follows r ← (r² + 1) / 2r; checks that it did.
void expect_newton_radii(const std::vector<Iterate>& run, double start) {
  double r = start;
  for (const Iterate& it : run) {
    EXPECT_NEAR(radius(it.x), r, 1e-9 * r) << "run " << it.run << " iteration " << it.iteration;
    r = (r * r + 1) / (2 * r);
  }
}

TEST(SolvePolicy, RestartsFromTheBestFeasibleIterateAfterAStall) {
  Overshoot nlp;
  SolverOptions options;
  options.stall_iterations = 3;
  options.max_restarts = 2;
  const Solve s = solve(nlp, options);
  const std::vector<Iterate> first = nlp.run(0), second = nlp.run(1);
  expect_newton_radii(first, 0.1);
  // The best iterate within the acceptable violation is iteration 1 (radius 5.05, f = −25.25);
  // three iterations later, none having improved on it, the run stops ...
  ASSERT_EQ(best_feasible(s, options.acceptable_constraint_violation), 1);
  ASSERT_NEAR(nlp.iterates[1].objective, -25.25, 1e-12);
  EXPECT_EQ(first.back().iteration, 1 + options.stall_iterations);
  // ... and Ipopt starts again from exactly that iterate, with its iteration count carried on.
  ASSERT_FALSE(second.empty());
  EXPECT_EQ(second.front().x, nlp.iterates[1].x);
  expect_newton_radii(second, 5.05);
  EXPECT_EQ(s.report.restarts, 1);
  EXPECT_EQ(nlp.run(2).size(), 0u);
  EXPECT_EQ(s.report.iterations, first.back().iteration + second.back().iteration);
  EXPECT_EQ(s.progress[first.size()].iteration, first.back().iteration);
  // The restarted run finds nothing better than where it began, never stalls, and converges.
  EXPECT_TRUE(s.report.solved);
  EXPECT_NEAR(s.report.x[0], 0.6, 1e-8);
  EXPECT_NEAR(s.report.x[1], 0.8, 1e-8);
}

TEST(SolvePolicy, StalledWithNoRestartLeftReturnsTheBestFeasibleIterate) {
  Overshoot nlp;
  SolverOptions options;
  options.stall_iterations = 3;
  options.max_restarts = 0;
  const Solve s = solve(nlp, options);
  EXPECT_EQ(s.report.status, "stalled");
  EXPECT_FALSE(s.report.solved);
  EXPECT_EQ(s.report.restarts, 0);
  EXPECT_EQ(s.report.iterations, 1 + options.stall_iterations);
  // The last iterate (radius 1.08, f = −5.42) is worse than iteration 1's: that one is returned.
  EXPECT_GT(nlp.iterates.back().objective, nlp.iterates[1].objective);
  EXPECT_EQ(s.report.x, nlp.iterates[1].x);
  EXPECT_EQ(s.report.objective, nlp.iterates[1].objective);
}

TEST(SolvePolicy, DoesNotRestartARunWhoseBestIterateIsItsStart) {
  // From radius 5.05 every iterate is worse than the start; restarting there would retrace the
  // same path, so the run goes on to the optimum without a stop.
  Overshoot nlp(5.05);
  SolverOptions options;
  options.stall_iterations = 3;
  const Solve s = solve(nlp, options);
  ASSERT_EQ(best_feasible(s, options.acceptable_constraint_violation), 0);
  EXPECT_GT(s.report.iterations, options.stall_iterations);
  EXPECT_EQ(s.report.restarts, 0);
  EXPECT_EQ(s.report.ipopt_status, "optimal");
}

TEST(SolvePolicy, RestartsShareTheIterationBudget) {
  Overshoot nlp;
  SolverOptions options;
  options.stall_iterations = 3;
  options.max_iterations = 6;
  const Solve s = solve(nlp, options);
  // 4 iterations before the stall, 2 left for the restarted run.
  EXPECT_EQ(s.report.restarts, 1);
  EXPECT_EQ(nlp.run(0).back().iteration, 4);
  EXPECT_EQ(nlp.run(1).back().iteration, 2);
  EXPECT_EQ(s.report.iterations, 6);
  EXPECT_EQ(s.report.status, "max_iterations");
  EXPECT_EQ(s.report.x, nlp.iterates[1].x);  // the best feasible iterate, not the last
  EXPECT_LE(s.progress.back().iteration, options.max_iterations);

  // A stall on the last iteration of the budget leaves nothing to restart with.
  Overshoot last;
  options.max_iterations = 4;
  const Solve t = solve(last, options);
  EXPECT_EQ(t.report.restarts, 0);
  EXPECT_EQ(t.report.iterations, 4);
  EXPECT_EQ(t.report.status, "stalled");
}

TEST(SolvePolicy, StoppedEarlyReturnsTheBetterOfItsLastAndBestFeasibleIterates) {
  for (int limit = 1; limit <= 6; ++limit) {
    SCOPED_TRACE("max_iterations " + std::to_string(limit));
    for (bool wander : {true, false}) {
      // Overshoot's best feasible iterate comes early and the later ones are worse; Hock–
      // Schittkowski 71's first iterate within a violation of 0.02 (iteration 2) is followed by
      // lower ones that violate the constraints more.
      Overshoot overshoot;
      Hs71 hs71;
      DenseNlp& nlp = wander ? static_cast<DenseNlp&>(overshoot) : hs71;
      SolverOptions options;
      options.max_iterations = limit;
      options.stall_iterations = 0;
      options.objective_change_tolerance = 0;
      options.acceptable_constraint_violation = 0.02;
      const Solve s = solve(nlp, options);
      ASSERT_FALSE(s.report.solved);
      const int best = best_feasible(s, options.acceptable_constraint_violation);
      const bool best_wins = best >= 0 && s.progress[best].objective < s.progress.back().objective;
      const Iterate& expected = best_wins ? nlp.iterates[best] : nlp.iterates.back();
      EXPECT_EQ(s.report.x, expected.x) << (best_wins ? "best feasible" : "last") << " iterate";
    }
  }
}

TEST(SolvePolicy, TheCasesAboveReturnBothKindsOfIterate) {
  // Guards the previous test against a path on which the last and the best feasible iterate
  // coincide: each kind must be returned at least once, and differ from the other there.
  int last_returned = 0, best_returned = 0;
  for (int limit = 1; limit <= 6; ++limit) {
    for (bool wander : {true, false}) {
      Overshoot overshoot;
      Hs71 hs71;
      DenseNlp& nlp = wander ? static_cast<DenseNlp&>(overshoot) : hs71;
      SolverOptions options;
      options.max_iterations = limit;
      options.stall_iterations = 0;
      options.objective_change_tolerance = 0;
      options.acceptable_constraint_violation = 0.02;
      const Solve s = solve(nlp, options);
      const int best = best_feasible(s, options.acceptable_constraint_violation);
      if (best < 0 || nlp.iterates[best].x == nlp.iterates.back().x) continue;
      (s.report.x == nlp.iterates.back().x ? last_returned : best_returned) += 1;
    }
  }
  EXPECT_GT(last_returned, 0);
  EXPECT_GT(best_returned, 0);
}

// ---------------------------------------------------------------------------------------------
// Cancellation.

TEST(SolvePolicy, CancelStopsAtTheNextIteration) {
  Hs71 nlp;
  std::atomic<bool> cancel{false};
  const Solve s = solve(
      nlp, SolverOptions{}, [&](const ProgressInfo& p) { cancel = p.iteration == 2; }, &cancel);
  EXPECT_EQ(s.report.status, "cancelled");
  EXPECT_EQ(s.report.ipopt_status, "user requested stop");
  EXPECT_FALSE(s.report.solved);
  EXPECT_EQ(s.report.iterations, 2);
  EXPECT_EQ(nlp.iterates.back().iteration, 2);
  EXPECT_EQ(nlp.hessian_points.size(), 2u);  // no Hessian for the iteration that was not taken
}

TEST(SolvePolicy, CancelBeforeTheStartStopsAtIterationZero) {
  Hs71 nlp;
  std::atomic<bool> cancel{true};
  const Solve s = solve(nlp, SolverOptions{}, {}, &cancel);
  EXPECT_EQ(s.report.status, "cancelled");
  EXPECT_EQ(s.report.iterations, 0);
  EXPECT_TRUE(nlp.hessian_points.empty());
}

TEST(SolvePolicy, CancelOnAStallIterationCancelsInsteadOfRestarting) {
  Overshoot nlp;
  SolverOptions options;
  options.stall_iterations = 3;
  std::atomic<bool> cancel{false};
  const Solve s = solve(
      nlp, options, [&](const ProgressInfo& p) { cancel = p.iteration == 4; }, &cancel);
  EXPECT_EQ(s.report.status, "cancelled");
  EXPECT_EQ(s.report.restarts, 0);
  EXPECT_EQ(s.report.iterations, 4);
}

TEST(SolvePolicy, ProgressCarriesTheSolvesOwnCountAndItsAcceptableExit) {
  Hs71 nlp;
  SolverOptions options;
  options.objective_change_tolerance = 2e-3;
  options.acceptable_iterations = 4;
  std::vector<ProgressInfo> seen;
  solve(nlp, options, [&](const ProgressInfo& p) { seen.push_back(p); });
  ASSERT_FALSE(seen.empty());
  for (const ProgressInfo& p : seen) {
    EXPECT_EQ(p.stage_iteration, p.iteration);  // a solve on its own: its count is the run's
    EXPECT_EQ(p.objective_change_tolerance, 2e-3);
    EXPECT_EQ(p.acceptable_iterations, 4);
    EXPECT_EQ(p.stage.kind, SolveStage::Kind::kSolve);
  }
}

TEST(SolveStage, WordsNameTheStageItsStepAndWhatTheObjectiveIs) {
  EXPECT_EQ(solve_stage_words({}), "solving");
  const SolveStage level2{SolveStage::Kind::kLevel, 2, 3, false};
  EXPECT_EQ(solve_stage_words(level2),
            "level 2 of at most 3: the least root force on knots refined where it lives");
  EXPECT_EQ(solve_stage_words({SolveStage::Kind::kLevel, 1, 1, false}),
            "the least root force on the knots asked for");
  const SolveStage joints{SolveStage::Kind::kJoints, 2, 5, true};
  EXPECT_EQ(solve_stage_words(joints),
            "second pass for the landing, joints, try 2 of at most 5: least joint effort at the "
            "keyframe times found, the root force held");
  EXPECT_NE(objective_meaning_words(level2).find("a jump between stages is no failure"),
            std::string::npos);
  EXPECT_NE(objective_meaning_words(joints).find("least joint effort"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Options that reach Ipopt, and the ones that must not.

TEST(SolvePolicy, IgnoresAnIpoptOptionsFileInTheWorkingFolder) {
  // Ipopt reads ./ipopt.opt unless told otherwise; one here would stop it after one iteration.
  const std::filesystem::path folder = test::temp_path("ipopt-opt");
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "ipopt.opt") << "max_iter 1\n";
  const std::filesystem::path previous = std::filesystem::current_path();
  std::filesystem::current_path(folder);
  Hs71 nlp;
  const SolveReport report = solve_nlp(nlp, SolverOptions{});
  std::filesystem::current_path(previous);
  std::filesystem::remove_all(folder);
  EXPECT_TRUE(report.solved) << report.status;
  EXPECT_GT(report.iterations, 1);
}

/// Hock–Schittkowski 71 with ∂f/∂x3 half as large again as it is.
class Hs71WrongGradient : public Hs71 {
  void grad_f(const double* x, double* out) const override {
    Hs71::grad_f(x, out);
    out[2] *= 1.5;
  }
};

std::string derivative_check(DenseNlp& nlp, const std::string& name) {
  const std::string file = test::temp_path(name + ".txt").string();
  SolverOptions options;
  options.max_iterations = 0;
  options.derivative_test_file = file;
  solve_nlp(nlp, options);
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(file);
  return text;
}

TEST(SolvePolicy, DerivativeCheckerWritesItsVerdictToTheGivenFile) {
  Hs71 right;
  const std::string good = derivative_check(right, "derivatives-right");
  EXPECT_NE(good.find("No errors detected by derivative checker"), std::string::npos) << good;
  Hs71WrongGradient wrong;
  const std::string bad = derivative_check(wrong, "derivatives-wrong");
  EXPECT_NE(bad.find("grad_f[          2]"), std::string::npos) << bad;
  EXPECT_NE(bad.find("Derivative checker detected 1 error"), std::string::npos) << bad;
}

// SolverOptions::feasibility_checkpoints on problems with known answers: min (x − 3)² subject to
// x² + 1 <= b. With b = 0.5 no x is feasible (the violation is at least 0.5, at x = 0), so a run
// must be stopped at the first checkpoint that asks for less; with b = 2 the optimum is x = 1
// and a checkpoint the run meets on its way must not stop it.
class Disk : public Nlp {
 public:
  explicit Disk(double bound) : bound_(bound) {}
  int variable_count() const override { return 1; }
  int constraint_count() const override { return 1; }
  void bounds(double* xl, double* xu, double* gl, double* gu) const override {
    xl[0] = -kUnbounded, xu[0] = kUnbounded, gl[0] = -kUnbounded, gu[0] = bound_;
  }
  void initial_point(double* x) const override { x[0] = 10.0; }
  double objective(const double* x) override { return (x[0] - 3) * (x[0] - 3); }
  void gradient(const double* x, double* g) override { g[0] = 2 * (x[0] - 3); }
  void constraints(const double* x, double* g) override { g[0] = x[0] * x[0] + 1; }
  int jacobian_nonzeros() const override { return 1; }
  void jacobian_structure(int* rows, int* columns) const override { rows[0] = columns[0] = 0; }
  void jacobian_values(const double* x, double* values) override { values[0] = 2 * x[0]; }
  bool has_hessian() const override { return true; }
  int hessian_nonzeros() const override { return 1; }
  void hessian_structure(int* rows, int* columns) const override { rows[0] = columns[0] = 0; }
  void hessian_values(const double*, double sigma, const double* lambda, double* values) override {
    values[0] = 2 * sigma + 2 * lambda[0];
  }

 private:
  double bound_;
};

TEST(FeasibilityCheckpoint, AnInfeasibleRunStopsAtTheCheckpointAndSaysSo) {
  Disk nlp(0.5);
  SolverOptions options;
  options.feasibility_checkpoints = {{1, 0.5}};
  const SolveReport report = solve_nlp(nlp, options);
  EXPECT_EQ(report.status, "stopped_infeasible");
  EXPECT_FALSE(report.solved);
  EXPECT_EQ(report.iterations, 1);
  EXPECT_EQ(report.ipopt_status,
            "stopped early: constraint violation never below 0.5 in 1 iterations");
  ASSERT_EQ(report.x.size(), 1u);
  EXPECT_TRUE(std::isfinite(report.x[0]));
}

TEST(FeasibilityCheckpoint, ARunThatMeetsItsCheckpointsSolves) {
  // x0 = 10 violates x² + 1 <= 2 by 99; Newton comes below 1 within a few iterations.
  Disk nlp(2.0);
  SolverOptions options;
  options.feasibility_checkpoints = {{8, 1.0}, {30, 0.5}};
  const SolveReport report = solve_nlp(nlp, options);
  EXPECT_EQ(report.status, "solved") << report.ipopt_status;
  ASSERT_EQ(report.x.size(), 1u);
  EXPECT_NEAR(report.x[0], 1.0, 1e-6);
  // The same run without checkpoints takes the same path.
  Disk again(2.0);
  const SolveReport free = solve_nlp(again, SolverOptions{});
  EXPECT_EQ(free.iterations, report.iterations);
  EXPECT_EQ(free.x, report.x);
}

TEST(FeasibilityCheckpoint, NoCheckpointsNoEarlyStop) {
  Disk nlp(0.5);
  SolverOptions options;
  options.max_iterations = 40;
  const SolveReport report = solve_nlp(nlp, options);
  EXPECT_NE(report.status, "stopped_infeasible");
  EXPECT_FALSE(report.solved);
}

}  // namespace
}  // namespace saltus
