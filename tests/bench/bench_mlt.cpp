// The Markov-chain layer of the Metropolis integrators (integrators/mlt/markov_chains): steps of
// 2^16 chains (propose, the analytic target of kernels/tests/mlt_test.cl, accept) with the
// default mutation settings, for states of 2 dimensions (the target's) and of 112 (a
// bidirectional path of 8 segments: its camera and light subpaths' blocks). Reports chain steps
// per second and the acceptance rate of each mutation kind.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <string>

#include "integrators/mlt/markov_chains.h"
#include "support/devices.h"
#include "support/test_scenes.h"

namespace gdr {
namespace {

constexpr const char* kProgram = "tests/mlt_test.cl";

void BM_MltSteps(benchmark::State& state) {
  Context& ctx = test::default_context();
  Scene scene = test::furnace_scene(0.5f, 1.0f, 8);
  KernelFactory kernels(ctx, scene);
  const size_t chains = size_t(1) << 16, dims = size_t(state.range(0));
  MarkovChains mc(ctx, kernels, kProgram, chains, dims, MltSettings{});
  Kernel f = kernels.make(kProgram, "mlt_test_target");
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> start(chains * dims);
  for (float& x : start) x = u(rng);
  mc.current().write(start);
  f.args(cl_uint(chains), mc.current(), mc.f_current()).run(chains);
  uint32_t it = 0;
  auto step = [&] {
    mc.propose(5, it);
    f.args(cl_uint(chains), mc.proposed(), mc.f_proposed()).run(chains);
    mc.accept(5, it);
    ++it;
  };
  step();  // untimed: the first launches compile
  mc.counts();
  for (auto _ : state) step();
  ctx.finish();
  std::vector<cl_uint> n = mc.counts();
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(chains));
  state.counters["small_acceptance"] = double(n[MLT_COUNTER_SMALL_ACCEPTED]) / std::max(1u, n[MLT_COUNTER_SMALL_STEPS]);
  state.counters["large_acceptance"] = double(n[MLT_COUNTER_LARGE_ACCEPTED]) / std::max(1u, n[MLT_COUNTER_LARGE_STEPS]);
  state.SetLabel(std::to_string(dims) + " dimensions, chain steps on " + ctx.device().name);
}
BENCHMARK(BM_MltSteps)->Arg(2)->Arg(112)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gdr
