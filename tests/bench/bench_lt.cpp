// Light tracer throughput on the project's Cornell box (256x256, one light subpath per pixel):
// whole passes (light subpaths per second, camera connections per second as a counter), and
// the splat film's gather alone (slots per second) for the slot counts of a pass.
#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <string>

#include "accel/embree_scene.h"
#include "integrators/bidir/bidirectional.h"
#include "render/device_scene.h"
#include "render/splat_film.h"
#include "scene/load_scene.h"
#include "support/devices.h"

namespace gdr {
namespace {

struct LtBench {
  Scene scene;
  std::unique_ptr<EmbreeScene> embree;
  std::unique_ptr<DeviceScene> device_scene;
  std::unique_ptr<Bidirectional> tracer;
  uint32_t pixels;

  explicit LtBench(Context& ctx)
      : scene(load(std::string(GDR_SOURCE_DIR) + "/scenes/cornell-box.xml")),
        embree(std::make_unique<EmbreeScene>(scene, BuildQuality::High)),
        device_scene(std::make_unique<DeviceScene>(ctx, scene)),
        tracer(std::make_unique<Bidirectional>(RenderInputs{ctx, scene, *embree, *device_scene}, BidirSettings{})),
        pixels(uint32_t(scene.camera.width) * scene.camera.height) {}

  static Scene load(const std::string& path) {
    LoadOptions o;
    o.defines = {{"res", "256"}};
    return load_scene(path, o);
  }
};

LtBench& bench() {
  static std::unique_ptr<LtBench> b = std::make_unique<LtBench>(test::default_context());
  return *b;
}

void label(benchmark::State& state, const char* what) {
  state.SetLabel(std::string(what) + ", cornell-box 256x256 on " + test::default_context().device().name);
}

// One pass (the scene's max_depth): camera rays for the emission seen directly, then the light
// subpaths, their camera connections and the gathers.
void BM_LtPass(benchmark::State& state) {
  LtBench& b = bench();
  RenderSettings s;
  s.spp = 1;
  s.max_depth = b.scene.max_depth;
  uint32_t seed = 1;
  b.tracer->render(s);  // untimed: PoCL compiles each kernel at its first launch
  for (auto _ : state) {
    s.seed = seed++;
    b.tracer->render(s);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * b.pixels);
  label(state, "light subpaths");
}
BENCHMARK(BM_LtPass)->Unit(benchmark::kMillisecond)->UseRealTime();

// The gather of as many full slots as a pass has subpaths, at film positions uniform over the
// image, with the box filter (one pixel per slot) and the scene's gaussian (up to 5 x 5).
void BM_SplatGather(benchmark::State& state) {
  LtBench& b = bench();
  Context& ctx = test::default_context();
  GdrCamera cam = b.scene.camera;
  const bool gaussian = state.range(0) != 0;
  cam.filter = gaussian ? FILTER_GAUSSIAN : FILTER_BOX;
  cam.filter_radius = gaussian ? 2.0f : 0.5f;
  KernelFactory kernels(ctx, b.scene);
  SplatFilm splats(ctx, kernels, "bidir/lt.cl", b.pixels);
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
  label(state, gaussian ? "slots, gaussian filter" : "slots, box filter");
}
BENCHMARK(BM_SplatGather)->DenseRange(0, 1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gdr
