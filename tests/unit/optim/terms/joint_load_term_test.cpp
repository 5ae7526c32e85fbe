// The least-joint-effort term (optim/terms/joint_load_term.h): value, gradient and curvature
// against central finite differences through the term interface (support/term_checks.h), with
// time variables included; its value against the joint moments of inverse dynamics evaluated
// on the trajectory directly (no derivative code); and zero weight for the root's own wrench.

#include "saltus/optim/terms/joint_load_term.h"

#include <gtest/gtest.h>

#include "saltus/evaluation/sampling.h"
#include "saltus/math/gauss_legendre.h"
#include "support/term_checks.h"

namespace saltus {
namespace {

TEST(JointLoadTerm, ValueGradientAndCurvatureMatchFiniteDifferences) {
  test::RandomPoint p(Formulation::kRelaxed);
  test::check_term(p, p.term("joint loads"), p.x);
}

TEST(JointLoadTerm, IsTheMeanSquareOfTheJointMomentsOfTheTrajectory) {
  test::RandomPoint p(Formulation::kRelaxed);
  const TrajectoryLayout& layout = p.nlp->layout();
  const Trajectory<double> trajectory = trajectory_from(layout, p.nlp->reference(), p.x.data());
  const std::vector<double> start_knots =
      trajectory_from(layout, p.nlp->reference(), p.start.data()).knots;
  const double duration = trajectory.duration();
  JointLoadTerm term(layout, start_knots, duration, 0.5);
  NlpEvaluations& at = p.nlp->evaluations();
  at.load(p.x.data());
  // The same sum written out: 3-point Gauss–Lobatto on the starting spans' lengths, the nodes
  // placed on the current spans, every non-root joint's moment from inverse dynamics.
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
      for (int j = 1; j < p.model.size(); ++j)
        sum += samples[q].joint_wrench[j].tail<3>().squaredNorm();
      expected +=
          0.5 * rule.weights[q] * (start_knots[span + 1] - start_knots[span]) / duration * sum;
    }
  }
  EXPECT_NEAR(term.value(at), expected, 1e-6 * expected);
  EXPECT_GT(expected, 0.0);
}

}  // namespace
}  // namespace saltus
