#include "integrators/bidir/subpaths.h"

#include <algorithm>

// The kernels see these layouts too (4-byte scalars only: the same on both sides).
static_assert(sizeof(GdrBidirOptions) == 40, "GdrBidirOptions layout changed");
static_assert(sizeof(GdrBidirPathState) == 64, "GdrBidirPathState layout changed");
static_assert(sizeof(GdrBidirVertex) == 60, "GdrBidirVertex layout changed");
static_assert(sizeof(GdrLightOrigin) == 32, "GdrLightOrigin layout changed");

namespace gdr {

BidirSubpaths::BidirSubpaths(const RenderInputs& in, int technique, size_t capacity)
    : in_(in),
      technique_(technique),
      kernels_(in.context, in.scene),
      direct_(in, kernels_, kProgram),
      emit_(kernels_.make(kProgram, "bidir_emit")),
      light_shade_(kernels_.make(kProgram, "bidir_light_shade")),
      camera_blocked_(kernels_.make(kProgram, "bidir_camera_blocked")),
      generate_(kernels_.make(kProgram, "bdpt_generate")),
      camera_shade_(kernels_.make(kProgram, "bdpt_camera_shade")),
      connect_(kernels_.make(kProgram, "bdpt_connect")),
      shadow_add_(kernels_.make(kProgram, "path_shadow_add")),
      grid_keys_(kernels_.make(kProgram, "vcm_grid_keys")),
      merge_(kernels_.make(kProgram, "vcm_merge")),
      splats_to_paths_(kernels_.make(kProgram, "bidir_splats_to_paths")),
      capacity_(capacity),
      store_vertices_(lt() ? 0 : kBdptMaxSegments - 1),
      queues_(in.context, capacity_, true),
      light_paths_(in.context, capacity_),
      camera_paths_(in.context, lt() ? 0 : capacity_),
      light_origins_(in.context, capacity_),
      delta_points_(in.context, 1),
      seen_(in.context, capacity_),
      store_(in.context, capacity_ * size_t(store_vertices_)),
      camera_vertices_(in.context, lt() ? 0 : capacity_),
      connectable_(in.context, lt() ? 0 : capacity_),
      shadow_rays_(in.context, capacity_, ray_queue_flags(in.context)),
      shadow_values_(in.context, lt() ? 0 : capacity_),
      counters_(in.context, GDR_COUNTER_NAMES(BIDIR_COUNTERS)) {
  if (merges()) {
    const size_t entries = capacity_ * size_t(store_vertices_);
    primitives_.emplace(in.context);
    grid_keys_buffer_ = Buffer<cl_uint>(in.context, entries);
    grid_starts_ = Buffer<cl_uint>(in.context, entries + 1);
    grid_sorted_ = Buffer<cl_uint>(in.context, entries);
    store_points_ = Buffer<Vec4>(in.context, entries);
  }
}

void BidirSubpaths::trace_light_subpaths(const GdrPtParams& p, const BidirSink& sink) {
  const GdrBidirOptions& o = options_;
  counters_.reset();
  emit_
      .args(p, o, queues_.rays[0], queues_.slots[0], light_paths_, light_origins_, counters_.buffer(), primary_,
            in_.device_scene)
      .run(p.pixel_count);
  cl_uint active = counters_.read()[BIDIR_COUNTER_NEXT_RAYS];
  for (int cur = 0; active > 0; cur = 1 - cur) {
    intersect(in_.embree, queues_.rays[cur], active, false, "light");
    counters_.reset();
    light_shade_
        .args(p, o, active, cl_uint(capacity_), in_.device_scene.camera(), queues_.rays[cur], queues_.slots[cur],
              queues_.rays[1 - cur], queues_.slots[1 - cur], shadow_rays_, sink.splats.slots(), seen_, light_paths_,
              store_, delta_points_, delta_depths_, counters_.buffer(), primary_, in_.device_scene)
        .run(active);
    counters_.read();
    if (counters_[BIDIR_COUNTER_LIGHT_VERTICES] > 0) ++stored_bound_;
    stored_ += counters_[BIDIR_COUNTER_LIGHT_VERTICES];
    cl_uint shadows = counters_[BIDIR_COUNTER_SHADOW_RAYS];
    if (shadows > 0) {
      occlude(in_.embree, shadow_rays_, shadows, "camera_connection");
      camera_blocked_.args(shadows, shadow_rays_, sink.splats.slots()).run(shadows);
      if (sink.take_splats) {
        sink.take_splats(p.pixel_count);
      } else if (sink.gather_into) {
        sink.splats.gather(in_.device_scene.camera(), in_.scene.camera.height, p.pixel_count, *sink.gather_into);
      } else if (sink.path_sums) {
        splats_to_paths_.args(p.pixel_count, sink.splats.slots(), *sink.path_sums).run(p.pixel_count);
      }
    }
    active = counters_[BIDIR_COUNTER_NEXT_RAYS];
  }
}

void BidirSubpaths::add_shadows(cl_uint count, const char* kind, Buffer<Vec4>& values) {
  if (count == 0) return;
  occlude(in_.embree, shadow_rays_, count, kind);
  shadow_add_.args(count, shadow_rays_, shadow_values_, values).run(count);
}

void BidirSubpaths::connect(const GdrPtParams& p, int camera_depth, cl_uint connectable, Buffer<Vec4>& values) {
  // Vertex j of a light subpath lies j + 1 bounces or more from its light, and the connection
  // adds a segment. A multiplexed path connects to one vertex at most: one launch finds it.
  const int last = std::min(stored_bound_, p.max_depth - camera_depth - 1);
  for (int j = 0; j < (options_.multiplex ? std::min(last, 1) : last); ++j) {
    counters_.reset();
    connect_
        .args(p, options_, connectable, options_.multiplex ? BIDIR_OWN_STRATEGY : cl_uint(j), cl_uint(capacity_), connectable_,
              camera_vertices_, light_paths_, store_, shadow_rays_, shadow_values_, counters_.buffer(),
              in_.device_scene)
        .run(connectable);
    counters_.read();
    add_shadows(counters_[BIDIR_COUNTER_SHADOW_RAYS], "connection", values);
  }
}

void BidirSubpaths::build_grid(const GdrPtParams& p) {
  ScopedTimer timer(in_.context.stats(), "render/grid_build");
  const size_t entries = capacity_ * size_t(stored_bound_);
  grid_buckets_ = std::max<cl_uint>(1, stored_);
  grid_keys_
      .args(p, options_, cl_uint(capacity_), cl_uint(entries), light_paths_, store_, grid_buckets_, grid_keys_buffer_,
            store_points_, in_.device_scene)
      .run(entries);
  primitives_->sort_by_key(grid_keys_buffer_, entries, grid_buckets_, grid_starts_, grid_sorted_);
}

void BidirSubpaths::merge(const GdrPtParams& p, cl_uint connectable, Buffer<Vec4>& values) {
  counters_.reset();
  merge_
      .args(p, options_, connectable, cl_uint(capacity_), connectable_, camera_vertices_, store_, store_points_,
            grid_starts_, grid_sorted_, grid_buckets_, values, counters_.buffer(), in_.device_scene)
      .run(connectable);
  counters_.read();
}

void BidirSubpaths::trace_camera_subpaths(const GdrPtParams& p, const BidirSink& sink, AuxLayers* aux) {
  const GdrBidirOptions& o = options_;
  counters_.reset();
  generate_
      .args(in_.device_scene.camera(), p, o, queues_.rays[0], queues_.slots[0], camera_paths_, counters_.buffer(),
            primary_)
      .run(p.pixel_count);
  cl_uint active = o.multiplex ? counters_.read()[BIDIR_COUNTER_NEXT_RAYS] : p.pixel_count;
  for (int depth = 0, cur = 0; active > 0; ++depth, cur = 1 - cur) {
    intersect(in_.embree, queues_.rays[cur], active, depth == 0, depth == 0 ? "camera" : "bounce");
    if (depth == 0 && aux) aux->add(p, queues_.rays[cur], active, in_.device_scene);
    counters_.reset();
    camera_shade_
        .args(p, o, active, queues_.rays[cur], queues_.slots[cur], queues_.rays[1 - cur], queues_.slots[1 - cur],
              shadow_rays_, shadow_values_, camera_paths_, camera_vertices_, connectable_, sink.values,
              counters_.buffer(), primary_, in_.device_scene)
        .run(active);
    counters_.read();
    cl_uint connectable = counters_[BIDIR_COUNTER_CONNECTABLE];
    active = counters_[BIDIR_COUNTER_NEXT_RAYS];
    add_shadows(counters_[BIDIR_COUNTER_SHADOW_RAYS], "shadow", sink.values);
    if (connectable > 0 && connects()) connect(p, depth + 1, connectable, sink.values);
    if (connectable > 0 && merges() && stored_ > 0) merge(p, connectable, sink.values);
  }
}

void BidirSubpaths::begin(const GdrBidirOptions& o, const PrimarySamples& primary) {
  options_ = o;
  primary_ = primary;
  stored_bound_ = 0;
  stored_ = 0;
}

void BidirSubpaths::trace_light(const GdrPtParams& p, const GdrBidirOptions& o, const BidirSink& sink) {
  begin(o, PrimarySamples());
  trace_light_subpaths(p, sink);
  if (merges() && stored_ > 0) build_grid(p);
}

PhotonGrid BidirSubpaths::grid() const {
  return PhotonGrid{store_, store_points_, grid_starts_, grid_sorted_, light_origins_,
                    stored_ > 0 ? grid_buckets_ : 0, cl_uint(capacity_), delta_points_, delta_depths_};
}

void BidirSubpaths::record_delta_points() {
  delta_depths_ = cl_uint(kBdptMaxSegments);
  delta_points_ = Buffer<GdrManifoldPoint>(in_.context, capacity_ * delta_depths_);
}

void BidirSubpaths::trace(const GdrPtParams& p, const GdrBidirOptions& o, bool light, const PrimarySamples& primary,
                          const BidirSink& sink, AuxLayers* aux) {
  begin(o, primary);
  if (!lt()) {
    if (light) trace_light_subpaths(p, sink);
    if (merges() && stored_ > 0) build_grid(p);
    trace_camera_subpaths(p, sink, aux);
  } else {
    direct_.add(p, -1, queues_.rays[0], SeenFilm{sink.values}, aux);
    if (light) trace_light_subpaths(p, sink);
  }
}

}  // namespace gdr
