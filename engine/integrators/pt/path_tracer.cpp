#include "integrators/pt/path_tracer.h"

#include "render/radiance_render.h"
#include "render/wavefront/chunks.h"

namespace gdr {
namespace {

// Paths in flight per chunk: bounds the queues' memory (about 300 bytes a path) while keeping
// Embree's batches and the kernels' launches large.
constexpr size_t kMaxPathsInFlight = size_t(1) << 19;
constexpr const char* kProgram = "pt/pt.cl";

}  // namespace

const std::vector<std::string> kPtParams = {"strategy", "aux"};

PtSettings pt_settings(const IntegratorParams& params) {
  PtSettings s;
  std::string strategy = params.choice("strategy", "mis", {"mis", "bsdf", "light"});
  s.strategy = strategy == "bsdf" ? PT_STRATEGY_BSDF : strategy == "light" ? PT_STRATEGY_LIGHT : PT_STRATEGY_MIS;
  s.aux = params.flag("aux", false);
  return s;
}

PathTracer::PathTracer(const RenderInputs& in, const PtSettings& pt)
    : in_(in),
      pt_(pt),
      kernels_(in.context, in.scene),
      generate_(kernels_.make(kProgram, "pt_generate")),
      route_(kernels_.make(kProgram, "pt_route")),
      shadow_(kernels_.make(kProgram, "path_shadow_add")),
      capacity_(chunk_capacity(kMaxPathsInFlight, in.scene.camera.width, in.scene.camera.height)),
      queues_(in.context, capacity_, true),
      paths_(in.context, capacity_),
      shadow_rays_(in.context, capacity_, kRayQueueFlags),
      shadow_values_(in.context, capacity_),
      counters_(in.context, GDR_COUNTER_NAMES(PT_COUNTERS)),
      film_(in.context, in.scene.camera.width, in.scene.camera.height, {"radiance"}),
      materials_(in.context, in.scene, kernels_, kProgram, "pt_shade", capacity_) {
  if (pt_.aux) aux_.emplace(in.context, kernels_, kProgram, film_.pixels());
}

GdrPtParams PathTracer::params(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) const {
  GdrPtParams p = in_.device_scene.path_params(settings, sample, first, count);
  p.strategy = pt_.strategy;
  return p;
}

void PathTracer::generate(const GdrPtParams& params) {
  generate_.args(in_.device_scene.camera(), params, queues_.rays[0], queues_.slots[0], paths_).run(params.pixel_count);
}

void PathTracer::intersect(int cur, cl_uint active, bool camera) {
  gdr::intersect(in_.embree, queues_.rays[cur], active, camera, camera ? "camera" : "bounce");
}

const std::vector<cl_uint>& PathTracer::shade(const GdrPtParams& params, int cur, cl_uint active) {
  counters_.reset();
  if (!materials_.direct()) {
    route_
        .args(params, active, queues_.rays[cur], queues_.slots[cur], materials_.keys(), paths_, film_["radiance"],
              counters_.buffer(), in_.device_scene)
        .run(active);
  }
  for (const MaterialQueues::Queue& q : materials_.route(active)) {
    q.kernel
        ->args(params, q.count, cl_int(materials_.direct()), *q.entries, queues_.rays[cur],
               queues_.slots[cur], queues_.rays[1 - cur], queues_.slots[1 - cur], shadow_rays_, shadow_values_,
               paths_, film_["radiance"], counters_.buffer(), in_.device_scene)
        .run(q.count);
  }
  return counters_.read();
}

void PathTracer::occlude(cl_uint shadows) { gdr::occlude(in_.embree, shadow_rays_, shadows, "shadow"); }

void PathTracer::add_shadows(cl_uint shadows) {
  shadow_.args(shadows, shadow_rays_, shadow_values_, film_["radiance"]).run(shadows);
}

void PathTracer::trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) {
  GdrPtParams p = params(settings, sample, first, count);
  generate(p);
  cl_uint active = count;
  int cur = 0;
  for (int depth = 0; active > 0; ++depth) {
    intersect(cur, active, depth == 0);
    if (depth == 0 && aux_) aux_->add(p, queues_.rays[cur], active, in_.device_scene);
    shade(p, cur, active);
    cl_uint shadows = counters_[PT_COUNTER_SHADOW_RAYS];
    if (shadows > 0) {
      occlude(shadows);
      add_shadows(shadows);
    }
    active = counters_[PT_COUNTER_NEXT_RAYS];
    cur = 1 - cur;
  }
  counters_.report(in_.context.stats());
}

RenderResult PathTracer::render(const RenderSettings& settings) {
  return render_radiance(in_.context, settings, film_, aux_, capacity_, [&](uint32_t sample, uint32_t first, uint32_t count) {
    trace_chunk(settings, sample, first, count);
  });
}

}  // namespace gdr
