// The convergence study's pure parts: the factorial design and the seeded timing disturbance.
// (Its tables: unit/formats/convergence_files_test.cpp; whole studies: tests/cli/study_test.cpp.)

#include "saltus/studies/convergence_study.h"

#include <gtest/gtest.h>

#include <set>

#include "support/test_motions.h"

namespace saltus {
namespace {

Motion nine_keyframes() {
  const BodyModel model = test::bundled_model();
  Motion m = test::base_motion("nine");
  for (int i = 0; i < 9; ++i)
    m.keyframes.push_back(test::keyframe(model, 2.04 * i / 8, {-45.0 * i}));
  return m;
}

TEST(DisturbKeyframeTimes, MovesEveryInteriorTimeByTheAmplitudeKeepingOrderAndEnds) {
  const Motion m = nine_keyframes();
  const Motion d = disturb_keyframe_times(m, 0.1, 7);
  ASSERT_EQ(d.keyframes.size(), m.keyframes.size());
  EXPECT_EQ(d.keyframes.front().time, 0.0);
  EXPECT_EQ(d.keyframes.back().time, m.flight_time());
  std::set<double> signs;
  for (std::size_t i = 1; i + 1 < m.keyframes.size(); ++i) {
    const double shift = d.keyframes[i].time - m.keyframes[i].time;
    // Spacing 0.255 s leaves room for ±0.1 with the 0.05 s gap: no clamping here.
    EXPECT_NEAR(std::abs(shift), 0.1, 1e-12) << i;
    signs.insert(shift > 0 ? 1 : -1);
    EXPECT_GE(d.keyframes[i].time - d.keyframes[i - 1].time, 0.05 - 1e-12);
    EXPECT_EQ(d.keyframes[i].rotations[0].coeffs(), m.keyframes[i].rotations[0].coeffs());
  }
  EXPECT_EQ(signs.size(), 2u) << "seven fair coin flips all the same way: not random";
  // Seeded: the same seed gives the same times, another seed other ones.
  const Motion again = disturb_keyframe_times(m, 0.1, 7);
  const Motion other = disturb_keyframe_times(m, 0.1, 8);
  bool differs = false;
  for (std::size_t i = 0; i < m.keyframes.size(); ++i) {
    EXPECT_EQ(again.keyframes[i].time, d.keyframes[i].time);
    differs |= other.keyframes[i].time != d.keyframes[i].time;
  }
  EXPECT_TRUE(differs);
}

TEST(DisturbKeyframeTimes, LargeShiftsArePushedApartNotReordered) {
  const Motion m = nine_keyframes();
  const Motion d = disturb_keyframe_times(m, 0.3, 3, 0.05);
  for (std::size_t i = 1; i < d.keyframes.size(); ++i)
    EXPECT_GE(d.keyframes[i].time - d.keyframes[i - 1].time, 0.05 - 1e-12) << i;
}

TEST(ConvergenceStudyCases, IsTheFactorialDesignWithTheNominalMassOnce) {
  ConvergenceStudyOptions options;
  options.epsilons = {10, 500};
  options.mass_errors = {-0.2, 0.0, 0.2};
  options.mass_segments = {"all", "thigh_r"};
  options.timing_errors = {0.0, 0.1};
  const std::vector<LabelledMotion> motions{{"A", {}}, {"B", {}}};
  const auto cases = convergence_study_cases(motions, options);
  // 2 motions × 3 formulations × (1 nominal + 2 segments × 2 errors) × 2 timings.
  EXPECT_EQ(cases.size(), 2u * 3u * 5u * 2u);
  int relaxed = 0, nominal = 0;
  for (const StudyCase& c : cases) {
    relaxed += c.formulation == Formulation::kRelaxed;
    nominal += c.mass_error == 0.0;
    if (c.formulation == Formulation::kRelaxed) {
      EXPECT_EQ(c.epsilon, 0.0);
    }
  }
  EXPECT_EQ(relaxed, 2 * 5 * 2);
  EXPECT_EQ(nominal, 2 * 3 * 2);
}

}  // namespace
}  // namespace saltus
