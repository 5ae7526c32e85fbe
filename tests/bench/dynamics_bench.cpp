// Inverse dynamics of the 13-segment model per time sample (target: <= 2 µs, Release, one
// core), and a whole `evaluate` pass (interpolation + inverse dynamics at 1000 samples).

#include <benchmark/benchmark.h>

#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/formats/motion_file.h"
#include "saltus/motion/interpolate.h"

namespace saltus {
namespace {

const MotionFile& m1() {
  static const MotionFile file = load_motion_file(
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/M1-straight-back-somersault.motion.json");
  return file;
}

void BM_InverseDynamicsPerSample(benchmark::State& bench) {
  const MotionFile& file = m1();
  const Trajectory<double> trajectory = interpolate_keyframes(file.motion, file.model);
  // Pre-sample states so that only inverse dynamics is timed.
  std::vector<BodyState<double>> states(256, BodyState<double>(file.model.size()));
  for (std::size_t k = 0; k < states.size(); ++k)
    trajectory.sample(file.motion.flight_time() * k / (states.size() - 1), states[k]);
  DynamicsData<double> data(file.model);
  std::size_t k = 0;
  for (auto _ : bench) {
    inverse_dynamics(file.model, data, states[k]);
    benchmark::DoNotOptimize(data.joint_wrench[0]);
    k = (k + 1) % states.size();
  }
  bench.SetItemsProcessed(bench.iterations());
}
BENCHMARK(BM_InverseDynamicsPerSample);

void BM_EvaluateMotion1000Samples(benchmark::State& bench) {
  const MotionFile& file = m1();
  EvaluateOptions options;
  options.samples = 1000;
  for (auto _ : bench) {
    const MotionEvaluation e = evaluate_motion(file.motion, file.model, options);
    benchmark::DoNotOptimize(e.metrics.objective);
  }
}
BENCHMARK(BM_EvaluateMotion1000Samples)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace saltus
