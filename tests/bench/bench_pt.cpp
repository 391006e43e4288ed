// Path-tracer kernel families on the project's Cornell box (256x256, one path per pixel): the
// generate, shade and shadow kernels' throughput (paths or rays per second) and Embree's closest-
// hit and occlusion queries on the same queues, for comparison. The queues are those of the
// first two bounces of a real pass; each benchmark restores its inputs (untimed) before a launch.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "accel/embree_scene.h"
#include "integrators/device_scene.h"
#include "integrators/pt/path_tracer.h"
#include "scene/load_scene.h"
#include "support/devices.h"

namespace gdr {
namespace {

// One pass of the path tracer's host loop, kept bounce by bounce: the same kernels, buffers and
// argument order as integrators/pt/path_tracer.cpp.
struct PtBench {
  Scene scene;
  std::unique_ptr<EmbreeScene> embree;
  std::unique_ptr<DeviceScene> device_scene;
  Kernel generate, shade, shadow;
  uint32_t pixels;
  GdrPtParams params{};
  Buffer<GdrRayHit> rays[2];
  Buffer<cl_uint> queue[2];
  Buffer<GdrPathState> paths;
  Buffer<GdrRay> shadow_rays;
  Buffer<Vec4> shadow_values;
  Buffer<cl_uint> counters;
  Buffer<Vec4> film;

  // Snapshots of the queues and path states at bounce 0 and 1 (before intersection).
  std::vector<GdrRayHit> queue_rays[2], queue_hits[2];
  std::vector<cl_uint> queue_slots[2];
  std::vector<GdrPathState> queue_paths[2];
  std::vector<GdrRay> shadow_queue;  // shadow rays of bounce 0, before occlusion
  std::vector<GdrRay> shadow_occluded;
  cl_uint active[2] = {0, 0}, shadows = 0;

  static Kernel make(Context& ctx, const Scene& s, const char* name) {
    return ctx.program("pt/pt.cl", scene_kernel_defines(s))->kernel(name);
  }

  explicit PtBench(Context& ctx)
      : scene(load(std::string(GDR_SOURCE_DIR) + "/scenes/cornell-box.xml")),
        embree(std::make_unique<EmbreeScene>(scene, BuildQuality::High)),
        device_scene(std::make_unique<DeviceScene>(ctx, scene)),
        generate(make(ctx, scene, "pt_generate")),
        shade(make(ctx, scene, "pt_shade")),
        shadow(make(ctx, scene, "pt_shadow")),
        pixels(uint32_t(scene.camera.width) * scene.camera.height),
        rays{Buffer<GdrRayHit>(ctx, pixels, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR),
             Buffer<GdrRayHit>(ctx, pixels, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR)},
        queue{Buffer<cl_uint>(ctx, pixels), Buffer<cl_uint>(ctx, pixels)},
        paths(ctx, pixels),
        shadow_rays(ctx, pixels, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR),
        shadow_values(ctx, pixels),
        counters(ctx, PT_COUNTER_COUNT),
        film(ctx, pixels) {
    RenderSettings settings;
    settings.seed = 1;
    settings.max_depth = scene.max_depth;
    params = device_scene->path_params(settings, 0, 0, pixels);
    film.fill(Vec4{});
    run_generate();
    active[0] = pixels;
    for (int depth = 0; depth < 2; ++depth) {
      queue_rays[depth] = rays[depth].read();
      queue_rays[depth].resize(active[depth]);
      queue_slots[depth] = queue[depth].read();
      queue_paths[depth] = paths.read();
      intersect(depth);
      queue_hits[depth] = rays[depth].read();
      queue_hits[depth].resize(active[depth]);
      std::vector<cl_uint> c = run_shade(depth);
      if (depth == 0) {
        shadows = c[PT_COUNTER_SHADOW_RAYS];
        shadow_queue = shadow_rays.read();
        shadow_queue.resize(shadows);
        {
          auto m = shadow_rays.map(shadows);
          embree->occluded(m.data(), shadows, "shadow");
        }
        shadow_occluded = shadow_rays.read();
        shadow_occluded.resize(shadows);
      }
      if (depth == 0) active[1] = c[PT_COUNTER_NEXT_RAYS];
    }
  }

  static Scene load(const std::string& path) {
    LoadOptions o;
    o.defines = {{"res", "256"}};
    return load_scene(path, o);
  }

  void run_generate() { generate.args(device_scene->camera(), params, rays[0], queue[0], paths).run(pixels); }

  void intersect(int depth) {
    auto m = rays[depth].map(active[depth]);
    embree->intersect(m.data(), active[depth], depth == 0, depth == 0 ? "camera" : "bounce");
  }

  std::vector<cl_uint> run_shade(int depth) {
    counters.fill(0u);
    shade.args(params, active[depth], rays[depth], queue[depth], rays[1 - depth], queue[1 - depth], shadow_rays,
               shadow_values, paths, film, counters);
    device_scene->set_args(shade, 11);
    shade.run(active[depth]);
    return counters.read();
  }

  // Puts back the queue of `depth` as it was before (hits: after) intersection.
  void restore(int depth, bool with_hits) {
    const auto& r = with_hits ? queue_hits[depth] : queue_rays[depth];
    rays[depth].write(r.data(), r.size());
    queue[depth].write(queue_slots[depth].data(), active[depth]);
    paths.write(queue_paths[depth]);
  }
};

PtBench& bench() {
  static std::unique_ptr<PtBench> b = std::make_unique<PtBench>(test::default_context());
  return *b;
}

void label(benchmark::State& state, const char* what) {
  state.SetLabel(std::string(what) + ", cornell-box 256x256 on " + test::default_context().device().name);
}

void BM_PtGenerate(benchmark::State& state) {
  PtBench& b = bench();
  for (auto _ : state) b.run_generate();
  state.SetItemsProcessed(int64_t(state.iterations()) * b.pixels);
  label(state, "camera paths");
}
BENCHMARK(BM_PtGenerate)->Unit(benchmark::kMillisecond)->UseRealTime();

// Embree closest hit of the camera queue (coherent) and of the first bounce queue (incoherent).
void BM_PtEmbreeIntersect(benchmark::State& state) {
  PtBench& b = bench();
  const int depth = int(state.range(0));
  for (auto _ : state) {
    state.PauseTiming();
    b.restore(depth, false);
    state.ResumeTiming();
    b.intersect(depth);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * b.active[depth]);
  label(state, depth == 0 ? "camera rays" : "bounce rays");
}
BENCHMARK(BM_PtEmbreeIntersect)->DenseRange(0, 1)->Unit(benchmark::kMillisecond)->UseRealTime();

// pt_shade on the intersected camera queue and first bounce queue (emission, NEE, BSDF sampling).
void BM_PtShade(benchmark::State& state) {
  PtBench& b = bench();
  const int depth = int(state.range(0));
  for (auto _ : state) {
    state.PauseTiming();
    b.restore(depth, true);
    b.counters.fill(0u);
    state.ResumeTiming();
    b.shade.args(b.params, b.active[depth], b.rays[depth], b.queue[depth], b.rays[1 - depth], b.queue[1 - depth],
                 b.shadow_rays, b.shadow_values, b.paths, b.film, b.counters);
    b.device_scene->set_args(b.shade, 11);
    b.shade.run(b.active[depth]);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * b.active[depth]);
  label(state, depth == 0 ? "camera-hit paths" : "bounce-hit paths");
}
BENCHMARK(BM_PtShade)->DenseRange(0, 1)->Unit(benchmark::kMillisecond)->UseRealTime();

// Embree occlusion of the first shadow-ray queue.
void BM_PtEmbreeOccluded(benchmark::State& state) {
  PtBench& b = bench();
  for (auto _ : state) {
    state.PauseTiming();
    b.shadow_rays.write(b.shadow_queue.data(), b.shadow_queue.size());
    state.ResumeTiming();
    auto m = b.shadow_rays.map(b.shadows);
    b.embree->occluded(m.data(), b.shadows, "shadow");
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * b.shadows);
  label(state, "shadow rays");
}
BENCHMARK(BM_PtEmbreeOccluded)->Unit(benchmark::kMillisecond)->UseRealTime();

// pt_shadow on the occlusion results of the first shadow-ray queue.
void BM_PtShadow(benchmark::State& state) {
  PtBench& b = bench();
  b.shadow_rays.write(b.shadow_occluded.data(), b.shadow_occluded.size());
  for (auto _ : state) b.shadow.args(b.shadows, b.shadow_rays, b.shadow_values, b.film).run(b.shadows);
  state.SetItemsProcessed(int64_t(state.iterations()) * b.shadows);
  label(state, "shadow rays");
}
BENCHMARK(BM_PtShadow)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gdr
