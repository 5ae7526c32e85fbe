// One evaluation of the relaxed NLP at paper resolution (M1: 5 keyframes, K = 1, 201 samples):
// objective, gradient (all per-sample root-wrench Jacobians), constraint Jacobian and the
// Gauss-Newton Hessian, each at a fresh x as Ipopt would ask for them.

#include <benchmark/benchmark.h>

#include "saltus/formats/motion_file.h"
#include "saltus/motion/interpolate.h"
#include "saltus/optim/motion_nlp.h"
#include "saltus/optim/optimize.h"
#include "support/ground_truth.h"

namespace saltus {
namespace {

void BM_RelaxedNlpEvaluation(benchmark::State& bench) {
  const MotionFile file = load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                           "/motions/M1-straight-back-somersault.motion.json");
  MotionNlpOptions options;
  options.samples = static_cast<int>(bench.range(0));
  const Trajectory<double> initial = interpolate_keyframes(file.motion, file.model);
  MotionNlp nlp(file.motion, file.model, initial, options);
  std::vector<double> x(nlp.variable_count()), gradient(x.size()), g(nlp.constraint_count()),
      jacobian(nlp.jacobian_nonzeros()), hessian(nlp.hessian_nonzeros()),
      lambda(nlp.constraint_count(), 0.0);
  nlp.initial_point(x.data());
  for (auto _ : bench) {
    x[0] += 1e-9;  // a new point each time: no cached evaluation
    benchmark::DoNotOptimize(nlp.objective(x.data()));
    nlp.gradient(x.data(), gradient.data());
    nlp.constraints(x.data(), g.data());
    nlp.jacobian_values(x.data(), jacobian.data());
    nlp.hessian_values(x.data(), 1.0, lambda.data(), hessian.data());
  }
  bench.counters["variables"] = nlp.variable_count();
  bench.counters["samples"] = options.samples;
}
BENCHMARK(BM_RelaxedNlpEvaluation)->Arg(100)->Arg(200)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace saltus

namespace saltus {
namespace {

/// The optimiser's scaling (issue: samples 100/200/400/800, keyframes 5/9/13/25): keyframes
/// read off a free flight with M1's arm and body movements and M1's take-off angular momentum,
/// interior times disturbed by a quarter of the keyframe spacing; relaxed model, K = 1, timing
/// on. One full solve per run. Counters: Ipopt iterations, problem size, average root force
/// before and after (N), 1 if solved.
void BM_OptimizeScaling(benchmark::State& bench) {
  const int samples = static_cast<int>(bench.range(0));
  const int keyframes = static_cast<int>(bench.range(1));
  const MotionFile m1 = load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                         "/motions/M1-straight-back-somersault.motion.json");
  const double spacing = m1.motion.flight_time() / (keyframes - 1);
  const test::GroundTruth truth = test::make_ground_truth(
      m1.motion, *m1.motion.takeoff.angular_momentum, keyframes, 0.25 * spacing);
  OptimizeOptions options;
  options.nlp.samples = samples;
  OptimizationResult result;
  for (auto _ : bench)
    result = optimize_motion(truth.motion, truth.model, options);
  bench.counters["ipopt_iterations"] = result.solve.iterations;
  bench.counters["variables"] = result.variables;
  bench.counters["constraints"] = result.constraints;
  bench.counters["force_before_N"] = result.before.metrics.avg_root_force;
  bench.counters["force_after_N"] = result.after.metrics.avg_root_force;
  bench.counters["solved"] = result.solve.solved ? 1 : 0;
}
BENCHMARK(BM_OptimizeScaling)
    ->ArgNames({"samples", "keyframes"})
    ->Args({100, 13})
    ->Args({200, 13})
    ->Args({400, 13})
    ->Args({800, 13})
    ->Args({200, 5})
    ->Args({200, 9})
    ->Args({200, 25})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace saltus
