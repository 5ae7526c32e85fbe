// Human joints as constraints (optim/terms/joint_bound_block.h): the Jacobian against central
// finite differences with its sparsity (support/term_checks.h), with and without the forces, the
// columns a row declares (only the segments that move its joint), and
// the rows (each load's square against its bound's) against the joints' moments and forces of
// inverse dynamics evaluated on the trajectory directly (no derivative code).

#include "saltus/optim/terms/joint_bound_block.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "saltus/dynamics/joint_wrench_state_jacobian.h"
#include "saltus/evaluation/sampling.h"
#include "support/term_checks.h"

namespace saltus {
namespace {

/// A bound per joint that differs from joint to joint (so a row cannot pass with another's).
std::vector<double> bounds_from(int joints, double first, double step) {
  std::vector<double> b;
  for (int j = 0; j < joints; ++j)
    b.push_back(first + step * j);
  return b;
}

TEST(JointBoundBlock, JacobianMatchesFiniteDifferencesAndItsSparsity) {
  test::RandomPoint p(Formulation::kRelaxed);
  const int joints = p.model.size() - 1;
  JointBoundBlock moments(p.model, p.nlp->layout(), bounds_from(joints, 2.0, 0.5));
  test::check_block(p, moments, p.x);
  JointBoundBlock both(p.model, p.nlp->layout(), bounds_from(joints, 2.0, 0.5),
                       bounds_from(joints, 30.0, 7.0));
  test::check_block(p, both, p.x);
}

// A row declares the root translation's columns and those of the segments that move its joint
// (the test above shows the Jacobian is zero outside them); a knee's row leaves the arms out.
TEST(JointBoundBlock, ARowListsOnlyTheSegmentsThatMoveItsJoint) {
  test::RandomPoint p(Formulation::kRelaxed);
  const TrajectoryLayout& layout = p.nlp->layout();
  const int joints = p.model.size() - 1;
  JointBoundBlock block(p.model, layout, bounds_from(joints, 2.0, 0.5),
                        bounds_from(joints, 30.0, 7.0));
  const std::vector<std::vector<int>> sparsity = block.sparsity();
  int narrower = 0;
  for (std::size_t row = 0; row < sparsity.size(); ++row) {
    const int joint = static_cast<int>(row % (2 * joints)) / 2 + 1;
    std::vector<int> curves;
    for (const int column : sparsity[row]) {
      if (column >= layout.control_variable_count()) continue;  // a keyframe time
      const int curve = column % layout.curve_block() / 3;
      EXPECT_TRUE(curve == 0 || joint_wrench_depends_on(p.model, joint, curve - 1))
          << "row " << row << " (joint " << p.model.segments[joint].joint << ") lists segment "
          << p.model.segments[curve - 1].name;
      if (std::find(curves.begin(), curves.end(), curve) == curves.end()) curves.push_back(curve);
    }
    int expected = 1;
    for (int k = 0; k < p.model.size(); ++k)
      expected += joint_wrench_depends_on(p.model, joint, k);
    EXPECT_EQ(static_cast<int>(curves.size()), expected) << "row " << row;
    narrower += expected < layout.curve_count();
  }
  EXPECT_GT(narrower, static_cast<int>(sparsity.size()) / 2);
}

TEST(JointBoundBlock, RowsAreEachJointsLoadAgainstItsBoundOnTheTrajectory) {
  test::RandomPoint p(Formulation::kRelaxed);
  const TrajectoryLayout& layout = p.nlp->layout();
  const int joints = p.model.size() - 1;
  const std::vector<double> moment_bounds = bounds_from(joints, 2.0, 0.5);
  const std::vector<double> force_bounds = bounds_from(joints, 30.0, 7.0);
  JointBoundBlock block(p.model, layout, moment_bounds, force_bounds);
  NlpEvaluations& at = p.nlp->evaluations();
  at.load(p.x.data());
  std::vector<double> g(block.rows());
  block.values(at, g.data());

  // The nodes written out: the block's fractions of every span of the current knots (its end
  // spans' finer ones on the first and the last), then the end.
  const Trajectory<double> trajectory = trajectory_from(layout, p.nlp->reference(), p.x.data());
  const std::vector<double>& knots = trajectory.knots;
  std::vector<double> times;
  const int last_span = layout.control_count() - 1;
  for (int span = 3; span <= last_span; ++span)
    for (const double xi : JointBoundBlock::node_fractions(span == 3 || span == last_span))
      times.push_back(knots[span] + xi * (knots[span + 1] - knots[span]));
  times.push_back(knots[layout.control_count()]);
  ASSERT_EQ(static_cast<int>(times.size()) * 2 * joints, block.rows());
  const std::vector<SampleRecord> samples = evaluate_trajectory(p.model, trajectory, times);
  int row = 0;
  for (const SampleRecord& sample : samples)
    for (int j = 1; j <= joints; ++j) {
      const double moment = sample.joint_wrench[j].tail<3>().norm();
      const double force = sample.joint_wrench[j].head<3>().norm();
      const double moment_row = g[row], force_row = g[row + 1];
      row += 2;
      EXPECT_NEAR(moment_row, moment * moment / (moment_bounds[j - 1] * moment_bounds[j - 1]),
                  1e-9 * (1.0 + moment_row))
          << "moment of joint " << j << " at t = " << sample.time;
      EXPECT_NEAR(force_row, force * force / (force_bounds[j - 1] * force_bounds[j - 1]),
                  1e-9 * (1.0 + force_row))
          << "force of joint " << j << " at t = " << sample.time;
    }
}

TEST(JointBoundBlock, RefusesABoundPerJointMissingOrNotPositive) {
  test::RandomPoint p(Formulation::kRelaxed);
  const int joints = p.model.size() - 1;
  EXPECT_THROW(JointBoundBlock(p.model, p.nlp->layout(), bounds_from(joints - 1, 2.0, 0.5)),
               std::invalid_argument);
  EXPECT_THROW(JointBoundBlock(p.model, p.nlp->layout(), bounds_from(joints, 0.0, 0.5)),
               std::invalid_argument);
  EXPECT_THROW(JointBoundBlock(p.model, p.nlp->layout(), bounds_from(joints, 2.0, 0.5),
                               bounds_from(2, 30.0, 7.0)),
               std::invalid_argument);
}

}  // namespace
}  // namespace saltus
