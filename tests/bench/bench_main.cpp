// Benchmark entry point: configures the runtimes like gdrender does, then runs Google Benchmark.
#include <benchmark/benchmark.h>

#include "device/runtime_env.h"

int main(int argc, char** argv) {
  gdr::configure_runtime(0);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
