// The benchmarks' main: the process-wide setting that `saltus` and saltus-gui make in theirs, so
// that an optimisation is timed as the programs run it.

#include <benchmark/benchmark.h>

#include "saltus/optim/solver_memory.h"

int main(int argc, char** argv) {
  saltus::keep_solver_memory_in_heap();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
