#include "integrators/bidir/light_tracer.h"

#include "render/radiance_render.h"
#include "render/wavefront/chunks.h"

namespace gdr {
namespace {

// Subpaths in flight per chunk, as the path tracer's: bounds the queues' memory.
constexpr size_t kMaxPathsInFlight = size_t(1) << 19;
constexpr const char* kProgram = "bidir/lt.cl";

// Mitsuba's max_depth: a light subpath's first vertex connected to the camera is 2 segments.
bool light_subpaths_allowed(int max_depth) { return max_depth < 0 || max_depth >= 2; }

}  // namespace

const std::vector<std::string> kLtParams = {"aux"};

LtSettings lt_settings(const IntegratorParams& params) {
  LtSettings s;
  s.aux = params.flag("aux", false);
  return s;
}

LightTracer::LightTracer(const RenderInputs& in, const LtSettings& lt)
    : in_(in),
      lt_(lt),
      kernels_(in.context, in.scene),
      camera_(kernels_.make(kProgram, "lt_camera")),
      direct_(kernels_.make(kProgram, "lt_direct")),
      emit_(kernels_.make(kProgram, "lt_emit")),
      shade_(kernels_.make(kProgram, "lt_shade")),
      shadow_(kernels_.make(kProgram, "lt_shadow")),
      capacity_(chunk_capacity(kMaxPathsInFlight, in.scene.camera.width, in.scene.camera.height)),
      queues_(in.context, capacity_, true),
      paths_(in.context, capacity_),
      shadow_rays_(in.context, capacity_, kRayQueueFlags),
      counters_(in.context, GDR_COUNTER_NAMES(LT_COUNTERS)),
      film_(in.context, in.scene.camera.width, in.scene.camera.height, {"radiance"}),
      splats_(in.context, kernels_, kProgram, capacity_) {
  if (lt_.aux) aux_.emplace(in.context, kernels_, kProgram, film_.pixels());
}

void LightTracer::trace_direct(const GdrPtParams& p) {
  camera_.args(in_.device_scene.camera(), p, queues_.rays[0]).run(p.pixel_count);
  intersect(in_.embree, queues_.rays[0], p.pixel_count, true, "camera");
  if (aux_) aux_->add(p, queues_.rays[0], p.pixel_count, in_.device_scene);
  counters_.reset();
  direct_.args(p, p.pixel_count, queues_.rays[0], film_["radiance"], counters_.buffer(), in_.device_scene)
      .run(p.pixel_count);
  counters_.read();
}

void LightTracer::trace_light_subpaths(const GdrPtParams& p) {
  counters_.reset();
  emit_.args(p, queues_.rays[0], queues_.slots[0], paths_, counters_.buffer(), in_.device_scene).run(p.pixel_count);
  cl_uint active = counters_.read()[LT_COUNTER_NEXT_RAYS];
  for (int cur = 0; active > 0; cur = 1 - cur) {
    intersect(in_.embree, queues_.rays[cur], active, false, "light");
    counters_.reset();
    shade_
        .args(p, active, in_.device_scene.camera(), queues_.rays[cur], queues_.slots[cur], queues_.rays[1 - cur],
              queues_.slots[1 - cur], shadow_rays_, splats_.slots(), paths_, counters_.buffer(), in_.device_scene)
        .run(active);
    counters_.read();
    cl_uint shadows = counters_[LT_COUNTER_SHADOW_RAYS];
    if (shadows > 0) {
      occlude(in_.embree, shadow_rays_, shadows, "camera_connection");
      shadow_.args(shadows, shadow_rays_, splats_.slots()).run(shadows);
      splats_.gather(in_.device_scene.camera(), film_.height(), p.pixel_count, film_["radiance"]);
    }
    active = counters_[LT_COUNTER_NEXT_RAYS];
  }
}

void LightTracer::trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) {
  GdrPtParams p = in_.device_scene.path_params(settings, sample, first, count);
  if (settings.max_depth != 0) trace_direct(p);
  if (light_subpaths_allowed(settings.max_depth) && p.light_count > 0) trace_light_subpaths(p);
  counters_.report(in_.context.stats());
}

RenderResult LightTracer::render(const RenderSettings& settings) {
  return render_radiance(in_.context, settings, film_, aux_, capacity_, [&](uint32_t sample, uint32_t first, uint32_t count) {
    trace_chunk(settings, sample, first, count);
  });
}

}  // namespace gdr
