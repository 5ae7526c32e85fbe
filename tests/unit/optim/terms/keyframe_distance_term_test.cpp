// The strict model's keyframe-distance objective (optim/terms/keyframe_distance_term.h) against
// central finite differences, through the term and block interfaces (support/term_checks.h).

#include "saltus/optim/terms/keyframe_distance_term.h"

#include <gtest/gtest.h>

#include "support/term_checks.h"

namespace saltus {
namespace {

TEST(KeyframeDistanceTerm, ValueGradientAndGaussNewtonMatchFiniteDifferences) {
  test::RandomPoint p(Formulation::kStrict);
  test::check_term(p, p.term("keyframe distance"), p.x);
}

}  // namespace
}  // namespace saltus
