#include "integrators/pt/path_tracer.h"

#include <algorithm>

#include "integrators/film.h"
#include "integrators/progressive_loop.h"
#include "util/log.h"

namespace gdr {
namespace {

// Paths in flight per chunk: bounds the queues' memory (about 300 bytes a path) while keeping
// Embree's batches and the kernels' launches large.
constexpr size_t kMaxPathsInFlight = size_t(1) << 19;

Kernel make_kernel(Context& ctx, const Scene& scene, const char* name) {
  return ctx.program("pt/pt.cl", scene_kernel_defines(scene))->kernel(name);
}

}  // namespace

PathTracer::PathTracer(Context& ctx, const Scene& scene, EmbreeScene& embree)
    : ctx_(ctx),
      scene_(scene),
      embree_(embree),
      device_scene_(ctx, scene),
      generate_(make_kernel(ctx, scene, "pt_generate")),
      shade_(make_kernel(ctx, scene, "pt_shade")),
      shadow_(make_kernel(ctx, scene, "pt_shadow")),
      capacity_(std::min(kMaxPathsInFlight, size_t(scene.camera.width) * scene.camera.height)),
      rays_{Buffer<GdrRayHit>(ctx, capacity_, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR),
            Buffer<GdrRayHit>(ctx, capacity_, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR)},
      queue_{Buffer<cl_uint>(ctx, capacity_), Buffer<cl_uint>(ctx, capacity_)},
      paths_(ctx, capacity_),
      shadow_rays_(ctx, capacity_, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR),
      shadow_values_(ctx, capacity_),
      counters_(ctx, PT_COUNTER_COUNT),
      film_(ctx, size_t(scene.camera.width) * scene.camera.height),
      aux_(make_kernel(ctx, scene, "path_aux")),
      aux_albedo_(ctx, film_.size()),
      aux_normal_(ctx, film_.size()),
      aux_depth_(ctx, film_.size()) {}

void PathTracer::generate(const GdrPtParams& params) {
  generate_.args(device_scene_.camera(), params, rays_[0], queue_[0], paths_).run(params.pixel_count);
}

void PathTracer::intersect(int cur, cl_uint active, bool camera) {
  auto rays = rays_[cur].map(active);
  embree_.intersect(rays.data(), active, camera, camera ? "camera" : "bounce");
}

std::vector<cl_uint> PathTracer::shade(const GdrPtParams& params, int cur, cl_uint active) {
  counters_.fill(0u);
  shade_.args(params, active, rays_[cur], queue_[cur], rays_[1 - cur], queue_[1 - cur], shadow_rays_, shadow_values_,
              paths_, film_, counters_);
  device_scene_.set_args(shade_, 11);
  shade_.run(active);
  return counters_.read();
}

void PathTracer::occlude(cl_uint shadows) {
  auto rays = shadow_rays_.map(shadows);
  embree_.occluded(rays.data(), shadows, "shadow");
}

void PathTracer::add_shadows(cl_uint shadows) {
  shadow_.args(shadows, shadow_rays_, shadow_values_, film_).run(shadows);
}

void PathTracer::trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) {
  Stats* stats = ctx_.stats();
  GdrPtParams p = params(settings, sample, first, count);
  generate(p);
  cl_uint active = count;
  int cur = 0;
  for (int depth = 0; active > 0; ++depth) {
    intersect(cur, active, depth == 0);
    if (depth == 0 && settings.aux) {
      aux_.args(p, active, rays_[cur], aux_albedo_, aux_normal_, aux_depth_);
      device_scene_.set_args(aux_, 6);
      aux_.run(active);
    }
    std::vector<cl_uint> counters = shade(p, cur, active);
    cl_uint shadows = counters[PT_COUNTER_SHADOW_RAYS];
    if (stats && counters[PT_COUNTER_NONFINITE]) stats->add_count("samples/nonfinite_rejected", counters[PT_COUNTER_NONFINITE]);
    if (shadows > 0) {
      occlude(shadows);
      add_shadows(shadows);
    }
    active = counters[PT_COUNTER_NEXT_RAYS];
    cur = 1 - cur;
  }
}

RenderResult PathTracer::render(const RenderSettings& settings) {
  Stats* stats = ctx_.stats();
  ScopedTimer timer(stats, "render/trace");
  const uint32_t pixels = uint32_t(scene_.camera.width) * scene_.camera.height;
  film_.fill(Vec4{});
  if (settings.aux) {
    aux_albedo_.fill(Vec4{});
    aux_normal_.fill(Vec4{});
    aux_depth_.fill(0.0f);
  }
  RenderResult result;
  result.samples = run_progressive(settings, [&](int sample) {
    for (uint32_t first = 0; first < pixels; first += uint32_t(capacity_)) {
      trace_chunk(settings, uint32_t(sample), first, std::min<uint32_t>(uint32_t(capacity_), pixels - first));
    }
  });
  result.seconds = timer.elapsed();
  float scale = result.samples > 0 ? 1.0f / result.samples : 0.0f;
  result.image = Image(scene_.camera.width, scene_.camera.height, {});
  result.image.add_rgb_layer("", film_rgb(film_, scale));
  if (settings.aux) {
    std::vector<float> depth = aux_depth_.read(), d(size_t(pixels) * 3);
    for (size_t p = 0; p < pixels; ++p) d[3 * p] = d[3 * p + 1] = d[3 * p + 2] = depth[p] * scale;
    result.image.add_rgb_layer("albedo", film_rgb(aux_albedo_, scale));
    result.image.add_rgb_layer("normal", film_rgb(aux_normal_, scale));
    result.image.add_rgb_layer("depth", d);
  }
  if (stats) {
    stats->add_count("samples/paths", uint64_t(pixels) * result.samples);
    stats->set("render/spp", result.samples);
  }
  return result;
}

}  // namespace gdr
