// Every objective term and constraint block of the optimiser (src/saltus/optim/terms/) against
// central finite differences, each through its own interface: a term's value is the sum of its
// squared residuals, its gradient the derivative of its value, its curvature 2·JᵀJ with J the
// residuals' derivative; a block's Jacobian is the derivative of its rows and zero off its
// declared sparsity. One test per term and block, at a random point where every kind of variable
// (root translation controls, joint tangents, keyframe times) has moved.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "saltus/motion/interpolate.h"
#include "saltus/optim/motion_nlp.h"
#include "saltus/optim/terms/constraint_block.h"
#include "saltus/optim/terms/objective_term.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

struct RandomPoint {
  BodyModel model = test::bundled_model();
  Motion motion = test::tuck_motion(model);
  std::unique_ptr<MotionNlp> nlp;
  std::vector<double> start, x;

  explicit RandomPoint(Formulation formulation, unsigned seed = 11, int knots_per_interval = 2) {
    MotionNlpOptions options;
    options.formulation = formulation;
    options.knots_per_interval = knots_per_interval;
    options.samples = 23;
    InterpolationOptions interpolation;
    interpolation.knots_per_interval = knots_per_interval;
    nlp = std::make_unique<MotionNlp>(motion, model,
                                      interpolate_keyframes(motion, model, interpolation), options);
    start.resize(nlp->variable_count());
    nlp->initial_point(start.data());
    x = start;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const TrajectoryLayout& layout = nlp->layout();
    for (int v = 0; v < layout.control_variable_count(); ++v)
      x[v] += (v % layout.curve_block() < 3 ? 0.02 : 0.08) * u(rng);
    for (int i = 1; i + 1 < layout.keyframe_count; ++i)
      x[layout.time_variable(i)] += 0.03 * u(rng);
  }

  ObjectiveTerm& term(const std::string& name) {
    for (ObjectiveTerm* t : nlp->objective_terms())
      if (t->name() == name) return *t;
    throw std::runtime_error("no term " + name);
  }
  ConstraintBlock& block(const std::string& name) {
    for (ConstraintBlock* b : nlp->constraint_blocks())
      if (b->name() == name) return *b;
    throw std::runtime_error("no block " + name);
  }
  /// Every variable of one control of the root translation, of two joints and every time.
  std::vector<int> probe_variables() const {
    const TrajectoryLayout& layout = nlp->layout();
    std::vector<int> v;
    for (int curve : {0, 1, layout.curve_count() - 1})
      for (int d = 0; d < 3; ++d)
        v.push_back(layout.control_variable(curve, 2, d));
    for (int i = 1; i + 1 < layout.keyframe_count; ++i)
      v.push_back(layout.time_variable(i));
    return v;
  }
};

std::vector<double> moved(std::vector<double> x, int variable, double step) {
  x[variable] += step;
  return x;
}

std::vector<double> along(std::vector<double> x, const Eigen::VectorXd& v, double step) {
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] += step * v[static_cast<Eigen::Index>(i)];
  return x;
}

/// value = Σ r², gradient = d value, curvature = 2·JᵀJ (+ the damping `extra`·‖v‖² along v).
void check_term(RandomPoint& p, ObjectiveTerm& term, const std::vector<double>& x,
                double damping = 0.0) {
  NlpEvaluations& at = p.nlp->evaluations();
  const int n = p.nlp->variable_count();
  auto value_at = [&](const std::vector<double>& y) {
    at.load(y.data());
    return term.value(at);
  };
  auto residuals_at = [&](const std::vector<double>& y) {
    at.load(y.data());
    return term.residuals(at);
  };

  const double value = value_at(x);
  double sum = 0.0;
  for (double r : residuals_at(x))
    sum += r * r;
  EXPECT_NEAR(value, sum, 1e-12 * std::max(1.0, sum)) << term.name() << ": value vs Σ r²";
  ASSERT_GT(value, 0.0) << term.name() << ": the test point must make the term work";

  std::vector<double> gradient(n, 0.0);
  at.load(x.data());
  term.add_gradient(at, gradient.data());
  const double scale = Eigen::Map<Eigen::VectorXd>(gradient.data(), n).cwiseAbs().maxCoeff();
  const double h = 1e-6;
  for (int v : p.probe_variables()) {
    const double numeric = (value_at(moved(x, v, h)) - value_at(moved(x, v, -h))) / (2 * h);
    EXPECT_NEAR(gradient[v], numeric, 2e-6 * scale + 1e-6 * std::abs(numeric))
        << term.name() << ": gradient, variable " << v;
  }

  // vᵀHv = 2‖J v‖² (+ damping·‖v‖²), J v by central differences of the residuals along v.
  const HessianBand band(p.nlp->layout());
  std::vector<double> values(band.nonzeros(), 0.0);
  at.load(x.data());
  term.add_curvature(at, 1.0, band, values.data());
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i)
    v[i] = g(rng);
  const std::vector<double> hv = band.product(values, v.data());
  const double actual = v.dot(Eigen::Map<const Eigen::VectorXd>(hv.data(), n));
  const std::vector<double> rp = residuals_at(along(x, v, h)), rm = residuals_at(along(x, v, -h));
  double expected = damping * value * v.squaredNorm();
  for (std::size_t r = 0; r < rp.size(); ++r)
    expected += 2.0 * std::pow((rp[r] - rm[r]) / (2 * h), 2);
  EXPECT_NEAR(actual, expected, 1e-5 * expected) << term.name() << ": Gauss-Newton curvature";
}

/// Jacobian entries against differences of the rows; rows do not move off their sparsity.
void check_block(RandomPoint& p, ConstraintBlock& block, const std::vector<double>& x) {
  NlpEvaluations& at = p.nlp->evaluations();
  const int rows = block.rows();
  auto rows_at = [&](const std::vector<double>& y) {
    at.load(y.data());
    std::vector<double> g(rows);
    block.values(at, g.data());
    return g;
  };
  const std::vector<std::vector<int>> sparsity = block.sparsity();
  ASSERT_EQ(static_cast<int>(sparsity.size()), rows) << block.name();
  std::vector<int> first(rows + 1, 0);
  for (int r = 0; r < rows; ++r)
    first[r + 1] = first[r] + static_cast<int>(sparsity[r].size());
  std::vector<double> jacobian(first[rows]);
  at.load(x.data());
  block.jacobian(at, jacobian.data());
  const double scale =
      Eigen::Map<Eigen::VectorXd>(jacobian.data(), jacobian.size()).cwiseAbs().maxCoeff();
  const double h = 1e-6;
  for (int v : p.probe_variables()) {
    const std::vector<double> gp = rows_at(moved(x, v, h)), gm = rows_at(moved(x, v, -h));
    for (int r = 0; r < rows; ++r) {
      const double numeric = (gp[r] - gm[r]) / (2 * h);
      const auto it = std::find(sparsity[r].begin(), sparsity[r].end(), v);
      const double analytic =
          it == sparsity[r].end() ? 0.0 : jacobian[first[r] + (it - sparsity[r].begin())];
      EXPECT_NEAR(analytic, numeric, 2e-6 * scale + 1e-6 * std::abs(numeric))
          << block.name() << ": row " << r << ", variable " << v
          << (it == sparsity[r].end() ? " (outside its sparsity)" : "");
    }
  }
}

TEST(RootWrenchTerm, ValueGradientAndDampedGaussNewtonMatchFiniteDifferences) {
  RandomPoint p(Formulation::kRelaxed);
  check_term(p, p.term("root wrench"), p.x, p.nlp->damping_factor());
}

TEST(ProximityTerm, ValueGradientAndCurvatureMatchFiniteDifferences) {
  RandomPoint p(Formulation::kRelaxed);
  check_term(p, p.term("proximity"), p.x);
}

TEST(KeyframeDistanceTerm, ValueGradientAndGaussNewtonMatchFiniteDifferences) {
  RandomPoint p(Formulation::kStrict);
  check_term(p, p.term("keyframe distance"), p.x);
}

TEST(JointTurnTerm, ValueGradientAndGaussNewtonMatchFiniteDifferencesPastTheLimit) {
  RandomPoint p(Formulation::kRelaxed);
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
  check_term(p, p.term("joint turn"), x);
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
    const double numeric = (value_at(moved(x, v, h)) - value_at(moved(x, v, -h))) / (2 * h);
    EXPECT_NEAR(gradient[v], numeric, 1e-6 * std::max(1.0, std::abs(numeric)));
  }
}

TEST(KeyframeTranslationBlock, JacobianMatchesFiniteDifferencesAndItsSparsity) {
  RandomPoint p(Formulation::kRelaxed);
  check_block(p, p.block("keyframe translation"), p.x);
}

TEST(KeyframeRotationBlock, JacobianMatchesFiniteDifferencesAndItsSparsity) {
  RandomPoint p(Formulation::kRelaxed);
  check_block(p, p.block("keyframe rotation"), p.x);
}

TEST(KeyframeRotationBlock, CurvatureIsGaussNewtonWhereTheKeyframesAreMet) {
  // At the interpolation the keyframe rotations are met to rounding, so there ∇²g equals its
  // Gauss–Newton part: compare λᵀ∇²g along v with differences of the rows' Jacobian.
  RandomPoint p(Formulation::kRelaxed);
  ConstraintBlock& block = p.block("keyframe rotation");
  NlpEvaluations& at = p.nlp->evaluations();
  const int n = p.nlp->variable_count(), rows = block.rows();
  std::vector<double> multipliers(rows);
  for (int r = 0; r < rows; ++r)
    multipliers[r] = 0.5 + 0.01 * r;
  const HessianBand band(p.nlp->layout());
  std::vector<double> values(band.nonzeros(), 0.0);
  at.load(p.start.data());
  block.add_curvature(at, multipliers.data(), band, values.data());
  std::mt19937 rng(9);
  std::normal_distribution<double> g;
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i)
    v[i] = g(rng);
  const std::vector<double> hv = band.product(values, v.data());
  // d/dε of λᵀ J(x + εv) v, J v by differences of the rows along v.
  auto weighted_rows = [&](const std::vector<double>& y) {
    at.load(y.data());
    std::vector<double> r(rows);
    block.values(at, r.data());
    double sum = 0.0;
    for (int i = 0; i < rows; ++i)
      sum += multipliers[i] * r[i];
    return sum;
  };
  const double h = 1e-4;
  const double second = (weighted_rows(along(p.start, v, h)) - 2.0 * weighted_rows(p.start) +
                         weighted_rows(along(p.start, v, -h))) /
                        (h * h);
  const double actual = v.dot(Eigen::Map<const Eigen::VectorXd>(hv.data(), n));
  EXPECT_NEAR(actual, second, 1e-3 * std::abs(second));
  EXPECT_GT(actual, 0.0);
}

TEST(TimeOrderBlock, JacobianMatchesFiniteDifferencesAndItsSparsity) {
  RandomPoint p(Formulation::kRelaxed);
  check_block(p, p.block("time order"), p.x);
}

TEST(ForceBoundBlock, JacobianMatchesFiniteDifferencesAndItsSparsity) {
  RandomPoint p(Formulation::kStrict);
  check_block(p, p.block("force bounds"), p.x);
}

TEST(MotionNlp, AssemblesEachFormulationFromItsTermsAndBlocks) {
  auto names = [](const auto& parts) {
    std::vector<std::string> out;
    for (const auto* part : parts)
      out.push_back(part->name());
    return out;
  };
  RandomPoint relaxed(Formulation::kRelaxed), strict(Formulation::kStrict);
  EXPECT_EQ(names(relaxed.nlp->objective_terms()),
            (std::vector<std::string>{"root wrench", "proximity", "joint turn"}));
  EXPECT_EQ(names(strict.nlp->objective_terms()),
            (std::vector<std::string>{"keyframe distance", "proximity", "joint turn"}));
  EXPECT_EQ(names(relaxed.nlp->constraint_blocks()),
            (std::vector<std::string>{"keyframe translation", "keyframe rotation", "time order"}));
  EXPECT_EQ(names(strict.nlp->constraint_blocks()),
            (std::vector<std::string>{"keyframe translation", "keyframe rotation", "time order",
                                      "force bounds"}));
  // The NLP's objective is the sum of its terms' values.
  for (RandomPoint* p : {&relaxed, &strict}) {
    double sum = 0.0;
    for (ObjectiveTerm* term : p->nlp->objective_terms()) {
      p->nlp->evaluations().load(p->x.data());
      sum += term->value(p->nlp->evaluations());
    }
    EXPECT_NEAR(p->nlp->objective(p->x.data()), sum, 1e-12 * sum);
  }
}

}  // namespace
}  // namespace saltus
