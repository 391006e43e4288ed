// The bidirectional integrator's throughput on the project's Cornell box (256x256, one light
// subpath per pixel): whole passes of each technique (light subpaths per second, with camera
// connections, vertex connections, merges and the hash grid's build as rates from the render's
// own counters), the splat film's gather alone (slots per second) for the slot counts of a pass,
// and the device primitives the grid is built with and queues are compacted with (scan,
// compaction, sort by key: items per second). The Metropolis integrator over the same kernels:
// mutations per second with their acceptance rates by kind.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>
#include <memory>
#include <random>
#include <string>

#include "accel/embree_scene.h"
#include "bench/cornell_label.h"
#include "device/devices.h"
#include "integrators/bidir/bidirectional.h"
#include "integrators/mlt/metropolis.h"
#include "render/device_scene.h"
#include "render/splat_film.h"
#include "render/wavefront/primitives.h"
#include "scene/load_scene.h"
#include "support/devices.h"
#include "support/source_scene.h"

namespace gdr {
namespace {

struct BidirBench {
  Stats stats;
  Context ctx{select_device(""), &stats};  // its own, so that the kernels' counters are read
  Scene scene;
  std::unique_ptr<EmbreeScene> embree;
  std::unique_ptr<DeviceScene> device_scene;
  uint32_t pixels;

  BidirBench()
      : scene(load(test::source_scene("cornell-box.xml"))),
        embree(std::make_unique<EmbreeScene>(scene, BuildQuality::High)),
        device_scene(std::make_unique<DeviceScene>(ctx, scene)),
        pixels(uint32_t(scene.camera.width) * scene.camera.height) {}

  static Scene load(const std::string& path) {
    LoadOptions o;
    o.defines = {{"res", "256"}};
    return load_scene(path, o);
  }
};

BidirBench& bidir_bench() {
  static std::unique_ptr<BidirBench> b = std::make_unique<BidirBench>();
  return *b;
}

// Renders `integrator` once per iteration (a new seed each) after `s`'s untimed first render (PoCL
// compiles each kernel at its first launch); returns how much each counter grew over the timed
// renders, and the seconds of `timer` over render/trace's.
struct TimedRenders {
  std::map<std::string, double> grew;
  double timer_share = 0;
};
TimedRenders timed_renders(benchmark::State& state, Integrator& integrator, RenderSettings s,
                           const std::vector<const char*>& counters, const char* timer = "") {
  BidirBench& b = bidir_bench();
  integrator.render(s);
  std::map<std::string, uint64_t> before;
  for (const char* c : counters) before[c] = b.stats.count(c);
  const double timer0 = b.stats.seconds(timer), trace0 = b.stats.seconds("render/trace");
  for (auto _ : state) {
    s.seed += 1;
    integrator.render(s);
  }
  TimedRenders out;
  for (const char* c : counters) out.grew[c] = double(b.stats.count(c) - before[c]);
  out.timer_share = (b.stats.seconds(timer) - timer0) / std::max(1e-9, b.stats.seconds("render/trace") - trace0);
  return out;
}

// One pass (the scene's max_depth) of technique range(0) (BIDIR_*): lt's camera rays and light
// subpaths; bdpt's, pm's and vcm's light subpaths, grid and camera subpaths.
void BM_BidirPass(benchmark::State& state) {
  BidirBench& b = bidir_bench();
  Bidirectional tracer(RenderInputs{b.ctx, b.scene, *b.embree, *b.device_scene}, bidir_settings(int(state.range(0)), IntegratorParams{}));
  RenderSettings s;
  s.spp = 1;
  s.max_depth = b.scene.max_depth;
  TimedRenders r = timed_renders(state, tracer, s,
                                 {"bidir/camera_connections", "bidir/connections", "bidir/merges", "bidir/light_vertices"},
                                 "render/grid_build");
  state.SetItemsProcessed(int64_t(state.iterations()) * b.pixels);
  auto rate = [&](const char* counter) { return benchmark::Counter(r.grew[counter], benchmark::Counter::kIsRate); };
  state.counters["camera_connections"] = rate("bidir/camera_connections");
  state.counters["connections"] = rate("bidir/connections");
  state.counters["merges"] = rate("bidir/merges");
  state.counters["grid_vertices"] = rate("bidir/light_vertices");
  state.counters["grid_build_share"] = r.timer_share;
  bench::cornell_label(state, std::string(bidir_technique_name(int(state.range(0)))) + ": light subpaths");
}
BENCHMARK(BM_BidirPass)->DenseRange(BIDIR_LT, BIDIR_VCM)->Unit(benchmark::kMillisecond)->UseRealTime();

// mlt's steps: four mutations a pixel a render, the bootstrap of 2^16 samples included; mutations
// per second and the acceptance of small and large steps.
void BM_MltMutations(benchmark::State& state) {
  BidirBench& b = bidir_bench();
  Metropolis mlt(RenderInputs{b.ctx, b.scene, *b.embree, *b.device_scene},
                 mlt_settings(IntegratorParams(std::map<std::string, std::string>{{"bootstrap", "65536"}})));
  RenderSettings s;
  s.spp = 4;
  s.max_depth = b.scene.max_depth;
  TimedRenders r = timed_renders(state, mlt, s,
                                 {"mlt/small_steps", "mlt/small_steps_accepted", "mlt/large_steps", "mlt/large_steps_accepted"});
  const double small = r.grew["mlt/small_steps"], large = r.grew["mlt/large_steps"];
  state.SetItemsProcessed(int64_t(small + large));
  state.counters["small_acceptance"] = r.grew["mlt/small_steps_accepted"] / std::max(1.0, small);
  state.counters["large_acceptance"] = r.grew["mlt/large_steps_accepted"] / std::max(1.0, large);
  bench::cornell_label(state, "mlt: mutations");
}
BENCHMARK(BM_MltMutations)->Unit(benchmark::kMillisecond)->UseRealTime();

// The device primitives on 2^20 items: exclusive scan, and the sort by key into 2^18 buckets
// (the hash grid's shape: a few vertices a bucket).
void BM_DeviceScan(benchmark::State& state) {
  Context& ctx = test::default_context();
  DevicePrimitives prim(ctx);
  const size_t n = size_t(1) << 20;
  Buffer<cl_uint> data(ctx, std::vector<cl_uint>(n, 1u));
  prim.exclusive_scan(data, n);  // untimed: the first launch compiles
  for (auto _ : state) prim.exclusive_scan(data, n);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(n));
  state.SetLabel("uint items on " + ctx.device().name);
}
BENCHMARK(BM_DeviceScan)->Unit(benchmark::kMillisecond)->UseRealTime();

// Compaction of 2^20 items, half of them flagged at random (the shape of a queue after a bounce).
void BM_DeviceCompact(benchmark::State& state) {
  Context& ctx = test::default_context();
  DevicePrimitives prim(ctx);
  const size_t n = size_t(1) << 20;
  std::mt19937 rng(1);
  std::vector<cl_uint> f(n), items(n);
  for (size_t i = 0; i < n; ++i) {
    f[i] = rng() & 1u;
    items[i] = cl_uint(i);
  }
  Buffer<cl_uint> flags(ctx, f), in(ctx, items), offsets(ctx, n), out(ctx, n);
  prim.compact(flags, in, n, offsets, out);  // untimed: the first launch compiles
  for (auto _ : state) prim.compact(flags, in, n, offsets, out);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(n));
  state.SetLabel("uint items, half kept, on " + ctx.device().name);
}
BENCHMARK(BM_DeviceCompact)->Unit(benchmark::kMillisecond)->UseRealTime();

// Selection by key of 2^20 items with three keys (a queue routed to three material queues): each
// key's items, in order, all three together.
void BM_DeviceSelectKeys(benchmark::State& state) {
  Context& ctx = test::default_context();
  DevicePrimitives prim(ctx);
  const size_t n = size_t(1) << 20;
  std::mt19937 rng(1);
  std::vector<cl_uint> k(n);
  for (cl_uint& v : k) v = rng() % 3u;
  Buffer<cl_uint> keys(ctx, k), key_buffer(ctx, std::vector<cl_uint>{0u, 1u, 2u}), offsets(ctx, 3 * n + 1), out(ctx, n);
  prim.select_keys(keys, n, key_buffer, offsets, out);  // untimed: the first launch compiles
  for (auto _ : state) prim.select_keys(keys, n, key_buffer, offsets, out);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(n));
  state.SetLabel("uint keys into three queues, on " + ctx.device().name);
}
BENCHMARK(BM_DeviceSelectKeys)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DeviceSortByKey(benchmark::State& state) {
  Context& ctx = test::default_context();
  DevicePrimitives prim(ctx);
  const size_t n = size_t(1) << 20;
  const cl_uint buckets = cl_uint(n / 4);
  std::mt19937 rng(1);
  std::vector<cl_uint> k(n);
  for (cl_uint& v : k) v = rng() % buckets;
  Buffer<cl_uint> keys(ctx, k), starts(ctx, size_t(buckets) + 1), sorted(ctx, n);
  prim.sort_by_key(keys, n, buckets, starts, sorted);
  for (auto _ : state) prim.sort_by_key(keys, n, buckets, starts, sorted);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(n));
  state.SetLabel("keys into 2^18 buckets on " + ctx.device().name);
}
BENCHMARK(BM_DeviceSortByKey)->Unit(benchmark::kMillisecond)->UseRealTime();

// The gather of as many full slots as a pass has subpaths, at film positions uniform over the
// image, with the box filter (one pixel per slot) and the scene's gaussian (up to 5 x 5).
void BM_SplatGather(benchmark::State& state) {
  BidirBench& b = bidir_bench();
  Context& ctx = test::default_context();
  GdrCamera cam = b.scene.camera;
  const bool gaussian = state.range(0) != 0;
  cam.filter = gaussian ? FILTER_GAUSSIAN : FILTER_BOX;
  cam.filter_radius = gaussian ? 2.0f : 0.5f;
  KernelFactory kernels(ctx, b.scene);
  SplatFilm splats(ctx, kernels, "bidir/bidir.cl", b.pixels);
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<GdrSplat> slots(b.pixels);
  for (GdrSplat& s : slots) {
    s.raster[0] = u(rng) * cam.width;
    s.raster[1] = u(rng) * cam.height;
    s.value[0] = s.value[1] = s.value[2] = 1.0f;
    s.valid = 1;
  }
  Buffer<GdrCamera> camera(ctx, std::vector<GdrCamera>{cam});
  Buffer<Vec4> film(ctx, b.pixels);
  film.fill(Vec4{});
  splats.slots().write(slots);
  splats.gather(camera, cam.height, b.pixels, film);  // untimed: the first launch compiles
  for (auto _ : state) {
    state.PauseTiming();
    splats.slots().write(slots);
    state.ResumeTiming();
    splats.gather(camera, cam.height, b.pixels, film);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * b.pixels);
  bench::cornell_label(state, gaussian ? "slots, gaussian filter" : "slots, box filter");
}
BENCHMARK(BM_SplatGather)->DenseRange(0, 1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gdr
