// What-if flights (evaluation/what_if.h) on M7, the double front with 1½ twists: the
// preparation done once per motion (interpolation, take-off momentum, tuck, the unchanged flight)
// and one what-if flight, what the app's What if panel runs each time a slider moves (target:
// the answer within 100 ms of a change).

#include <benchmark/benchmark.h>

#include "saltus/evaluation/what_if.h"
#include "saltus/formats/motion_file.h"

namespace saltus {
namespace {

const MotionFile& m7() {
  static const MotionFile file =
      load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                       "/motions/M7-double-front-one-and-a-half-twists.motion.json");
  return file;
}

void BM_WhatIfPrepareM7(benchmark::State& bench) {
  const MotionFile& file = m7();
  for (auto _ : bench) {
    const WhatIf w(file.motion, file.model);
    benchmark::DoNotOptimize(w.unchanged_landing().somersaults);
  }
}
BENCHMARK(BM_WhatIfPrepareM7)->Unit(benchmark::kMillisecond);

void BM_WhatIfFlyM7(benchmark::State& bench) {
  const MotionFile& file = m7();
  const WhatIf w(file.motion, file.model);
  WhatIfChange change;
  change.open_later_s = 0.05;
  change.tuck_scale = 1.1;
  for (auto _ : bench) {
    const WhatIfResult r = w.fly(change);
    benchmark::DoNotOptimize(r.landing.somersaults);
  }
}
BENCHMARK(BM_WhatIfFlyM7)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace saltus
