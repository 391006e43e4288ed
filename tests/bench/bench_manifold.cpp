// The manifold walks' Newton solver (render/manifold_walks) on chains of 1, 2 and 4 specular
// vertices (a mirror, a glass slab, a glass sphere, two glass slabs), in float and in double:
// 1024 walks per solve, from starts scattered up to 0.3 around a base chain's start (fixed seed).
// Reports walks per second (both walks of each: the forward one and the walk back), the success
// rate and the mean Newton iterations per walk.
#include <benchmark/benchmark.h>

#include <random>

#include "support/devices.h"
#include "support/manifold_chains.h"

namespace gdr {
namespace {

using namespace test;

struct Chain {
  const char* name;
  ChainScene (*setup)();
  V3 origin, end;
  std::vector<V3> guess;  // near the base chain's vertices; the base chain is solved from it
  int flags;
};

const std::vector<Chain> kChains = {
    {"mirror (1)", mirror_setup, {-1.5, 1, 0}, {2.5, 2, 0}, {{0.1, 0, 0}}, MANIFOLD_VERTEX_DELTA},
    {"glass slab (2)", slab_setup, {-1.5, 0, 0}, {1.5, 2, 0}, {{-1.2, 0.5, 0}, {1.2, 1.5, 0}},
     MANIFOLD_VERTEX_DELTA | MANIFOLD_VERTEX_TRANSMIT},
    {"glass sphere (2)", sphere_setup, {0, -3, 0}, {0.1, 3, 0.1}, sphere_points({0, -3, 0}, {0.1, 3, 0.1}),
     MANIFOLD_VERTEX_DELTA | MANIFOLD_VERTEX_TRANSMIT},
    {"two glass slabs (4)", double_slab_setup, {-1.5, 0, 0}, {1.5, 3, 0},
     {{-1.3, 0.5, 0}, {-1.0, 1, 0}, {0.8, 1.5, 0}, {1.1, 2, 0}}, MANIFOLD_VERTEX_DELTA | MANIFOLD_VERTEX_TRANSMIT},
};

// range(0): the chain; range(1): 1 for double.
void BM_ManifoldWalks(benchmark::State& state) {
  const Chain& c = kChains[state.range(0)];
  ChainScene s = c.setup();
  ManifoldSettings settings;
  settings.precision = state.range(1) ? "double" : "float";
  if (settings.precision == "double" && !default_context().device().fp64) {
    state.SkipWithError("the device has no cl_khr_fp64");
    return;
  }
  // The base chain: solved from the guess, with the walk back not held to the guess.
  ManifoldSettings loose = settings;
  loose.reverse_factor = 1e9f;
  Solver seed(s, loose);
  std::vector<GdrManifoldPoint> guess;
  for (const V3& p : c.guess) guess.push_back(locate(s.scene, s.specular_shape, {p[0], p[1], p[2]}));
  GdrManifoldResult base = seed.solve({make_walk(s, c.origin, c.origin, c.end, guess, c.flags)})[0];
  if (base.status != 0) {
    state.SkipWithError("the base chain could not be solved");
    return;
  }
  std::vector<GdrManifoldPoint> chain(base.v, base.v + c.guess.size());

  constexpr int kWalks = 1024;
  Solver solver(s, settings, nullptr, kWalks);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  std::vector<GdrManifoldWalk> walks;
  for (int i = 0; i < kWalks; ++i) {
    V3 start{c.origin[0] + u(rng), c.origin[1], c.origin[2] + u(rng)};
    walks.push_back(make_walk(s, start, c.origin, c.end, chain, c.flags));
  }
  double solved = 0, iterations = 0, runs = 0;
  for (auto _ : state) {
    std::vector<GdrManifoldResult> r = solver.solve(walks);
    for (const GdrManifoldResult& x : r) {
      solved += x.status == 0;
      iterations += x.iterations;
    }
    runs += 1;
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * kWalks);
  state.counters["success"] = solved / (runs * kWalks);
  state.counters["iterations"] = iterations / (runs * kWalks);
  state.SetLabel(std::string(c.name) + ", " + settings.precision + " on " + default_context().device().name);
}
BENCHMARK(BM_ManifoldWalks)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(0.3);

}  // namespace
}  // namespace gdr
