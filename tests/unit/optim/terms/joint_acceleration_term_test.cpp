// The joint-acceleration term (optim/terms/joint_acceleration_term.h): against central finite
// differences through the term interface (support/term_checks.h); zero for a deviation the
// spline moves with no acceleration (the same offset on every control, or one growing linearly
// along the Greville abscissae); and the inertia a joint moves, against the parallel-axis sum
// written out for a foot and the nesting of a leg.

#include "saltus/optim/terms/joint_acceleration_term.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "saltus/math/bspline_basis.h"
#include "support/term_checks.h"

namespace saltus {
namespace {

TEST(JointAccelerationTerm, ValueGradientAndCurvatureMatchFiniteDifferences) {
  test::RandomPoint p(Formulation::kRelaxed);
  test::check_term(p, p.term("joint acceleration"), p.x);
}

TEST(JointAccelerationTerm, DeviationsWithoutAccelerationCostNothing) {
  test::RandomPoint p(Formulation::kRelaxed);
  const TrajectoryLayout& layout = p.nlp->layout();
  const std::vector<double> knots =
      trajectory_from(layout, p.nlp->reference(), p.start.data()).knots;
  JointAccelerationTerm term(layout, p.model, knots, 1.0);
  std::vector<double> x = p.start;
  for (int k = 1; k < layout.segment_count; ++k)
    for (int c = 0; c < layout.control_count(); ++c) {
      // Greville abscissa of control c: the mean of its three inner knots.
      const double greville = (knots[c + 1] + knots[c + 2] + knots[c + 3]) / 3.0;
      for (int d = 0; d < 3; ++d)
        x[layout.control_variable(1 + k, c, d)] = 0.2 * (d + 1) + 0.3 * k * greville;
    }
  // The root's curves are not joints: they may do anything.
  for (int c = 0; c < layout.control_count(); ++c)
    for (int v = 0; v < 6; ++v)
      x[c * layout.curve_block() + v] = 0.5 * c * c;
  NlpEvaluations& at = p.nlp->evaluations();
  at.load(x.data());
  EXPECT_NEAR(term.value(at), 0.0, 1e-18);
  // A bend is not free.
  x[layout.control_variable(5, 4, 1)] += 0.1;
  at.load(x.data());
  EXPECT_GT(term.value(at), 0.0);
}

TEST(JointAccelerationTerm, TheInertiaAJointMovesIsItsSubtreesAboutItsCentre) {
  const BodyModel model = test::bundled_model();
  const int foot = model.joint_index("ankle_r");
  const Segment& f = model.segments[foot];
  for (const Segment& s : model.segments)
    ASSERT_NE(s.parent, foot) << "the foot is a leaf";
  const Eigen::Matrix3d about_ankle =
      f.inertia +
      f.mass * (f.com.squaredNorm() * Eigen::Matrix3d::Identity() - f.com * f.com.transpose());
  EXPECT_NEAR(joint_subtree_inertia(model, foot),
              Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(about_ankle).eigenvalues().maxCoeff(),
              1e-12);
  const double hip = joint_subtree_inertia(model, model.joint_index("hip_r"));
  const double knee = joint_subtree_inertia(model, model.joint_index("knee_r"));
  EXPECT_GT(hip, knee);
  EXPECT_GT(knee, joint_subtree_inertia(model, foot));
  EXPECT_GT(hip, 0.5);  // a leg about the hip: over 1 kg·m² for 66 kg
}

}  // namespace
}  // namespace saltus
