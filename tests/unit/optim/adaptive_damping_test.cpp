// The trust-region rule of the relaxed model's damping factor μ (optim/adaptive_damping.h).

#include "saltus/optim/adaptive_damping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace saltus {
namespace {

TEST(AdaptiveDamping, ShrinksAfterWellPredictedStepsDownToItsFloor) {
  DampingRule rule;
  AdaptiveDamping damping(rule);
  EXPECT_EQ(damping.factor(), rule.initial);
  damping.update(0.9, false);
  EXPECT_DOUBLE_EQ(damping.factor(), rule.initial / rule.shrink);
  for (int i = 0; i < 100; ++i)
    damping.update(1.0, false);
  EXPECT_DOUBLE_EQ(damping.factor(), rule.minimum);
}

TEST(AdaptiveDamping, GrowsAfterPoorOrShortenedStepsUpToItsCeiling) {
  DampingRule rule;
  AdaptiveDamping damping(rule);
  damping.update(0.1, false);  // poorly predicted
  EXPECT_DOUBLE_EQ(damping.factor(), rule.initial * rule.grow);
  damping.reset();
  damping.update(-3.0, false);  // the objective went up
  EXPECT_DOUBLE_EQ(damping.factor(), rule.initial * rule.grow);
  damping.reset();
  damping.update(1.0, true);  // a perfect prediction of a step the line search had to cut
  EXPECT_DOUBLE_EQ(damping.factor(), rule.initial * rule.grow);
  damping.update(std::numeric_limits<double>::quiet_NaN(), false);  // no verdict: be careful
  EXPECT_DOUBLE_EQ(damping.factor(), std::min(rule.maximum, rule.initial * rule.grow * rule.grow));
  for (int i = 0; i < 100; ++i)
    damping.update(0.0, false);
  EXPECT_DOUBLE_EQ(damping.factor(), rule.maximum);
}

TEST(AdaptiveDamping, KeepsItsFactorBetweenTheThresholds) {
  AdaptiveDamping damping;
  damping.update(0.5, false);
  EXPECT_DOUBLE_EQ(damping.factor(), DampingRule().initial);
  damping.update(0.25, false);  // the thresholds themselves are "fair"
  damping.update(0.75, false);
  EXPECT_DOUBLE_EQ(damping.factor(), DampingRule().initial);
}

}  // namespace
}  // namespace saltus
