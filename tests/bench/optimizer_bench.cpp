// One evaluation of the relaxed NLP at paper resolution (M1: 5 keyframes, K = 1, 201 samples):
// objective, gradient (all per-sample root-wrench Jacobians), constraint Jacobian and the
// Gauss-Newton Hessian, each at a fresh x as Ipopt would ask for them.

#include <benchmark/benchmark.h>

#include "saltus/motion/interpolate.h"
#include "saltus/optim/motion_nlp.h"

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
