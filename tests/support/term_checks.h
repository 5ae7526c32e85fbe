#pragma once
// Checks shared by the tests of the optimiser's objective terms and constraint blocks
// (tests/unit/optim/terms/, one test file per term or block): each against central finite
// differences through its own interface. A term's value is the sum of its squared residuals, its
// gradient the derivative of its value, its curvature 2·JᵀJ with J the residuals' derivative; a
// block's Jacobian is the derivative of its rows and zero off its declared sparsity. The point is
// random, with every kind of variable (root translation controls, joint tangents, keyframe times)
// moved.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "saltus/motion/interpolate.h"
#include "saltus/optim/motion_nlp.h"
#include "saltus/optim/terms/constraint_block.h"
#include "saltus/optim/terms/objective_term.h"
#include "support/test_motions.h"

namespace saltus::test {

struct RandomPoint {
  BodyModel model = bundled_model();
  Motion motion = tuck_motion(model);
  std::unique_ptr<MotionNlp> nlp;
  std::vector<double> start, x;

  explicit RandomPoint(Formulation formulation, unsigned seed = 11, int knots_per_interval = 2,
                       double root_moment_weight = 1.0) {
    MotionNlpOptions options;
    options.root_moment_weight = root_moment_weight;
    options.formulation = formulation;
    options.knots_per_interval = knots_per_interval;
    options.samples = 23;
    options.joint_effort = 0.1;  // every relaxed term present
    options.joint_load_weight = 0.01;
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

inline std::vector<double> moved(std::vector<double> x, int variable, double step) {
  x[variable] += step;
  return x;
}

inline std::vector<double> along(std::vector<double> x, const Eigen::VectorXd& v, double step) {
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] += step * v[static_cast<Eigen::Index>(i)];
  return x;
}

/// value = Σ r², gradient = d value, curvature = 2·JᵀJ (+ the damping `extra`·‖v‖² along v).
inline void check_term(RandomPoint& p, ObjectiveTerm& term, const std::vector<double>& x,
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
  const double actual = band.quadratic_form(values, v.data());
  const std::vector<double> rp = residuals_at(along(x, v, h)), rm = residuals_at(along(x, v, -h));
  double expected = damping * value * v.squaredNorm();
  for (std::size_t r = 0; r < rp.size(); ++r)
    expected += 2.0 * std::pow((rp[r] - rm[r]) / (2 * h), 2);
  EXPECT_NEAR(actual, expected, 1e-5 * expected) << term.name() << ": Gauss-Newton curvature";
}

/// Jacobian entries against differences of the rows; rows do not move off their sparsity.
inline void check_block(RandomPoint& p, ConstraintBlock& block, const std::vector<double>& x) {
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

}  // namespace saltus::test
