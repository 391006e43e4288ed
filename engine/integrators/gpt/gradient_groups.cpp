#include "integrators/gpt/gradient_groups.h"

#include <algorithm>

#include "render/wavefront/batches.h"
#include "render/wavefront/chunks.h"
#include "util/log.h"

namespace gdr {

static_assert(sizeof(GptChain) == 28 + 40 * MANIFOLD_MAX_CHAIN, "GptChain layout changed");

namespace {

// Groups in flight per batch: a group holds five paths (about 1.5 KiB of queues and state), and
// with the manifold shift up to four walks (about 2 KiB more).
constexpr size_t kMaxGroupsInFlight = size_t(1) << 17;
constexpr size_t kMaxManifoldGroupsInFlight = size_t(1) << 15;
// Fewer groups than this a batch would leave launches and Embree's calls too small to pay.
constexpr size_t kMinBatchGroups = size_t(1) << 13;

// G-BDPT's and G-VCM's groups connect to light subpaths.
bool connects(GroupKind kind) { return kind == GroupKind::kConnecting || kind == GroupKind::kConnectingMerging; }
// G-PM's and G-VCM's merge with the photons of their chunk's light subpaths.
bool merges(GroupKind kind) { return kind == GroupKind::kMerging || kind == GroupKind::kConnectingMerging; }

Defines gpt_defines(const RenderInputs& in, const GptSettings& gpt, GroupKind kind) {
  Defines d = gpt_manifold_enabled(in.scene, gpt) ? manifold_defines(in.context.device(), gpt.manifold) : Defines{};
  if (connects(kind)) d["GDR_GBDPT"] = "1";
  if (kind == GroupKind::kConnectingMerging) d["GDR_GVCM"] = "1";
  if (kind == GroupKind::kConnecting && gpt.power_primal) d["GDR_GBDPT_POWER_PRIMAL"] = "1";
  if (kind == GroupKind::kMerging) d["GDR_GPM"] = "1";
  return d;
}

}  // namespace

GptSettings gpt_shift_settings(const IntegratorParams& params, const std::string& default_shift) {
  GptSettings s;
  std::string shift = params.choice("shift", default_shift, {"hybrid", "replay", "manifold"});
  s.shift = shift == "replay" ? GPT_SHIFT_REPLAY : shift == "manifold" ? GPT_SHIFT_MANIFOLD : GPT_SHIFT_HYBRID;
  s.shift_threshold = params.non_negative("shift_threshold", s.shift_threshold);
  s.manifold = manifold_settings(params);
  return s;
}

bool gpt_manifold_enabled(const Scene& scene, const GptSettings& gpt) {
  return gpt.shift == GPT_SHIFT_MANIFOLD && scene.features.specular_chains();
}

size_t GradientGroups::chunk_capacity_for(const RenderInputs& in, const GptSettings& gpt, GroupKind kind) {
  // The CPU device's bound pays where the group states' traffic is the cost; the manifold walks'
  // stages took 1.03 of their time with it (caustics box, 256 px), and merging's photons are a
  // chunk's own.
  const bool manifold = gpt_manifold_enabled(in.scene, gpt);
  return device_chunk_capacity(manifold ? kMaxManifoldGroupsInFlight : kMaxGroupsInFlight,
                               in.context.is_cpu() && !manifold && !merges(kind), gpt.in_flight, in.scene.camera.width,
                               in.scene.camera.height);
}

const char* GradientGroups::program() const {
  switch (kind_) {
    case GroupKind::kConnecting: return kConnectingProgram;
    case GroupKind::kMerging: return kMergingProgram;
    case GroupKind::kConnectingMerging: return kConnectingMergingProgram;
    default: return kProgram;
  }
}

GradientGroups::Batch::Batch(const RenderInputs& in, const KernelFactory& kernels, const char* program,
                             size_t capacity, GroupKind kind, bool route, int command_queue)
    : command_queue(command_queue),
      materials(in.context, in.scene, kernels, program, "gpt_shade", capacity, route),
      base_queues(in.context, capacity, false),
      shift_groups(in.context, capacity),
      offset_rays(in.context, capacity * GPT_OFFSETS, ray_queue_flags(in.context)),
      reconnect_rays(in.context, capacity * GPT_OFFSETS, ray_queue_flags(in.context)),
      shadow_rays(in.context, capacity * (GPT_OFFSETS + 1), ray_queue_flags(in.context)),
      bases(in.context, capacity),
      offsets(in.context, capacity * GPT_OFFSETS),
      pend(in.context, capacity * GPT_PEND_COUNT),
      records(in.context, kind == GroupKind::kPaths ? 0 : capacity),
      connectable(in.context, kind == GroupKind::kPaths ? 0 : capacity),
      counters(in.context, GDR_COUNTER_NAMES(GPT_COUNTERS)) {}

GradientGroups::GradientGroups(const RenderInputs& in, const GptSettings& gpt, size_t capacity, size_t indices,
                               GroupKind kind)
    : in_(in),
      gpt_(gpt),
      kind_(kind),
      kernels_(in.context, in.scene, gpt_defines(in, gpt, kind)),
      generate_(kernels_.make(program(), "gpt_generate")),
      scatter_(kernels_.make(program(), "gpt_scatter")),
      route_(kernels_.make(program(), "gpt_route")),
      shadow_(kernels_.make(program(), "gpt_shadow")),
      shift_(kernels_.make(program(), "gpt_shift")),
      capacity_(capacity),
      acc_(in.context, indices * GPT_ACC_COUNT) {
  const bool manifold = gpt_manifold_enabled(in.scene, gpt);
  // Batches step G-PT's own groups only: the others share their light subpaths' and merges'
  // buffers, and the manifold stage its walks'.
  const int wanted = gpt.batches > 0 ? gpt.batches : in.context.is_cpu() ? 1 : 2;
  const int batches = kind == GroupKind::kPaths && !manifold ? batch_count(capacity_, wanted, kMinBatchGroups) : 1;
  const bool route = gpt.route_materials.value_or(!in.context.is_cpu());
  for (int i = 0; i < batches; ++i) {
    batches_.emplace_back(in, kernels_, program(), batch_capacity(capacity_, batches), kind, route,
                          i % Context::kQueues);
  }
  chains_ = Buffer<GptChain>(in.context, manifold ? capacity_ : 0);
  walks_ = Buffer<GdrManifoldWalk>(in.context, manifold ? capacity_ * GPT_OFFSETS : 0);
  walk_results_ = Buffer<GdrManifoldResult>(in.context, manifold ? capacity_ * GPT_OFFSETS : 0);
  if (manifold) {
    manifold_.emplace(in, kernels_, program(), capacity_ * GPT_OFFSETS, gpt.manifold);
    join_.emplace(kernels_.make(program(), "gpt_manifold_join"));
  }
  if (connects(kind)) connect_.emplace(kernels_.make(program(), "gbdpt_connect"));
  if (gpt.shift == GPT_SHIFT_MANIFOLD) log::verbose(manifold_description(in.scene, in.context.device(), gpt.manifold));
}

GdrGptParams GradientGroups::params(const RenderSettings& settings, uint32_t sample, uint32_t first,
                                    uint32_t count) const {
  GdrGptParams p{};
  p.path = in_.device_scene.path_params(settings, sample, first, count);
  p.shift = gpt_.shift;
  p.shift_threshold = gpt_.shift_threshold;
  return p;
}

void GradientGroups::shade(Batch& b, const PrimarySamples& primary) {
  const Buffer<GdrRayHit>& base_in = b.base_queues.rays[b.cur];
  b.counters.reset();
  if (!b.materials.direct()) {
    route_
        .args(b.params, b.active, base_in, b.materials.keys(), b.bases, b.offsets, acc_, b.pend, b.records,
              b.counters.buffer(), primary, in_.device_scene)
        .run(b.active);
  }
  for (const MaterialQueues::Queue& q : b.materials.route(b.active)) {
    q.kernel
        ->args(b.params, q.count, q.first, cl_int(b.materials.direct()), b.materials.entries(), base_in,
               b.base_queues.rays[1 - b.cur], b.shift_groups, b.shadow_rays, b.bases, b.offsets, acc_, b.pend,
               b.records, b.connectable, b.counters.buffer(), primary, in_.device_scene)
        .run(q.count);
  }
}

void GradientGroups::intersect_offsets(Batch& b, cl_uint rays, cl_uint reconnects, bool coherent) {
  intersect(in_.embree, b.offset_rays, rays, coherent, "offset");
  occlude(in_.embree, b.reconnect_rays, reconnects, "reconnection");
  scatter_.args(rays, b.offset_rays, reconnects, b.reconnect_rays, b.offsets).run(rays + reconnects);
}

void GradientGroups::walk_offsets(Batch& b, cl_uint walks) {
  if (!manifold_ || walks == 0) return;
  manifold_->solve(walks_, walks, walk_results_, b.params.path);
  b.counters.reset();
  join_->args(b.params, walks, walks_, walk_results_, chains_, b.offsets, b.counters.buffer(), in_.device_scene)
      .run(walks);
  b.counters.read();
}

void GradientGroups::add_shadows(Batch& b, cl_uint count, const char* kind, bool coherent) {
  if (count == 0) return;
  occlude(in_.embree, b.shadow_rays, count, kind, coherent);
  shadow_.args(count, b.shadow_rays, b.pend, b.bases, acc_).run(count);
}

void GradientGroups::connect(Batch& b, int camera_depth, cl_uint connectable, const GroupLightSubpaths& light) {
  // Vertex j of a light subpath lies j + 1 bounces or more from its light, and the connection
  // adds a segment.
  const int max_depth = b.params.path.max_depth;
  const int last = max_depth < 0 ? light.stored_bound : std::min(light.stored_bound, max_depth - camera_depth - 1);
  for (int j = 0; j < last; ++j) {
    b.counters.reset();
    connect_
        ->args(b.params, connectable, cl_uint(j), light.stride, b.connectable, b.records, light.paths, light.store,
               b.shadow_rays, b.pend, b.counters.buffer(), in_.device_scene)
        .run(connectable);
    b.counters.read();
    add_shadows(b, b.counters[GPT_COUNTER_SHADOW_RAYS], "connection", false);
  }
}

void GradientGroups::start(Batch& b, const GdrGptParams& p, const PrimarySamples& primary) {
  b.params = p;
  b.active = p.path.pixel_count;
  b.cur = b.depth = 0;
  b.phase = b.active > 0 ? Batch::Phase::kGenerating : Batch::Phase::kDone;
  if (b.active == 0) return;
  QueueScope scope(in_.context, b.command_queue);
  b.counters.reset();
  generate_
      .args(in_.device_scene.camera(), p, b.base_queues.rays[0], b.offset_rays, b.bases, b.offsets, chains_, acc_,
            b.counters.buffer(), primary)
      .run(b.active);
}

void GradientGroups::step(Batch& b, const PrimarySamples& primary, AuxLayers* aux, const GroupLightSubpaths* light,
                          const RecordsStep& merge) {
  QueueScope scope(in_.context, b.command_queue);
  b.counters.read();  // waits for what the batch's device was running
  switch (b.phase) {
    case Batch::Phase::kGenerating:
      intersect(in_.embree, b.base_queues.rays[0], b.active, true, "camera");
      if (aux) aux->add(b.params.path, b.base_queues.rays[0], b.active, in_.device_scene);
      intersect_offsets(b, b.counters[GPT_COUNTER_OFFSET_RAYS], 0, true);  // camera rays of the neighbour pixels
      b.next = b.active;
      break;
    case Batch::Phase::kShading: {
      b.next = b.counters[GPT_COUNTER_BASE_RAYS];
      const cl_uint connectable = b.counters[GPT_COUNTER_CONNECTABLE];
      const cl_uint shifting = b.counters[GPT_COUNTER_SHIFT_GROUPS];
      intersect(in_.embree, b.base_queues.rays[1 - b.cur], b.next, false, "bounce");
      add_shadows(b, b.counters[GPT_COUNTER_SHADOW_RAYS], "shadow", b.depth == 0);
      if (light && connectable > 0) connect(b, b.depth + 1, connectable, *light);
      if (merge && connectable > 0) merge(connectable);
      if (shifting > 0) {
        b.counters.reset();
        shift_
            .args(b.params, shifting, b.shift_groups, b.base_queues.rays[1 - b.cur], b.offset_rays, b.reconnect_rays,
                  b.bases, b.offsets, chains_, walks_, b.counters.buffer(), primary, in_.device_scene)
            .run(shifting);
        b.phase = Batch::Phase::kShifting;
        return;
      }
      b.cur = 1 - b.cur;
      ++b.depth;
      break;
    }
    case Batch::Phase::kShifting: {
      const cl_uint offset_rays = b.counters[GPT_COUNTER_OFFSET_RAYS];
      const cl_uint reconnects = b.counters[GPT_COUNTER_RECONNECT_RAYS];
      walk_offsets(b, b.counters[GPT_COUNTER_MANIFOLD_WALKS]);
      intersect_offsets(b, offset_rays, reconnects, false);
      b.cur = 1 - b.cur;
      ++b.depth;
      break;
    }
    case Batch::Phase::kDone: return;
  }
  b.active = b.next;
  if (b.active == 0) {
    b.phase = Batch::Phase::kDone;
    return;
  }
  shade(b, primary);
  b.phase = Batch::Phase::kShading;
}

void GradientGroups::trace(const GdrGptParams& p, const PrimarySamples& primary, AuxLayers* aux,
                           const GroupLightSubpaths* light, const RecordsStep& merge) {
  for (size_t i = 0; i < batches_.size(); ++i) {
    const BatchRange r = batch_range(p.path.first_pixel, p.path.pixel_count, batches_.size(), i);
    GdrGptParams part = p;
    part.path.first_pixel = r.first;
    part.path.pixel_count = r.count;
    start(batches_[i], part, primary);
  }
  step_in_turn(batches_, [](const Batch& b) { return b.phase == Batch::Phase::kDone; },
               [&](Batch& b) { step(b, primary, aux, light, merge); });
  // A batch's last shadows may still run on its queue: the pass's gather reads every path's sums.
  if (batches_.size() > 1) in_.context.finish();
}

void GradientGroups::report(Stats* stats) {
  for (Batch& b : batches_) b.counters.report(stats);
  if (manifold_) manifold_->report(stats);
}

}  // namespace gdr
