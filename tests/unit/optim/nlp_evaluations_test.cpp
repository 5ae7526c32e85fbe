// What the optimiser's terms share at one point (optim/nlp_evaluations.h): the keyframe values and
// sampled root wrenches are those of a plain RootWrenchDerivatives at the same x, they do not
// depend on the number of threads (bit for bit), and a point is evaluated once.

#include "saltus/optim/nlp_evaluations.h"

#include <gtest/gtest.h>

#include "saltus/evaluation/sampling.h"
#include "support/term_checks.h"

namespace saltus {
namespace {

TEST(NlpEvaluations, GiveTheValuesOfAPlainEvaluatorForAnyThreadCount) {
  test::RandomPoint p(Formulation::kRelaxed, 5);
  const TrajectoryLayout& layout = p.nlp->layout();
  RootWrenchDerivatives plain(p.model, layout, p.nlp->reference());
  plain.set_variables(p.x.data());
  const std::vector<double> times = uniform_times(p.motion.flight_time(), 17);
  std::vector<std::vector<Vector6d>> wrenches;
  std::vector<std::vector<double>> rotation_derivatives;
  for (int threads : {1, 3}) {
    NlpEvaluations at(p.model, layout, p.nlp->reference(), threads);
    at.load(p.x.data());
    EXPECT_EQ(at.keyframe_times(), keyframe_times_from(layout, p.nlp->reference(), p.x.data()));
    at.need_keyframe_derivatives();
    for (int i = 0; i < layout.keyframe_count; ++i) {
      EXPECT_LT((at.keyframe_translation(i).value - plain.keyframe_translation_value(i)).norm(),
                1e-14);
      EXPECT_LT((at.keyframe_rotation(i, 4).value - plain.keyframe_rotation_value(i, 4)).norm(),
                1e-14);
    }
    WrenchSamples samples(times);
    const std::vector<Vector6d>& values = samples.values(at);
    const std::vector<LocalJacobian<6>>& jacobians = samples.jacobians(at);
    for (std::size_t k = 0; k < times.size(); ++k) {
      EXPECT_LT((values[k] - plain.wrench(times[k])).norm(), 1e-9 * (1 + values[k].norm())) << k;
      EXPECT_EQ(jacobians[k].value, values[k]) << k;
    }
    wrenches.push_back(values);
    const LocalJacobian<4>& r = at.keyframe_rotation(2, 7);
    rotation_derivatives.emplace_back(r.control.data(), r.control.data() + r.control.size());
  }
  EXPECT_EQ(wrenches[0], wrenches[1]);
  EXPECT_EQ(rotation_derivatives[0], rotation_derivatives[1]);
}

TEST(NlpEvaluations, ANewPointIsANewGenerationTheSamePointIsNot) {
  test::RandomPoint p(Formulation::kRelaxed, 6);
  NlpEvaluations at(p.model, p.nlp->layout(), p.nlp->reference(), 1);
  at.load(p.x.data());
  const long first = at.generation();
  std::vector<double> same = p.x;
  at.load(same.data());
  EXPECT_EQ(at.generation(), first);
  same[0] += 1e-9;
  at.load(same.data());
  EXPECT_GT(at.generation(), first);
  EXPECT_EQ(at.x()[0], same[0]);
}

}  // namespace
}  // namespace saltus
