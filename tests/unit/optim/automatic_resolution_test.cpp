// The automatic resolution's rules (optim/automatic_resolution.h) without an optimisation: the
// first guess from how far a steady somersault turns per interval and the refinement factor from
// the power law it assumes, at its edges.

#include "saltus/optim/automatic_resolution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/test_motions.h"

namespace saltus {
namespace {

/// A straight body somersaulting at `rate` (rad/s), keyframed every `step` seconds over `duration`.
Motion steady_somersault(const BodyModel& model, double rate, double step, double duration) {
  Motion m = test::base_motion("steady somersault");
  const int intervals = static_cast<int>(std::lround(duration / step));
  for (int i = 0; i <= intervals; ++i) {
    test::PoseDeg pose;
    pose.root_x = rate * step * i * 180.0 / M_PI;
    m.keyframes.push_back(test::keyframe(model, step * i, pose));
  }
  return m;
}

TEST(AutomaticResolution, FirstGuessSplitsAnIntervalByHowFarTheBodyTurnsInItAndByItsLength) {
  // The first level's spans, from the physics of the motion: a body turning at ω over an
  // interval of Δ gets ⌈ω·Δ / 1.6 rad⌉ spans (92° per span at the fastest rate), at least
  // ⌈Δ / 0.26 s⌉ of them. Values chosen half-way between two span counts, so that the spline's
  // rate may differ from ω by a third either way.
  const BodyModel model = test::bundled_model();
  const AutomaticResolution rules;
  ASSERT_NEAR(rules.turn_per_span, 1.6, 1e-12);
  ASSERT_NEAR(rules.max_span, 0.26, 1e-12);
  struct Case {
    double rate, step, duration;
    int spans;
  };
  // 137.5° per 0.2 s: 1.5 spans' worth -> 2; 46° per 0.2 s -> 1; 69° per 0.4 s: by length -> 2.
  for (const Case& c : {Case{12.0, 0.2, 1.0, 2}, Case{4.0, 0.2, 1.0, 1}, Case{3.0, 0.4, 1.2, 2}}) {
    SCOPED_TRACE(c.rate);
    const Motion motion = steady_somersault(model, c.rate, c.step, c.duration);
    EXPECT_EQ(first_subdivisions(motion, model, rules),
              std::vector<int>(motion.keyframes.size() - 1, c.spans));
  }
}

TEST(AutomaticResolution, RefiningSplitsEachIntervalByThePowerLawsFactorAndNeverCoarsens) {
  const AutomaticResolution rules;
  // An interval of 0.5 s whose mean squared wrench m asks for a factor f exactly:
  // (m / (6·target²))^(1/(2p)) = f, so m = 6·target²·f^(2p).
  const double length = 0.5;
  auto residual_for = [&](double factor) {
    return 6.0 * rules.target_force * rules.target_force *
           std::pow(factor, 2.0 * rules.convergence_order) * length;
  };
  std::vector<int> spans = {1, 2, 3};
  const std::vector<double> times = {0.0, 0.5, 1.0, 1.5};
  // Exactly a factor 2; just past it (3); below the target (none).
  EXPECT_TRUE(
      refine(spans, {residual_for(2.0), residual_for(2.0 * (1 + 1e-6)), 0.1}, times, rules));
  EXPECT_EQ(spans, (std::vector<int>{2, 6, 3}));
  // At most max_spans_per_interval spans, and an interval already there stays.
  spans = {rules.max_spans_per_interval - 1, rules.max_spans_per_interval, 1};
  EXPECT_TRUE(refine(spans, {residual_for(4.0), residual_for(4.0), 0.0}, times, rules));
  EXPECT_EQ(spans,
            (std::vector<int>{rules.max_spans_per_interval, rules.max_spans_per_interval, 1}));
  // Nothing left to refine: false, spans unchanged.
  EXPECT_FALSE(refine(spans, {residual_for(4.0), residual_for(4.0), 0.0}, times, rules));
}

}  // namespace
}  // namespace saltus
