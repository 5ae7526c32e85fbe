// The polish's rules (optim/polish_rules.h) on their edges, from figures alone: each bar a try is
// held to (landing within 3 deg or no farther than the levels, root force within 0.5 N or no
// larger, a joint rise past 1.5x, the hopeless landing at 5 x 3 deg, the 1 N fallback over paying
// joints) is met at the edge and missed just past it, with the constants of optimize.h and
// evaluation/joint_loads.h rather than numbers copied from a run.

#include "saltus/optim/polish_rules.h"

#include <gtest/gtest.h>

#include <optional>

#include "saltus/evaluation/joint_loads.h"

namespace saltus {
namespace {

constexpr double kJustPast = 1e-9;
const PolishTry& bounded() {
  return kPolishTries[0];
}
const PolishTry& unbounded() {
  return kPolishTries[kPolishAttempts - 1];
}

PolishBaseline levels(double force, double drift, bool joints_pay = false) {
  PolishBaseline b;
  b.avg_root_force = force;
  b.landing_drift_deg = drift;
  b.joints_pay = joints_pay;
  return b;
}
PolishTryFigures tried(double force, double drift, bool solved = true) {
  return {solved, force, drift};
}

TEST(PolishRules, TheLaddersTriesAreBoundedFirstAndUnboundedLast) {
  ASSERT_GE(kPolishAttempts, 2);
  EXPECT_TRUE(bounded().joints_bounded);
  EXPECT_TRUE(bounded().from_levels);
  EXPECT_FALSE(unbounded().joints_bounded);
}

TEST(PolishRules, ATryLandsWithinTheBarOrNoFartherThanTheLevels) {
  const double bar = AutomaticResolution{}.max_landing_drift_deg;
  EXPECT_TRUE(polish_try_lands(tried(0.1, bar), levels(0.1, 0.5)));
  EXPECT_FALSE(polish_try_lands(tried(0.1, bar + kJustPast), levels(0.1, 0.5)));
  // Past the bar, but the levels flew off farther: it lands as well as they did.
  EXPECT_TRUE(polish_try_lands(tried(0.1, 2 * bar), levels(0.1, 2 * bar)));
  EXPECT_FALSE(polish_try_lands(tried(0.1, 2 * bar + kJustPast), levels(0.1, 2 * bar)));
}

TEST(PolishRules, ATryIsKeptSolvedWithinTheRootForceLimitOrTheLevelsAndLanding) {
  EXPECT_TRUE(polish_try_holds(tried(kPolishMaxRootForce, 1.0), levels(0.1, 0.5)));
  EXPECT_FALSE(polish_try_holds(tried(kPolishMaxRootForce + kJustPast, 1.0), levels(0.1, 0.5)));
  // Above the limit, but no more than the levels left.
  EXPECT_TRUE(polish_try_holds(tried(0.8, 1.0), levels(0.8, 0.5)));
  EXPECT_FALSE(polish_try_holds(tried(0.8 + kJustPast, 1.0), levels(0.8, 0.5)));
  EXPECT_FALSE(polish_try_holds(tried(0.1, 1.0, /*solved=*/false), levels(0.1, 0.5)));
  EXPECT_FALSE(polish_try_holds(tried(0.1, 4.0), levels(0.1, 0.5))) << "lands off";
}

TEST(PolishRules, ABoundedTryLandingFiveTimesTheBarOffEndsTheBoundedTries) {
  const double hopeless = kPolishHopelessDriftFactor * AutomaticResolution{}.max_landing_drift_deg;
  EXPECT_FALSE(
      polish_bounded_tries_hopeless(bounded(), false, tried(1.0, hopeless), levels(0.1, 0.5)));
  EXPECT_TRUE(polish_bounded_tries_hopeless(bounded(), false, tried(1.0, hopeless + kJustPast),
                                            levels(0.1, 0.5)));
  // Not while the levels themselves land farther off, nor for a kept or an unbounded try.
  EXPECT_FALSE(polish_bounded_tries_hopeless(bounded(), false, tried(1.0, hopeless + 1),
                                             levels(0.1, hopeless + 2)));
  EXPECT_FALSE(
      polish_bounded_tries_hopeless(bounded(), true, tried(1.0, hopeless + 1), levels(0.1, 0.5)));
  EXPECT_FALSE(polish_bounded_tries_hopeless(unbounded(), false, tried(1.0, hopeless + 1),
                                             levels(0.1, 0.5)));
}

TEST(PolishRules, AKeptTryPastTheJointBarIsSolvedAgainWithTighterBounds) {
  EXPECT_FALSE(polish_tightens(true, kJointLoadRiseLimit));
  EXPECT_TRUE(polish_tightens(true, kJointLoadRiseLimit + kJustPast));
  EXPECT_FALSE(polish_tightens(false, 3.0)) << "only a kept try";
}

TEST(PolishRules, FinerKnotsOnlyBeforeTheUnboundedTryOverPayingJointsWithACandidate) {
  const PolishBaseline paying = levels(0.2, 1.0, /*joints_pay=*/true);
  EXPECT_TRUE(polish_refines_before_unbounded(unbounded(), true, paying, true));
  EXPECT_FALSE(polish_refines_before_unbounded(bounded(), true, paying, true));
  EXPECT_FALSE(polish_refines_before_unbounded(unbounded(), false, paying, true))
      << "a resolution the user fixed";
  EXPECT_FALSE(polish_refines_before_unbounded(unbounded(), true, levels(0.2, 1.0), true));
  EXPECT_FALSE(polish_refines_before_unbounded(unbounded(), true, paying, false));
}

TEST(PolishRules, TheOverLimitCandidateIsTheLandingBoundedTryWithTheLeastRootForce) {
  const PolishBaseline b = levels(0.2, 1.0);
  EXPECT_TRUE(polish_over_limit_candidate(bounded(), false, tried(0.7, 2.0), b, std::nullopt));
  EXPECT_TRUE(polish_over_limit_candidate(bounded(), false, tried(0.7, 2.0), b, 0.7 + kJustPast));
  EXPECT_FALSE(polish_over_limit_candidate(bounded(), false, tried(0.7, 2.0), b, 0.7));
  EXPECT_FALSE(polish_over_limit_candidate(bounded(), true, tried(0.7, 2.0), b, std::nullopt));
  EXPECT_FALSE(polish_over_limit_candidate(bounded(), false, tried(0.7, 4.0), b, std::nullopt))
      << "lands off";
  EXPECT_FALSE(
      polish_over_limit_candidate(bounded(), false, tried(0.7, 2.0, false), b, std::nullopt));
  EXPECT_FALSE(polish_over_limit_candidate(unbounded(), false, tried(0.7, 2.0), b, std::nullopt));
}

TEST(PolishRules, TheFallbackIsABoundedTryUpToOneNewtonOnlyOverPayingJoints) {
  const PolishBaseline paying = levels(0.3, 1.0, /*joints_pay=*/true);
  const double limit = kPolishMaxRootForceOverPayingJoints;
  EXPECT_TRUE(polish_fallback_candidate(bounded(), false, tried(limit, 2.0), paying, std::nullopt));
  EXPECT_FALSE(polish_fallback_candidate(bounded(), false, tried(limit + kJustPast, 2.0), paying,
                                         std::nullopt));
  EXPECT_TRUE(polish_fallback_candidate(bounded(), false, tried(0.6, 2.0), paying, 0.7));
  EXPECT_FALSE(polish_fallback_candidate(bounded(), false, tried(0.7, 2.0), paying, 0.6))
      << "the least root force stays";
  EXPECT_FALSE(
      polish_fallback_candidate(bounded(), false, tried(0.6, 2.0), levels(0.3, 1.0), std::nullopt))
      << "joints that do not pay keep the unbounded try";
  EXPECT_FALSE(
      polish_fallback_candidate(unbounded(), false, tried(0.6, 2.0), paying, std::nullopt));
  EXPECT_FALSE(polish_fallback_candidate(bounded(), false, tried(0.6, 4.0), paying, std::nullopt));
  EXPECT_FALSE(polish_fallback_candidate(bounded(), true, tried(0.6, 2.0), paying, std::nullopt));
}

}  // namespace
}  // namespace saltus
