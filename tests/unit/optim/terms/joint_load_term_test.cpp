// The least-joint-effort term (optim/terms/joint_load_term.h): value, gradient and curvature
// against central finite differences through the term interface (support/term_checks.h), with
// time variables included; its value against the joint moments of inverse dynamics evaluated
// on the trajectory directly (no derivative code); and zero weight for the root's own wrench.
// The same with a scale per joint (optimize_motion counts each joint against its input peak).

#include "saltus/optim/terms/joint_load_term.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "saltus/evaluation/sampling.h"
#include "saltus/math/gauss_legendre.h"
#include "support/term_checks.h"

namespace saltus {
namespace {

TEST(JointLoadTerm, ValueGradientAndCurvatureMatchFiniteDifferences) {
  test::RandomPoint p(Formulation::kRelaxed);
  test::check_term(p, p.term("joint loads"), p.x);
}

/// The term's value written out without derivative code: 3-point Gauss–Lobatto on the starting
/// spans' lengths, the nodes placed on the current spans, every non-root joint's moment from
/// inverse dynamics, joint j's counted as scales[j - 1]·n_j (empty: 1).
double mean_square_of_joint_moments(test::RandomPoint& p, double weight,
                                    const std::vector<double>& scales) {
  const TrajectoryLayout& layout = p.nlp->layout();
  const Trajectory<double> trajectory = trajectory_from(layout, p.nlp->reference(), p.x.data());
  const std::vector<double> start_knots =
      trajectory_from(layout, p.nlp->reference(), p.start.data()).knots;
  const QuadratureRule rule = gauss_lobatto(3);
  const std::vector<double>& knots = trajectory.knots;
  double expected = 0.0;
  for (int span = 3; span < layout.control_count(); ++span) {
    std::vector<double> times;
    for (int q = 0; q < 3; ++q)
      times.push_back(knots[span] + rule.nodes[q] * (knots[span + 1] - knots[span]));
    const std::vector<SampleRecord> samples = evaluate_trajectory(p.model, trajectory, times);
    for (int q = 0; q < 3; ++q) {
      double sum = 0.0;
      for (int j = 1; j < p.model.size(); ++j) {
        const double s = scales.empty() ? 1.0 : scales[j - 1];
        sum += s * s * samples[q].joint_wrench[j].tail<3>().squaredNorm();
      }
      expected += weight * rule.weights[q] * (start_knots[span + 1] - start_knots[span]) /
                  trajectory.duration() * sum;
    }
  }
  return expected;
}

TEST(JointLoadTerm, IsTheMeanSquareOfTheJointMomentsOfTheTrajectory) {
  test::RandomPoint p(Formulation::kRelaxed);
  const TrajectoryLayout& layout = p.nlp->layout();
  const Trajectory<double> start = trajectory_from(layout, p.nlp->reference(), p.start.data());
  JointLoadTerm term(layout, start.knots, start.duration(), 0.5);
  NlpEvaluations& at = p.nlp->evaluations();
  at.load(p.x.data());
  const double expected = mean_square_of_joint_moments(p, 0.5, {});
  EXPECT_NEAR(term.value(at), expected, 1e-6 * expected);
  EXPECT_GT(expected, 0.0);
}

TEST(JointLoadTerm, EachJointCountsByItsScale) {
  test::RandomPoint p(Formulation::kRelaxed);
  const TrajectoryLayout& layout = p.nlp->layout();
  const Trajectory<double> start = trajectory_from(layout, p.nlp->reference(), p.start.data());
  std::vector<double> scales;
  for (int j = 1; j < p.model.size(); ++j)
    scales.push_back(0.2 + 0.37 * j);
  JointLoadTerm term(layout, start.knots, start.duration(), 0.5, scales);
  test::check_term(p, term, p.x);
  NlpEvaluations& at = p.nlp->evaluations();
  at.load(p.x.data());
  const double expected = mean_square_of_joint_moments(p, 0.5, scales);
  EXPECT_NEAR(term.value(at), expected, 1e-6 * expected);
  EXPECT_GT(std::abs(expected - mean_square_of_joint_moments(p, 0.5, {})), 0.1 * expected);
}

}  // namespace
}  // namespace saltus
