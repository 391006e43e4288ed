// The counter-based RNG kernel: random numbers per second on the default device.
#include <benchmark/benchmark.h>

#include "device/context.h"
#include "support/devices.h"

namespace gdr {
namespace {

void BM_RngFill(benchmark::State& state) {
  Context& ctx = test::default_context();
  Kernel k = ctx.program("util/rng_fill.cl")->kernel("rng_fill");
  const unsigned count = static_cast<unsigned>(state.range(0));
  Buffer<float> out(ctx, count);
  k.args(out, count, 1u, 0u, 8u);
  for (auto _ : state) k.run(count);
  state.SetItemsProcessed(int64_t(state.iterations()) * count);
  state.SetLabel(ctx.device().name);
}
BENCHMARK(BM_RngFill)->Arg(1 << 20)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gdr
