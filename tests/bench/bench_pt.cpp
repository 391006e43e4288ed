// Path-tracer kernel families on the project's Cornell box (256x256, one path per pixel): the
// generate, shade and shadow kernels' throughput (paths or rays per second) and Embree's closest-
// hit and occlusion queries on the same queues, for comparison. The queues are those of the
// first two bounces of a real pass; each benchmark restores its inputs (untimed) before a launch.
// Generate and shade run one path a work item and eight (the lanes argument: pt_generate_lanes,
// pt_shade_lanes_diffuse, a CPU device's default).
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "accel/embree_scene.h"
#include "bench/cornell_label.h"
#include "integrators/pt/path_tracer.h"
#include "render/device_scene.h"
#include "scene/load_scene.h"
#include "support/devices.h"
#include "support/source_scene.h"

namespace gdr {
namespace {

// A PathTracer on its first pass, with snapshots of its queues at bounces 0 and 1, so each
// benchmark can restore its inputs (untimed) and time one stage exactly as renders run it.
struct PtBench {
  Scene scene;
  std::unique_ptr<EmbreeScene> embree;
  std::unique_ptr<DeviceScene> device_scene;
  std::unique_ptr<PathTracer> tracer;
  uint32_t pixels;
  GdrPtParams params{};

  // Snapshots of the queues and path states at bounce 0 and 1 (before intersection).
  std::vector<GdrRayHit> queue_rays[2], queue_hits[2];
  std::vector<cl_uint> queue_slots[2];
  std::vector<GdrPathState> queue_paths[2];
  std::vector<GdrRay> shadow_queue;  // shadow rays of bounce 0, before occlusion
  std::vector<GdrRay> shadow_occluded;
  cl_uint active[2] = {0, 0}, shadows = 0;

  PtBench(Context& ctx, int lanes)
      : scene(load(test::source_scene("cornell-box.xml"))),
        embree(std::make_unique<EmbreeScene>(scene, BuildQuality::High)),
        device_scene(std::make_unique<DeviceScene>(ctx, scene)),
        tracer(std::make_unique<PathTracer>(RenderInputs{ctx, scene, *embree, *device_scene}, one_batch(lanes))),
        pixels(uint32_t(scene.camera.width) * scene.camera.height) {
    RenderSettings settings;
    settings.seed = 1;
    settings.max_depth = scene.max_depth;
    params = tracer->params(settings, 0, 0, pixels);
    tracer->generate(params);
    active[0] = pixels;
    for (int depth = 0; depth < 2; ++depth) {
      queue_rays[depth] = snapshot(tracer->rays(depth), active[depth]);
      queue_slots[depth] = tracer->queue(depth).read();
      queue_paths[depth] = tracer->paths().read();
      tracer->intersect(depth, active[depth], depth == 0);
      queue_hits[depth] = snapshot(tracer->rays(depth), active[depth]);
      const std::vector<cl_uint>& c = tracer->shade(params, depth, active[depth]);
      if (depth == 0) {
        shadows = c[PT_COUNTER_SHADOW_RAYS];
        shadow_queue = snapshot(tracer->shadow_rays(), shadows);
        tracer->occlude(shadows);
        shadow_occluded = snapshot(tracer->shadow_rays(), shadows);
        active[1] = c[PT_COUNTER_NEXT_RAYS];
      }
    }
  }

  template <class T>
  static std::vector<T> snapshot(const Buffer<T>& b, size_t count) {
    std::vector<T> v = b.read();
    v.resize(count);
    return v;
  }

  // The stages run on the whole chunk: one batch.
  static PtSettings one_batch(int lanes) {
    PtSettings s;
    s.batches = 1;
    s.lanes = lanes;
    return s;
  }

  static Scene load(const std::string& path) {
    LoadOptions o;
    o.defines = {{"res", "256"}};
    return load_scene(path, o);
  }

  // Puts back the queue of `depth` as it was before (hits: after) intersection.
  void restore(int depth, bool with_hits) {
    const auto& r = with_hits ? queue_hits[depth] : queue_rays[depth];
    tracer->rays(depth).write(r.data(), r.size());
    tracer->queue(depth).write(queue_slots[depth].data(), active[depth]);
    tracer->paths().write(queue_paths[depth]);
  }
};

// The tracer with `lanes` paths a work item (1 or 8).
PtBench& pt_bench(int lanes = 8) {
  static std::unique_ptr<PtBench> b[2];
  std::unique_ptr<PtBench>& one = b[lanes == 8 ? 1 : 0];
  if (!one) one = std::make_unique<PtBench>(test::default_context(), lanes);
  return *one;
}

std::string lanes_label(int lanes) { return lanes == 8 ? ", eight a work item" : ", one a work item"; }

void BM_PtGenerate(benchmark::State& state) {
  const int lanes = int(state.range(0));
  PtBench& b = pt_bench(lanes);
  for (auto _ : state) b.tracer->generate(b.params);
  state.SetItemsProcessed(int64_t(state.iterations()) * b.pixels);
  bench::cornell_label(state, "camera paths" + lanes_label(lanes));
}
BENCHMARK(BM_PtGenerate)->Arg(1)->Arg(8)->Unit(benchmark::kMillisecond)->UseRealTime();

// Embree closest hit of the camera queue (coherent) and of the first bounce queue (incoherent).
void BM_PtEmbreeIntersect(benchmark::State& state) {
  PtBench& b = pt_bench();
  const int depth = int(state.range(0));
  for (auto _ : state) {
    state.PauseTiming();
    b.restore(depth, false);
    state.ResumeTiming();
    b.tracer->intersect(depth, b.active[depth], depth == 0);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * b.active[depth]);
  bench::cornell_label(state, depth == 0 ? "camera rays" : "bounce rays");
}
BENCHMARK(BM_PtEmbreeIntersect)->DenseRange(0, 1)->Unit(benchmark::kMillisecond)->UseRealTime();

// pt_shade on the intersected camera queue and first bounce queue (emission, NEE, BSDF sampling).
void BM_PtShade(benchmark::State& state) {
  const int depth = int(state.range(0)), lanes = int(state.range(1));
  PtBench& b = pt_bench(lanes);
  for (auto _ : state) {
    state.PauseTiming();
    b.restore(depth, true);
    state.ResumeTiming();
    b.tracer->shade(b.params, depth, b.active[depth]);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * b.active[depth]);
  bench::cornell_label(state, (depth == 0 ? "camera-hit paths" : "bounce-hit paths") + lanes_label(lanes));
}
BENCHMARK(BM_PtShade)->ArgsProduct({{0, 1}, {1, 8}})->Unit(benchmark::kMillisecond)->UseRealTime();

// Embree occlusion of the first shadow-ray queue.
void BM_PtEmbreeOccluded(benchmark::State& state) {
  PtBench& b = pt_bench();
  for (auto _ : state) {
    state.PauseTiming();
    b.tracer->shadow_rays().write(b.shadow_queue.data(), b.shadow_queue.size());
    state.ResumeTiming();
    b.tracer->occlude(b.shadows);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * b.shadows);
  bench::cornell_label(state, "shadow rays");
}
BENCHMARK(BM_PtEmbreeOccluded)->Unit(benchmark::kMillisecond)->UseRealTime();

// pt_shadow on the occlusion results of the first shadow-ray queue.
void BM_PtShadow(benchmark::State& state) {
  PtBench& b = pt_bench();
  b.tracer->shadow_rays().write(b.shadow_occluded.data(), b.shadow_occluded.size());
  for (auto _ : state) b.tracer->add_shadows(b.shadows);
  state.SetItemsProcessed(int64_t(state.iterations()) * b.shadows);
  bench::cornell_label(state, "shadow rays");
}
BENCHMARK(BM_PtShadow)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gdr
