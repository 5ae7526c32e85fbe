// The Optimise panel's progress (core/run_progress.h): the stage in the library's words, the
// count line, what the objective means, and the time left from the run's own pace: a solve
// whose objective's relative change falls geometrically is worked out to its acceptable exit,
// the solves that may follow are counted at this run's mean solve length, and nothing is
// promised before there is anything to go by.

#include "core/run_progress.h"

#include <gtest/gtest.h>

#include <cmath>

namespace saltus::gui {
namespace {

constexpr double kSecondsPerIteration = 0.2;

/// Reports of one solve of `iterations` iterations whose objective's relative change falls by
/// `ratio` an iteration from `change0`, after `before` iterations of the run; objective from 100.
std::vector<ProgressInfo> solve(SolveStage stage, int iterations, int before, double change0,
                                double ratio) {
  std::vector<ProgressInfo> out;
  double objective = 100.0;
  for (int k = 0; k <= iterations; ++k) {
    ProgressInfo p;
    p.stage = stage;
    p.stage_iteration = k;
    p.iteration = before + k;
    p.elapsed_seconds = kSecondsPerIteration * (before + k);
    p.objective_change_tolerance = 1e-3;
    p.acceptable_iterations = 3;
    // Relative change |f_k − f_k−1| / f_k = change0·ratio^k exactly.
    if (k > 0) objective /= 1.0 + change0 * std::pow(ratio, k);
    p.objective = objective;
    out.push_back(p);
  }
  return out;
}

const SolveStage kLevel1{SolveStage::Kind::kLevel, 1, 3, false};
const SolveStage kLevel2{SolveStage::Kind::kLevel, 2, 3, false};
const SolveStage kJoints1{SolveStage::Kind::kJoints, 1, 5, false};

TEST(RunProgress, SaysTheStageTheCountAndWhatTheObjectiveMeans) {
  RunProgress progress;
  EXPECT_FALSE(progress.started());
  for (const ProgressInfo& p : solve(kLevel2, 5, 30, 0.1, 0.8))
    progress.add(p);
  EXPECT_EQ(progress.stage_line(),
            "Level 2 of at most 3: the least root force on knots refined where it lives");
  EXPECT_EQ(progress.count_line().rfind("iteration 35 · 7.0 s · objective ", 0), 0u)
      << progress.count_line();
  EXPECT_EQ(progress.objective_line(), objective_meaning_words(kLevel2));
}

TEST(RunProgress, AConvergingSolveIsWorkedOutToItsAcceptableExit) {
  RunProgress progress(false);
  for (const ProgressInfo& p : solve({SolveStage::Kind::kLevel, 1, 1, false}, 8, 0, 0.1, 0.5))
    progress.add(p);
  const auto left = progress.time_left();
  ASSERT_TRUE(left);
  // The change at iteration 8 is 0.1·0.5^8 = 3.9e-4, already below 1e-3: only the acceptable
  // iterations remain at the least; at the most half as many again as it has taken (4).
  EXPECT_NEAR(left->least, 3 * kSecondsPerIteration, 1e-6);
  EXPECT_NEAR(left->most, 4 * kSecondsPerIteration, 1e-6);

  RunProgress early(false);
  for (const ProgressInfo& p : solve({SolveStage::Kind::kLevel, 1, 1, false}, 5, 0, 1.0, 0.5))
    early.add(p);
  // At iteration 5 the change is 0.5^5 = 0.031: log(0.031/1e-3)/log(2) = 4.97 more, then 3.
  ASSERT_TRUE(early.time_left());
  EXPECT_NEAR(early.time_left()->least, (std::log2(0.03125 / 1e-3) + 3) * kSecondsPerIteration,
              1e-6);
}

TEST(RunProgress, LaterSolvesCountAtThisRunsOwnSolvesBetweenNoneAndAllThatMayFollow) {
  RunProgress progress;  // joints follow the levels
  for (const ProgressInfo& p : solve(kLevel1, 30, 0, 0.1, 0.8))
    progress.add(p);
  for (const ProgressInfo& p : solve(kLevel2, 2, 30, 0.5, 1.0))
    progress.add(p);
  // Level 2 after two iterations, not converging yet: at the most as long as level 1 (30
  // iterations, 28 to go), then one more level (6 s) and two joints' tries; at the least one
  // try. A try before one has run: 1.5 times a level's 30 iterations at 5 times the levels'
  // pace (0.2 s): 45 s.
  const double pace = kSecondsPerIteration;
  const double joint_try = kJointTryIterations * 30 * kJointIterationCost * pace;
  auto left = progress.time_left();
  ASSERT_TRUE(left);
  EXPECT_NEAR(left->least, joint_try, 1e-6);
  EXPECT_NEAR(left->most, 28 * pace + 30 * pace + 2 * joint_try, 1e-6);
  EXPECT_NE(progress.time_left_line().find("s left (at 0.2 s an iteration)"), std::string::npos)
      << progress.time_left_line();
  // Six iterations into the joints' first try, not converging: at the most half as many again
  // (3), then one more try as long as 1.5 times the levels' mean (16 iterations: 30 and 2) at
  // its own pace.
  for (const ProgressInfo& p : solve(kJoints1, 6, 32, 0.5, 1.0))
    progress.add(p);
  left = progress.time_left();
  ASSERT_TRUE(left);
  EXPECT_NEAR(left->least, 0.0, 1e-9);
  EXPECT_NEAR(left->most, 3 * pace + kJointTryIterations * 16 * pace, 1e-6);
}

TEST(RunProgress, NoEstimateBeforeThereIsAnythingToGoBy) {
  RunProgress progress;
  EXPECT_EQ(progress.time_left_line(), "time left: estimating…");
  // The first solve, its objective not yet falling steadily.
  for (const ProgressInfo& p : solve(kLevel1, 3, 0, 0.2, 1.0))
    progress.add(p);
  EXPECT_FALSE(progress.time_left());
  EXPECT_EQ(progress.time_left_line(), "time left: estimating…");
}

}  // namespace
}  // namespace saltus::gui
