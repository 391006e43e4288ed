#include "integrators/pt/path_tracer.h"

#include <algorithm>

#include "render/radiance_render.h"
#include "render/wavefront/batches.h"
#include "render/wavefront/chunks.h"
#include "util/error.h"

namespace gdr {
namespace {

// Paths in flight per chunk: bounds the queues' memory (about 300 bytes a path) while keeping
// Embree's batches and the kernels' launches large.
constexpr size_t kMaxPathsInFlight = size_t(1) << 19;
// Fewer paths than this a batch would leave launches and Embree's calls too small to pay.
constexpr size_t kMinBatchPaths = size_t(1) << 14;
constexpr const char* kProgram = "pt/pt.cl";

}  // namespace

const std::vector<std::string> kPtParams = {"strategy", "aux", "batches", "lanes"};

PtSettings pt_settings(const IntegratorParams& params) {
  PtSettings s;
  std::string strategy = params.choice("strategy", "mis", {"mis", "bsdf", "light"});
  s.strategy = strategy == "bsdf" ? PT_STRATEGY_BSDF : strategy == "light" ? PT_STRATEGY_LIGHT : PT_STRATEGY_MIS;
  s.aux = params.flag("aux", false);
  s.batches = params.choice("batches", "2", {"1", "2"}) == "1" ? 1 : 2;
  if (params.has("lanes")) s.lanes = params.choice("lanes", "8", {"1", "8"}) == "8" ? 8 : 1;
  return s;
}

PathTracer::Batch::Batch(const RenderInputs& in, const KernelFactory& kernels, size_t capacity, int command_queue,
                         const MaterialQueues::LaneKernels& lanes)
    : command_queue(command_queue),
      queues(in.context, capacity, true),
      paths(in.context, capacity),
      shadow_rays(in.context, capacity, ray_queue_flags(in.context)),
      shadow_values(in.context, capacity),
      counters(in.context, GDR_COUNTER_NAMES(PT_COUNTERS)),
      materials(in.context, in.scene, kernels, kProgram, "pt_shade", capacity, true, lanes) {}

PathTracer::PathTracer(const RenderInputs& in, const PtSettings& pt)
    : in_(in),
      pt_(pt),
      kernels_(in.context, in.scene),
      lanes_(pt.lanes.value_or(in.context.is_cpu() ? 8 : 1)),
      generate_(kernels_.make(kProgram, lanes_ == 8 ? "pt_generate_lanes" : "pt_generate")),
      route_(kernels_.make(kProgram, lanes_ == 8 ? "pt_route_lanes" : "pt_route")),
      shadow_(kernels_.make(kProgram, "path_shadow_add")),
      capacity_(chunk_capacity(kMaxPathsInFlight, in.scene.camera.width, in.scene.camera.height)),
      film_(in.context, in.scene.camera.width, in.scene.camera.height, {"radiance"}) {
  const int batches = batch_count(capacity_, pt_.batches, kMinBatchPaths);
  MaterialQueues::LaneKernels lanes;
  if (lanes_ == 8) lanes = {"pt_shade_lanes", {BSDF_DIFFUSE, BSDF_PLASTIC}};
  for (int i = 0; i < batches; ++i) {
    batches_.emplace_back(in, kernels_, batch_capacity(capacity_, batches), i % Context::kQueues, lanes);
  }
  if (pt_.aux) aux_.emplace(in.context, kernels_, kProgram, film_.pixels());
}

GdrPtParams PathTracer::params(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) const {
  GdrPtParams p = in_.device_scene.path_params(settings, sample, first, count);
  p.strategy = pt_.strategy;
  return p;
}

void PathTracer::generate(Batch& b, const GdrPtParams& params) {
  if (params.pixel_count > b.paths.size()) {
    throw Error("pt: " + std::to_string(params.pixel_count) + " paths for a batch of " +
                std::to_string(b.paths.size()));
  }
  generate_.args(in_.device_scene.camera(), params, b.queues.rays[0], b.queues.slots[0], b.paths)
      .run_lanes(params.pixel_count, size_t(lanes_));
}

void PathTracer::intersect(Batch& b, int cur, cl_uint active, bool camera) {
  gdr::intersect(in_.embree, b.queues.rays[cur], active, camera, camera ? "camera" : "bounce");
}

void PathTracer::enqueue_shade(Batch& b, const GdrPtParams& params, int cur, cl_uint active) {
  b.counters.reset();
  if (!b.materials.direct()) {
    route_
        .args(params, active, b.queues.rays[cur], b.queues.slots[cur], b.materials.keys(), b.paths,
              film_["radiance"], b.counters.buffer(), in_.device_scene)
        .run_lanes(active, size_t(lanes_));
  }
  for (const MaterialQueues::Queue& q : b.materials.route(active)) {
    q.kernel
        ->args(params, q.count, q.first, cl_int(b.materials.direct()), b.materials.entries(), b.queues.rays[cur],
               b.queues.slots[cur], b.queues.rays[1 - cur], b.queues.slots[1 - cur], b.shadow_rays, b.shadow_values,
               b.paths, film_["radiance"], b.counters.buffer(), in_.device_scene);
    q.run();
  }
}

const std::vector<cl_uint>& PathTracer::shade(const GdrPtParams& params, int cur, cl_uint active) {
  enqueue_shade(batches_[0], params, cur, active);
  return batches_[0].counters.read();
}

void PathTracer::occlude(Batch& b, cl_uint shadows) {
  gdr::occlude(in_.embree, b.shadow_rays, shadows, "shadow", b.depth == 0);  // from the first hits: coherent
}

void PathTracer::add_shadows(Batch& b, cl_uint shadows) {
  shadow_.args(shadows, b.shadow_rays, b.shadow_values, film_["radiance"]).run(shadows);
}

void PathTracer::step(Batch& b) {
  QueueScope scope(in_.context, b.command_queue);
  if (b.shading) {
    b.counters.read();
    const cl_uint shadows = b.counters[PT_COUNTER_SHADOW_RAYS];
    if (shadows > 0) {
      occlude(b, shadows);
      add_shadows(b, shadows);
    }
    b.active = b.counters[PT_COUNTER_NEXT_RAYS];
    b.cur = 1 - b.cur;
    ++b.depth;
    b.shading = false;
  }
  if (b.active == 0) return;
  intersect(b, b.cur, b.active, b.depth == 0);
  if (b.depth == 0 && aux_) aux_->add(b.params, b.queues.rays[b.cur], b.active, in_.device_scene);
  enqueue_shade(b, b.params, b.cur, b.active);
  b.shading = true;
}

void PathTracer::trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) {
  for (size_t i = 0; i < batches_.size(); ++i) {
    Batch& b = batches_[i];
    const BatchRange r = batch_range(first, count, batches_.size(), i);
    b.params = params(settings, sample, r.first, r.count);
    b.active = r.count;
    b.cur = b.depth = 0;
    b.shading = false;
    if (r.count == 0) continue;
    QueueScope scope(in_.context, b.command_queue);
    generate(b, b.params);
  }
  step_in_turn(batches_, [](const Batch& b) { return b.active == 0 && !b.shading; },
               [&](Batch& b) { step(b); });
  for (Batch& b : batches_) b.counters.report(in_.context.stats());
}

RenderResult PathTracer::render(const RenderSettings& settings) {
  return render_radiance(in_.context, settings, film_, aux_, capacity_, [&](uint32_t sample, uint32_t first, uint32_t count) {
    trace_chunk(settings, sample, first, count);
  });
}

}  // namespace gdr
