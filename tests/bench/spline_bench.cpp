/// Spline benchmarks. Budget (docs/method.md, optimiser inner loop): all 13 joints' quaternion
/// splines with ω and α in <= 2 µs per time sample (double, Release).

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <random>
#include <vector>

#include "saltus/math/bspline_basis.h"
#include "saltus/math/quaternion_spline.h"

namespace saltus {
namespace {

constexpr int kJoints = 13;
constexpr double kFlightTime = 2.04;

/// Keyframes at `count` uniform times over the flight, each rotation a random turn of up to
/// 90° from the previous one (a joint, or the root somersaulting).
void random_keyframes(int count, std::mt19937& rng, std::vector<double>& times,
                      std::vector<Quat<double>>& targets) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  times.clear();
  targets.clear();
  Quat<double> q = Quat<double>::Identity();
  for (int i = 0; i < count; ++i) {
    times.push_back(kFlightTime * i / (count - 1));
    targets.push_back(q);
    const Eigen::Vector3d axis(uniform(rng), uniform(rng), uniform(rng));
    q = q * Quat<double>(Eigen::AngleAxisd(0.5 * M_PI * std::abs(uniform(rng)), axis.normalized()));
  }
}

std::vector<QuaternionSpline<double>> fitted_joint_splines() {
  std::mt19937 rng(2024);
  std::vector<QuaternionSpline<double>> splines;
  std::vector<double> times;
  std::vector<Quat<double>> targets;
  for (int j = 0; j < kJoints; ++j) {
    random_keyframes(5, rng, times, targets);
    const std::vector<double> knots = clamped_cubic_knots(refine_breakpoints(times, 1));
    splines.emplace_back(knots, fit_quaternion_spline(knots, times, targets));
  }
  return splines;
}

/// One iteration = one time sample: q, ω, α of all 13 joints (spans found by binary search).
void BM_EvaluateAllJointSplines(benchmark::State& state) {
  const std::vector<QuaternionSpline<double>> splines = fitted_joint_splines();
  double t = 0.0;
  const double dt = 0.0007319;  // not commensurate with the knots: every span gets visited
  for (auto _ : state) {
    for (const QuaternionSpline<double>& spline : splines) {
      QuaternionSample<double> sample = spline.evaluate(t);
      benchmark::DoNotOptimize(sample);
    }
    t += dt;
    if (t > kFlightTime) t -= kFlightTime;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["joints"] = kJoints;
}
BENCHMARK(BM_EvaluateAllJointSplines);

/// One fit of a 13-keyframe joint trajectory (knots at the keyframes).
void BM_FitQuaternionSpline(benchmark::State& state) {
  std::mt19937 rng(7);
  std::vector<double> times;
  std::vector<Quat<double>> targets;
  random_keyframes(13, rng, times, targets);
  const std::vector<double> knots = clamped_cubic_knots(refine_breakpoints(times, 1));
  for (auto _ : state) {
    std::vector<Quat<double>> control = fit_quaternion_spline(knots, times, targets);
    benchmark::DoNotOptimize(control);
  }
}
BENCHMARK(BM_FitQuaternionSpline)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace saltus
