// The optimiser's derivatives against central finite differences at random points, for every
// kind of variable (root translation controls, joint tangent coordinates, keyframe times), both
// formulations, with and without knot refinement.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>

#include "saltus/formats/motion_file.h"
#include "saltus/math/quaternion.h"
#include "saltus/motion/interpolate.h"
#include "saltus/optim/motion_nlp.h"
#include "saltus/optim/solve_policy.h"
#include "support/term_checks.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

struct NlpAtRandomPoint {
  BodyModel model = test::bundled_model();
  Motion motion;
  std::unique_ptr<MotionNlp> nlp;
  std::vector<double> x;

  NlpAtRandomPoint(Formulation formulation, int knots_per_interval, unsigned seed) {
    motion = test::tuck_motion(model);
    MotionNlpOptions options;
    options.formulation = formulation;
    options.knots_per_interval = knots_per_interval;
    options.samples = 23;
    InterpolationOptions interpolation;
    interpolation.knots_per_interval = knots_per_interval;
    const Trajectory<double> initial = interpolate_keyframes(motion, model, interpolation);
    nlp = std::make_unique<MotionNlp>(motion, model, initial, options);
    x.resize(nlp->variable_count());
    nlp->initial_point(x.data());
    // A random point away from the start, every kind of variable moved.
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const TrajectoryLayout& layout = nlp->layout();
    for (int v = 0; v < layout.control_variable_count(); ++v)
      x[v] += (v % layout.curve_block() < 3 ? 0.02 : 0.08) * u(rng);
    for (int i = 1; i + 1 < layout.keyframe_count; ++i)
      x[layout.time_variable(i)] += 0.03 * u(rng);
  }
};

/// Relative agreement of an analytic derivative with a central difference.
void expect_close(double analytic, double numeric, double scale, const std::string& what) {
  EXPECT_NEAR(analytic, numeric, 2e-5 * scale + 1e-6 * std::abs(numeric)) << what;
}

class NlpDerivatives : public ::testing::TestWithParam<std::tuple<Formulation, int>> {};

TEST_P(NlpDerivatives, GradientMatchesFiniteDifferences) {
  NlpAtRandomPoint s(std::get<0>(GetParam()), std::get<1>(GetParam()), 7);
  MotionNlp& nlp = *s.nlp;
  std::vector<double> gradient(nlp.variable_count());
  nlp.gradient(s.x.data(), gradient.data());
  const double scale =
      Eigen::Map<Eigen::VectorXd>(gradient.data(), gradient.size()).cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  const double h = 1e-6;
  int checked = 0;
  for (int v = 0; v < nlp.variable_count();
       v += (v < nlp.layout().control_variable_count() ? 5 : 1)) {
    std::vector<double> xp = s.x, xm = s.x;
    xp[v] += h;
    xm[v] -= h;
    const double numeric = (nlp.objective(xp.data()) - nlp.objective(xm.data())) / (2 * h);
    expect_close(gradient[v], numeric, scale, "variable " + std::to_string(v));
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

TEST_P(NlpDerivatives, ConstraintJacobianMatchesFiniteDifferences) {
  NlpAtRandomPoint s(std::get<0>(GetParam()), std::get<1>(GetParam()), 11);
  MotionNlp& nlp = *s.nlp;
  const int n = nlp.variable_count(), m = nlp.constraint_count();
  const int nnz = nlp.jacobian_nonzeros();
  std::vector<int> rows(nnz), cols(nnz);
  std::vector<double> values(nnz);
  nlp.jacobian_structure(rows.data(), cols.data());
  nlp.jacobian_values(s.x.data(), values.data());
  Eigen::MatrixXd analytic = Eigen::MatrixXd::Zero(m, n);
  for (int e = 0; e < nnz; ++e)
    analytic(rows[e], cols[e]) += values[e];

  const double h = 1e-6;
  std::vector<double> gp(m), gm(m);
  for (int v = 0; v < n; v += (v < nlp.layout().control_variable_count() ? 3 : 1)) {
    std::vector<double> xp = s.x, xm = s.x;
    xp[v] += h;
    xm[v] -= h;
    nlp.constraints(xp.data(), gp.data());
    nlp.constraints(xm.data(), gm.data());
    for (int r = 0; r < m; ++r) {
      const double numeric = (gp[r] - gm[r]) / (2 * h);
      // Also proves the sparsity: a derivative outside the declared structure shows up here.
      const double scale = std::max(1.0, analytic.row(r).cwiseAbs().maxCoeff());
      expect_close(analytic(r, v), numeric, scale,
                   "row " + std::to_string(r) + " variable " + std::to_string(v));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Formulations, NlpDerivatives,
                         ::testing::Combine(::testing::Values(Formulation::kRelaxed,
                                                              Formulation::kStrict),
                                            ::testing::Values(1, 2)));

/// The relaxed objective's Hessian (multipliers zero: no constraint curvature) as a dense
/// matrix, and the gradient, at x.
void dense_model(MotionNlp& nlp, const std::vector<double>& x, Eigen::MatrixXd& hessian,
                 Eigen::VectorXd& gradient) {
  const int n = nlp.variable_count();
  const int nnz = nlp.hessian_nonzeros();
  std::vector<int> rows(nnz), cols(nnz);
  std::vector<double> values(nnz);
  nlp.hessian_structure(rows.data(), cols.data());
  const std::vector<double> lambda(nlp.constraint_count(), 0.0);
  nlp.hessian_values(x.data(), 1.0, lambda.data(), values.data());
  hessian = Eigen::MatrixXd::Zero(n, n);
  for (int e = 0; e < nnz; ++e) {
    EXPECT_LE(cols[e], rows[e]);  // lower triangle
    hessian(rows[e], cols[e]) += values[e];
    if (rows[e] != cols[e]) hessian(cols[e], rows[e]) += values[e];
  }
  gradient.resize(n);
  nlp.gradient(x.data(), gradient.data());
}

TEST(NlpHessian, IsTheDampedGaussNewtonOfItsTermsResiduals) {
  // vᵀHv = Σ_terms 2‖J_r v‖² + μ·J(x)·‖v‖² (the root wrench's damping), with J_r v by central
  // differences of each term's residuals along v: an independent path to the Hessian's assembly
  // and band indexing.
  NlpAtRandomPoint s(Formulation::kRelaxed, 2, 3);
  MotionNlp& nlp = *s.nlp;
  const int n = nlp.variable_count();
  Eigen::MatrixXd h;
  Eigen::VectorXd unused_gradient;
  dense_model(nlp, s.x, h, unused_gradient);
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i)
    v[i] = g(rng);
  const double eps = 1e-6;
  std::vector<double> xp = s.x, xm = s.x;
  for (int i = 0; i < n; ++i)
    xp[i] += eps * v[i], xm[i] -= eps * v[i];
  double expected =
      nlp.options().damping.initial * nlp.force_objective(s.x.data()) * v.squaredNorm();
  NlpEvaluations& at = nlp.evaluations();
  for (ObjectiveTerm* term : nlp.objective_terms()) {
    at.load(xp.data());
    const std::vector<double> rp = term->residuals(at);
    at.load(xm.data());
    const std::vector<double> rm = term->residuals(at);
    for (std::size_t r = 0; r < rp.size(); ++r)
      expected += 2.0 * std::pow((rp[r] - rm[r]) / (2 * eps), 2);
  }
  const double actual = v.dot(h * v);
  EXPECT_NEAR(actual, expected, 1e-5 * expected);
}

TEST(NlpDamping, FollowsHowWellTheDampedModelPredictedTheStep) {
  // The NLP judges each step by the damped quadratic model it handed Ipopt at the step's origin.
  // Here the same judgement is made independently (dense model, objective values) along the
  // damped Gauss-Newton direction d for step lengths α, and the factor must move the way
  // AdaptiveDamping's rule says for that ratio. The model's decrease along d is
  // α(1 − α/2)·gᵀB⁻¹g: beyond α = 2 it predicts an increase, which counts as poorly predicted
  // (ratio −1); α = 2 itself (a predicted change of 0) is left out.
  const DampingRule rule;
  int shrunk = 0, kept = 0, grown = 0;
  for (const double alpha : {1.0 / 256, 1.0 / 64, 1.0 / 16, 0.25, 0.5, 1.0, 1.5, 1.9, 3.0, 6.0}) {
    NlpAtRandomPoint s(Formulation::kRelaxed, 1, 3);
    MotionNlp& nlp = *s.nlp;
    ASSERT_EQ(nlp.damping_factor(), rule.initial);
    Eigen::MatrixXd hessian;
    Eigen::VectorXd gradient;
    dense_model(nlp, s.x, hessian, gradient);
    const Eigen::VectorXd step = -alpha * hessian.ldlt().solve(gradient);
    std::vector<double> next = s.x;
    for (int v = 0; v < nlp.variable_count(); ++v)
      next[v] += step[v];
    const double predicted = -(gradient.dot(step) + 0.5 * step.dot(hessian * step));
    const double before = nlp.objective(s.x.data());
    const double ratio = predicted > 0 ? (before - nlp.objective(next.data())) / predicted : -1.0;
    StepTaken taken;
    taken.iteration = 1;
    taken.line_search_trials = 1;
    nlp.step_taken(taken);
    Eigen::MatrixXd unused_hessian;
    Eigen::VectorXd unused_gradient;
    dense_model(nlp, next, unused_hessian, unused_gradient);
    SCOPED_TRACE("alpha " + std::to_string(alpha) + ", ratio " + std::to_string(ratio));
    if (ratio > rule.good_ratio + 0.01) {
      EXPECT_DOUBLE_EQ(nlp.damping_factor(), rule.initial / rule.shrink);
      ++shrunk;
    } else if (ratio < rule.poor_ratio - 0.01) {
      EXPECT_DOUBLE_EQ(nlp.damping_factor(), rule.initial * rule.grow);
      ++grown;
    } else if (ratio > rule.poor_ratio + 0.01 && ratio < rule.good_ratio - 0.01) {
      EXPECT_DOUBLE_EQ(nlp.damping_factor(), rule.initial);
      ++kept;
    }
  }
  // Short steps are predicted well, long ones badly: both verdicts must have been exercised.
  EXPECT_GT(shrunk, 0);
  EXPECT_GT(grown, 0);

  // A step the line search had to cut grows the factor even when predicted well; a new run
  // (iteration 0) starts again from the initial factor.
  NlpAtRandomPoint s(Formulation::kRelaxed, 1, 3);
  MotionNlp& nlp = *s.nlp;
  Eigen::MatrixXd hessian;
  Eigen::VectorXd gradient;
  dense_model(nlp, s.x, hessian, gradient);
  std::vector<double> next = s.x;
  const Eigen::VectorXd step = -1e-3 * hessian.ldlt().solve(gradient);
  for (int v = 0; v < nlp.variable_count(); ++v)
    next[v] += step[v];
  StepTaken cut;
  cut.iteration = 1;
  cut.line_search_trials = 3;
  nlp.step_taken(cut);
  dense_model(nlp, next, hessian, gradient);
  EXPECT_DOUBLE_EQ(nlp.damping_factor(), rule.initial * rule.grow);
  nlp.step_taken(StepTaken{});
  EXPECT_DOUBLE_EQ(nlp.damping_factor(), rule.initial);
}

TEST(NlpKeyframeRows, AreInUnitsOfTheirTolerance) {
  // Rotation rows are ‖Q − Q̄‖²/ε2², recomputed here from the trajectory the variables describe;
  // the rows' upper bound sits kKeyframeBoundMargin inside 1. A non-default ε2 proves the scale.
  NlpAtRandomPoint s(Formulation::kRelaxed, 1, 13);
  s.motion.tolerances.quaternion = 0.08;
  s.motion.tolerances.translation_m = 0.4;
  InterpolationOptions interpolation;
  MotionNlpOptions options;
  options.samples = 23;
  MotionNlp nlp(s.motion, s.model, interpolate_keyframes(s.motion, s.model, interpolation),
                options);
  const int m = nlp.constraint_count();
  std::vector<double> g(m), x_lower(nlp.variable_count()), x_upper(nlp.variable_count()),
      g_lower(m), g_upper(m);
  nlp.constraints(s.x.data(), g.data());
  nlp.bounds(x_lower.data(), x_upper.data(), g_lower.data(), g_upper.data());

  const TrajectoryLayout& layout = nlp.layout();
  const Trajectory<double> trajectory = trajectory_from(layout, nlp.reference(), s.x.data());
  const std::vector<double> times = keyframe_times_from(layout, nlp.reference(), s.x.data());
  const int first_rotation_row = 3 * layout.keyframe_count;
  int checked = 0;
  for (int i = 0; i < layout.keyframe_count; ++i) {
    for (int k = 0; k < layout.segment_count; ++k) {
      const Eigen::Quaterniond q = trajectory.rotations[k].evaluate(times[i]).q;
      const Eigen::Quaterniond& target = s.motion.keyframes[i].rotations[k];
      const double distance =
          std::min((q.coeffs() - target.coeffs()).norm(), (q.coeffs() + target.coeffs()).norm());
      const int row = first_rotation_row + i * layout.segment_count + k;
      EXPECT_NEAR(g[row], distance * distance / (0.08 * 0.08), 1e-9) << "keyframe " << i;
      EXPECT_DOUBLE_EQ(g_upper[row], 1.0 - kKeyframeBoundMargin);
      checked += distance > 0.01;
    }
  }
  EXPECT_GT(checked, 10);  // the random point is away from the keyframes
  for (int row = 0; row < first_rotation_row; ++row) {
    EXPECT_DOUBLE_EQ(g_upper[row], 1.0 - kKeyframeBoundMargin);
    EXPECT_DOUBLE_EQ(g_lower[row], -(1.0 - kKeyframeBoundMargin));
  }
}

/// Two NLPs on the tuck motion at K = 1, with and without the joint-turn penalty, and a point
/// where one light segment's control j is turned 0.3 rad past the limit of the pair (j − 1, j)
/// (and, where the reference hardly turns, of the pair (j, j + 1) too).
struct SpunLimb {
  BodyModel model = test::bundled_model();
  Motion motion = test::tuck_motion(model);
  std::unique_ptr<MotionNlp> with_penalty, without;
  std::vector<double> start, x;
  int segment = 0, control = 3;

  SpunLimb() {
    const Trajectory<double> initial = interpolate_keyframes(motion, model, {});
    MotionNlpOptions options;
    options.samples = 23;
    with_penalty = std::make_unique<MotionNlp>(motion, model, initial, options);
    options.joint_turn_weight = 0.0;
    without = std::make_unique<MotionNlp>(motion, model, initial, options);
    segment = with_penalty->layout().segment_count - 1;  // the last segment: a foot
    start.resize(with_penalty->variable_count());
    with_penalty->initial_point(start.data());
    x = start;
    // Turn control j further about the axis it already turns about (from control j − 1): the
    // tangent δ adds 2|δ| to the turn.
    const auto& c = with_penalty->reference().joint_control[segment];
    const Eigen::Quaterniond d = c[control - 1].conjugate() * c[control];
    const Eigen::Vector3d axis =
        d.vec().norm() > 1e-6 ? Eigen::Vector3d(d.vec().normalized()) : Eigen::Vector3d::UnitX();
    const double turn = 2.0 * std::acos(std::clamp(d.w(), -1.0, 1.0));
    const double push = 0.5 * (std::max(M_PI, turn) + 0.3 - turn);
    for (int i = 0; i < 3; ++i)
      x[with_penalty->layout().control_variable(segment + 1, control, i)] = push * axis[i];
  }

  /// The turn from control j − 1 to j of `segment` at point y, by acos (independent of the
  /// library's atan2 form).
  double turn(const std::vector<double>& y, int k, int j) const {
    const TrajectoryLayout& layout = with_penalty->layout();
    const auto& c = with_penalty->reference().joint_control[k];
    auto control_at = [&](int i) {
      const Eigen::Vector3d delta(y[layout.control_variable(k + 1, i, 0)],
                                  y[layout.control_variable(k + 1, i, 1)],
                                  y[layout.control_variable(k + 1, i, 2)]);
      return Eigen::Quaterniond(c[i] * quat_exp(delta));
    };
    const Eigen::Quaterniond d = control_at(j - 1).conjugate() * control_at(j);
    return 2.0 * std::acos(std::clamp(d.w(), -1.0, 1.0));
  }

  /// ρ·Σ (θ − max(π, θ̄))₊² over every non-root pair, from turn().
  double expected_penalty(const std::vector<double>& y) const {
    const double rho = with_penalty->options().joint_turn_weight;
    double sum = 0.0;
    for (int k = 1; k < with_penalty->layout().segment_count; ++k)
      for (int j = 1; j < with_penalty->layout().control_count(); ++j) {
        const double excess = turn(y, k, j) - std::max(M_PI, turn(start, k, j));
        if (excess > 0) sum += rho * excess * excess;
      }
    return sum;
  }
};

TEST(NlpJointTurn, PenalisesOnlyTurnsPastTheLimitOrTheInterpolationsOwnTurn) {
  SpunLimb s;
  // The start is never penalised, whatever its own turns.
  EXPECT_EQ(s.with_penalty->objective(s.start.data()), s.without->objective(s.start.data()));
  const double expected = s.expected_penalty(s.x);
  EXPECT_GE(expected, 1000.0 * 0.3 * 0.3 - 1e-6);  // at least the pushed pair, 0.3 rad past
  EXPECT_NEAR(s.with_penalty->objective(s.x.data()) - s.without->objective(s.x.data()), expected,
              1e-9 * expected);
}

TEST(NlpJointTurn, GradientAndGaussNewtonHessianMatchFiniteDifferencesOfTheTurn) {
  SpunLimb s;
  MotionNlp& nlp = *s.with_penalty;
  const TrajectoryLayout& layout = nlp.layout();
  std::vector<double> gradient(nlp.variable_count());
  nlp.gradient(s.x.data(), gradient.data());
  const double scale =
      Eigen::Map<Eigen::VectorXd>(gradient.data(), gradient.size()).cwiseAbs().maxCoeff();
  // The three controls of the pairs (j − 1, j) and (j, j + 1).
  std::vector<int> variables;
  for (int j = s.control - 1; j <= s.control + 1; ++j)
    for (int i = 0; i < 3; ++i)
      variables.push_back(layout.control_variable(s.segment + 1, j, i));
  const double h = 1e-6;
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(nlp.variable_count(), nlp.variable_count());
  for (int v : variables) {
    std::vector<double> xp = s.x, xm = s.x;
    xp[v] += h;
    xm[v] -= h;
    const double numeric = (nlp.objective(xp.data()) - nlp.objective(xm.data())) / (2 * h);
    expect_close(gradient[v], numeric, scale, "variable " + std::to_string(v));
  }
  // The Hessians differ by 2ρ·∇θ∇θᵀ for each pair past its limit (∇θ by central differences).
  for (int pair = s.control; pair <= s.control + 1; ++pair) {
    if (s.turn(s.x, s.segment, pair) <= std::max(M_PI, s.turn(s.start, s.segment, pair))) continue;
    Eigen::VectorXd turn_gradient = Eigen::VectorXd::Zero(nlp.variable_count());
    for (int v : variables) {
      std::vector<double> xp = s.x, xm = s.x;
      xp[v] += h;
      xm[v] -= h;
      turn_gradient[v] = (s.turn(xp, s.segment, pair) - s.turn(xm, s.segment, pair)) / (2 * h);
    }
    expected += 2.0 * nlp.options().joint_turn_weight * turn_gradient * turn_gradient.transpose();
  }
  Eigen::MatrixXd h_with, h_without;
  Eigen::VectorXd unused;
  dense_model(nlp, s.x, h_with, unused);
  dense_model(*s.without, s.x, h_without, unused);
  ASSERT_GT(expected.norm(), 100.0);
  EXPECT_LE((h_with - h_without - expected).norm(), 1e-5 * expected.norm());
}

TEST(NlpThreads, GiveBitForBitTheValuesOfOneThread) {
  NlpAtRandomPoint s(Formulation::kRelaxed, 2, 17);
  InterpolationOptions interpolation;
  interpolation.knots_per_interval = 2;
  const Trajectory<double> initial = interpolate_keyframes(s.motion, s.model, interpolation);
  std::vector<std::vector<double>> gradients;
  std::vector<double> objectives;
  for (int threads : {1, 3}) {
    MotionNlpOptions options;
    options.knots_per_interval = 2;
    options.samples = 90;
    options.threads = threads;
    MotionNlp nlp(s.motion, s.model, initial, options);
    objectives.push_back(nlp.objective(s.x.data()));
    gradients.emplace_back(nlp.variable_count());
    nlp.gradient(s.x.data(), gradients.back().data());
  }
  EXPECT_EQ(objectives[0], objectives[1]);
  EXPECT_EQ(gradients[0], gradients[1]);
}

TEST(Solver, StoppedEarlyReturnsTheBetterOfItsLastAndItsBestFeasibleIterate) {
  // Stopped by the iteration limit, the solver hands back its last iterate unless an earlier one
  // that met the constraints (as the progress reports show) had a lower objective.
  const MotionFile m1 = load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                         "/motions/M1-straight-back-somersault.motion.json");
  const Trajectory<double> initial = interpolate_keyframes(m1.motion, m1.model, {});
  MotionNlp nlp(m1.motion, m1.model, initial, MotionNlpOptions{});
  for (int limit : {3, 10, 18}) {
    SolverOptions options;
    options.max_iterations = limit;
    double best_feasible = std::numeric_limits<double>::infinity(), last = 0.0;
    const SolveReport report = solve_nlp(nlp, options, [&](const ProgressInfo& p) {
      if (p.constraint_violation <= options.acceptable_constraint_violation)
        best_feasible = std::min(best_feasible, p.objective);
      last = p.objective;
    });
    ASSERT_FALSE(report.solved) << "M1 is expected to need more than " << limit << " iterations";
    EXPECT_DOUBLE_EQ(report.objective, std::min(last, best_feasible)) << limit;
    EXPECT_NEAR(nlp.objective(report.x.data()), report.objective, 1e-9 * report.objective);
  }
}

}  // namespace
}  // namespace saltus

namespace saltus {
namespace {

TEST(IpoptDerivativeChecker, FindsNoErrorInGradientOrJacobian) {
  // Ipopt's own checker compares our gradient and constraint Jacobian, through the adapter's
  // index mapping, with its one-sided differences at the starting point of the bundled M1
  // (timing and knot refinement on).
  const MotionFile m1 = load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                         "/motions/M1-straight-back-somersault.motion.json");
  InterpolationOptions interpolation;
  interpolation.knots_per_interval = 2;
  const Trajectory<double> initial = interpolate_keyframes(m1.motion, m1.model, interpolation);
  // The strict formulation's constraint Jacobian holds every root-wrench derivative the relaxed
  // objective is built from. The relaxed gradient itself cannot be judged by one-sided
  // differences: J's curvature reaches ~3e6 (the first translation control drives the take-off
  // acceleration), so truncation alone exceeds any useful tolerance; central differences above.
  for (Formulation formulation : {Formulation::kStrict}) {
    MotionNlpOptions nlp_options;
    nlp_options.formulation = formulation;
    nlp_options.knots_per_interval = 2;
    nlp_options.samples = 40;  // off the knots: a sample on a knot has a one-sided kink in its time
    MotionNlp nlp(m1.motion, m1.model, initial, nlp_options);
    const std::string report = ::testing::TempDir() + "/saltus-derivative-check-" +
                               std::to_string(static_cast<int>(formulation)) + ".txt";
    SolverOptions options;
    options.max_iterations = 0;
    options.derivative_test_file = report;
    solve_nlp(nlp, options);
    std::ifstream in(report);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("Starting derivative checker"), std::string::npos) << text.substr(0, 500);
    EXPECT_NE(text.find("No errors detected by derivative checker"), std::string::npos)
        << text.substr(0, 4000);
  }
}

TEST(MotionNlp, AssemblesEachFormulationFromItsTermsAndBlocks) {
  auto names = [](const auto& parts) {
    std::vector<std::string> out;
    for (const auto* part : parts)
      out.push_back(part->name());
    return out;
  };
  test::RandomPoint relaxed(Formulation::kRelaxed), strict(Formulation::kStrict);
  EXPECT_EQ(names(relaxed.nlp->objective_terms()),
            (std::vector<std::string>{"root wrench", "keyframe distance", "proximity",
                                      "joint acceleration", "joint loads", "joint turn"}));
  // The joint-acceleration and joint-load terms are the relaxed model's (its strict objective is
  // the keyframes).
  EXPECT_EQ(names(strict.nlp->objective_terms()),
            (std::vector<std::string>{"keyframe distance", "proximity", "joint turn"}));
  EXPECT_EQ(names(relaxed.nlp->constraint_blocks()),
            (std::vector<std::string>{"keyframe translation", "keyframe rotation", "time order"}));
  EXPECT_EQ(names(strict.nlp->constraint_blocks()),
            (std::vector<std::string>{"keyframe translation", "keyframe rotation", "time order",
                                      "force bounds"}));
  // The NLP's objective is the sum of its terms' values.
  for (test::RandomPoint* p : {&relaxed, &strict}) {
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
