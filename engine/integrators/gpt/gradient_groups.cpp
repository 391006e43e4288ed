#include "integrators/gpt/gradient_groups.h"

#include <algorithm>

#include "render/wavefront/chunks.h"
#include "util/log.h"

namespace gdr {

static_assert(sizeof(GptChain) == 28 + 40 * MANIFOLD_MAX_CHAIN, "GptChain layout changed");

namespace {

// Groups in flight per batch: a group holds five paths (about 1.5 KiB of queues and state), and
// with the manifold shift up to four walks (about 2 KiB more).
constexpr size_t kMaxGroupsInFlight = size_t(1) << 17;
constexpr size_t kMaxManifoldGroupsInFlight = size_t(1) << 15;

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
      materials_(in.context, in.scene, kernels_, program(), "gpt_shade", capacity_,
                 gpt.route_materials.value_or(!in.context.is_cpu())),
      base_queues_(in.context, capacity_, false),
      shift_groups_(in.context, capacity_),
      offset_rays_(in.context, capacity_ * GPT_OFFSETS, ray_queue_flags(in.context)),
      reconnect_rays_(in.context, capacity_ * GPT_OFFSETS, ray_queue_flags(in.context)),
      shadow_rays_(in.context, capacity_ * (GPT_OFFSETS + 1), ray_queue_flags(in.context)),
      bases_(in.context, capacity_),
      offsets_(in.context, capacity_ * GPT_OFFSETS),
      acc_(in.context, indices * GPT_ACC_COUNT),
      pend_(in.context, capacity_ * GPT_PEND_COUNT),
      records_(in.context, kind == GroupKind::kPaths ? 0 : capacity_),
      connectable_(in.context, kind == GroupKind::kPaths ? 0 : capacity_),
      counters_(in.context, GDR_COUNTER_NAMES(GPT_COUNTERS)) {
  const bool manifold = gpt_manifold_enabled(in.scene, gpt);
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

void GradientGroups::shade(const GdrGptParams& p, const PrimarySamples& primary, const Buffer<GdrRayHit>& base_in,
                           Buffer<GdrRayHit>& base_out, cl_uint active) {
  counters_.reset();
  if (!materials_.direct()) {
    route_
        .args(p, active, base_in, materials_.keys(), bases_, offsets_, acc_, pend_, records_, counters_.buffer(),
              primary, in_.device_scene)
        .run(active);
  }
  for (const MaterialQueues::Queue& q : materials_.route(active)) {
    q.kernel
        ->args(p, q.count, q.first, cl_int(materials_.direct()), materials_.entries(), base_in, base_out,
               shift_groups_, shadow_rays_, bases_, offsets_, acc_, pend_, records_, connectable_,
               counters_.buffer(), primary, in_.device_scene)
        .run(q.count);
  }
  counters_.read();
}

void GradientGroups::intersect_offsets(cl_uint rays, cl_uint reconnects, bool coherent) {
  intersect(in_.embree, offset_rays_, rays, coherent, "offset");
  occlude(in_.embree, reconnect_rays_, reconnects, "reconnection");
  scatter_.args(rays, offset_rays_, reconnects, reconnect_rays_, offsets_).run(rays + reconnects);
}

void GradientGroups::walk_offsets(const GdrGptParams& p, cl_uint walks) {
  if (!manifold_ || walks == 0) return;
  manifold_->solve(walks_, walks, walk_results_, p.path);
  counters_.reset();
  join_->args(p, walks, walks_, walk_results_, chains_, offsets_, counters_.buffer(), in_.device_scene).run(walks);
  counters_.read();
}

void GradientGroups::add_shadows(cl_uint count, const char* kind, bool coherent) {
  if (count == 0) return;
  occlude(in_.embree, shadow_rays_, count, kind, coherent);
  shadow_.args(count, shadow_rays_, pend_, bases_, acc_).run(count);
}

void GradientGroups::connect(const GdrGptParams& p, int camera_depth, cl_uint connectable,
                             const GroupLightSubpaths& light) {
  // Vertex j of a light subpath lies j + 1 bounces or more from its light, and the connection
  // adds a segment.
  const int max_depth = p.path.max_depth;
  const int last = max_depth < 0 ? light.stored_bound : std::min(light.stored_bound, max_depth - camera_depth - 1);
  for (int j = 0; j < last; ++j) {
    counters_.reset();
    connect_
        ->args(p, connectable, cl_uint(j), light.stride, connectable_, records_, light.paths, light.store,
               shadow_rays_, pend_, counters_.buffer(), in_.device_scene)
        .run(connectable);
    counters_.read();
    add_shadows(counters_[GPT_COUNTER_SHADOW_RAYS], "connection", false);
  }
}

void GradientGroups::trace(const GdrGptParams& p, const PrimarySamples& primary, AuxLayers* aux,
                           const GroupLightSubpaths* light, const RecordsStep& merge) {
  Buffer<GdrRayHit>* base_rays = base_queues_.rays;
  const cl_uint count = p.path.pixel_count;

  counters_.reset();
  generate_
      .args(in_.device_scene.camera(), p, base_rays[0], offset_rays_, bases_, offsets_, chains_, acc_,
            counters_.buffer(), primary)
      .run(count);
  counters_.read();
  intersect(in_.embree, base_rays[0], count, true, "camera");
  if (aux) aux->add(p.path, base_rays[0], count, in_.device_scene);
  intersect_offsets(counters_[GPT_COUNTER_OFFSET_RAYS], 0, true);  // camera rays of the neighbour pixels

  cl_uint active = count;
  for (int cur = 0, depth = 0; active > 0; cur = 1 - cur, ++depth) {
    shade(p, primary, base_rays[cur], base_rays[1 - cur], active);
    const cl_uint next = counters_[GPT_COUNTER_BASE_RAYS], connectable = counters_[GPT_COUNTER_CONNECTABLE];
    const cl_uint shifting = counters_[GPT_COUNTER_SHIFT_GROUPS];
    intersect(in_.embree, base_rays[1 - cur], next, false, "bounce");
    add_shadows(counters_[GPT_COUNTER_SHADOW_RAYS], "shadow", depth == 0);
    if (light && connectable > 0) connect(p, depth + 1, connectable, *light);
    if (merge && connectable > 0) merge(connectable);
    if (shifting > 0) {
      counters_.reset();
      shift_
          .args(p, shifting, shift_groups_, base_rays[1 - cur], offset_rays_, reconnect_rays_, bases_, offsets_,
                chains_, walks_, counters_.buffer(), primary, in_.device_scene)
          .run(shifting);
      counters_.read();
      const cl_uint offset_rays = counters_[GPT_COUNTER_OFFSET_RAYS];
      const cl_uint reconnects = counters_[GPT_COUNTER_RECONNECT_RAYS];
      walk_offsets(p, counters_[GPT_COUNTER_MANIFOLD_WALKS]);
      intersect_offsets(offset_rays, reconnects, false);
    }
    active = next;
  }
}

void GradientGroups::report(Stats* stats) {
  counters_.report(stats);
  if (manifold_) manifold_->report(stats);
}

}  // namespace gdr
