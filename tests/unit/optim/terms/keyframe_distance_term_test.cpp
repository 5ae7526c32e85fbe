// The strict model's keyframe-distance objective (optim/terms/keyframe_distance_term.h) and the
// relaxed model's keyframe prior (the same distance in units of the tolerances, weighted)
// against central finite differences, through the term interface (support/term_checks.h).

#include "saltus/optim/terms/keyframe_distance_term.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/term_checks.h"

namespace saltus {
namespace {

TEST(KeyframeDistanceTerm, ValueGradientAndGaussNewtonMatchFiniteDifferences) {
  test::RandomPoint p(Formulation::kStrict);
  test::check_term(p, p.term("keyframe distance"), p.x);
}

TEST(KeyframeDistanceTerm, TheRelaxedPriorIsTheDistanceInToleranceUnitsTimesItsWeight) {
  test::RandomPoint relaxed(Formulation::kRelaxed), strict(Formulation::kStrict);
  ASSERT_EQ(relaxed.x, strict.x);
  test::check_term(relaxed, relaxed.term("keyframe distance"), relaxed.x);
  relaxed.nlp->evaluations().load(relaxed.x.data());
  strict.nlp->evaluations().load(strict.x.data());
  const std::vector<double> prior =
      relaxed.term("keyframe distance").residuals(relaxed.nlp->evaluations());
  const std::vector<double> distance =
      strict.term("keyframe distance").residuals(strict.nlp->evaluations());
  ASSERT_EQ(prior.size(), distance.size());
  const double w = relaxed.nlp->options().keyframe_weight;
  const Tolerances& tol = relaxed.motion.tolerances;
  const std::size_t per_keyframe =
      3 + 4 * static_cast<std::size_t>(relaxed.nlp->layout().segment_count);
  ASSERT_GT(w, 0.0);
  for (std::size_t e = 0; e < prior.size(); ++e) {
    const double epsilon = e % per_keyframe < 3 ? tol.translation_m : tol.quaternion;
    EXPECT_NEAR(prior[e], std::sqrt(w) / epsilon * distance[e], 1e-12 + 1e-12 * std::abs(prior[e]))
        << e;
  }
}

}  // namespace
}  // namespace saltus
