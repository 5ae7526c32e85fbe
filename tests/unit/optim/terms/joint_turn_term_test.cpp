// The soft limit on a joint's turn between consecutive control points, pushed past its limit
// (optim/terms/joint_turn_term.h) against central finite differences, through the term and block
// interfaces (support/term_checks.h).

#include "saltus/optim/terms/joint_turn_term.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/term_checks.h"

namespace saltus {
namespace {

TEST(JointTurnTerm, ValueGradientAndGaussNewtonMatchFiniteDifferencesPastTheLimit) {
  test::RandomPoint p(Formulation::kRelaxed);
  // Turn one foot control a further 1.2 rad about the axis it already turns about, past π.
  const TrajectoryLayout& layout = p.nlp->layout();
  const int segment = layout.segment_count - 1, control = 3;
  const auto& c = p.nlp->reference().joint_control[segment];
  const Eigen::Quaterniond d = c[control - 1].conjugate() * c[control];
  const Eigen::Vector3d axis =
      d.vec().norm() > 1e-6 ? Eigen::Vector3d(d.vec().normalized()) : Eigen::Vector3d::UnitX();
  const double turn = 2.0 * std::acos(std::clamp(d.w(), -1.0, 1.0));
  std::vector<double> x = p.x;
  for (int i = 0; i < 3; ++i)
    x[layout.control_variable(segment + 1, control, i)] =
        0.5 * (std::max(M_PI, turn) + 0.3 - turn) * axis[i];
  // The probes must include the pushed control, so that the penalty's derivative is checked.
  test::check_term(p, p.term("joint turn"), x);
  NlpEvaluations& at = p.nlp->evaluations();
  at.load(x.data());
  std::vector<double> gradient(p.nlp->variable_count(), 0.0);
  p.term("joint turn").add_gradient(at, gradient.data());
  const double h = 1e-6;
  for (int i = 0; i < 3; ++i) {
    const int v = layout.control_variable(segment + 1, control, i);
    auto value_at = [&](const std::vector<double>& y) {
      at.load(y.data());
      return p.term("joint turn").value(at);
    };
    const double numeric =
        (value_at(test::moved(x, v, h)) - value_at(test::moved(x, v, -h))) / (2 * h);
    EXPECT_NEAR(gradient[v], numeric, 1e-6 * std::max(1.0, std::abs(numeric)));
  }
}

}  // namespace
}  // namespace saltus
