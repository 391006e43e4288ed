#include "integrators/gbidir/light_tracing_shifts.h"

#include "render/wavefront/ray_queues.h"

namespace gdr {

LightTracingShifts::LightTracingShifts(const RenderInputs& in, const GradientGroups& groups, size_t slots, bool walks,
                                       const ManifoldSettings& manifold)
    : in_(in),
      rays_(groups.kernels().make(groups.program(), "gbdpt_lt_offset_rays")),
      eval_(groups.kernels().make(groups.program(), "gbdpt_lt_offset_eval")),
      blocked_(groups.kernels().make(groups.program(), "gbdpt_lt_offset_blocked")),
      gather_(groups.kernels().make(groups.program(), "gbdpt_lt_gather")),
      add_(groups.kernels().make(groups.program(), "gbdpt_add_light_tracing")),
      offset_rays_(in.context, slots * GPT_OFFSETS, ray_queue_flags(in.context)),
      shadow_rays_(in.context, slots * GPT_OFFSETS, ray_queue_flags(in.context)),
      pairs_(in.context, slots * GPT_OFFSETS),
      layers_(in.context, size_t(in.scene.camera.width) * in.scene.camera.height * GBDPT_LT_LAYERS),
      walk_of_(in.context, walks ? slots * GPT_OFFSETS : 1),
      walks_(in.context, walks ? slots * GPT_OFFSETS : 1),
      walk_results_(in.context, walks ? slots * GPT_OFFSETS : 1) {
  layers_.fill(Vec4{});
  if (!walks) return;
  walk_kernel_.emplace(groups.kernels().make(groups.program(), "gbdpt_lt_offset_walks"));
  manifold_.emplace(in, groups.kernels(), groups.program(), slots * GPT_OFFSETS, manifold);
}

void LightTracingShifts::report(Stats* stats) {
  if (manifold_) manifold_->report(stats);
}

void LightTracingShifts::shift(const GdrGptParams& p, const GdrBidirOptions& o, cl_uint count,
                               const BidirSubpaths& subpaths, SplatFilm& splats, GradientGroups& groups) {
  if (count == 0) return;
  ScopedTimer timer(in_.context.stats(), "render/light_tracing_shifts");
  const Buffer<GdrCamera>& camera = in_.device_scene.camera();
  DeviceCounters& counters = groups.counters();
  const cl_uint stride = cl_uint(subpaths.capacity());
  const PhotonGrid g = subpaths.grid();
  counters.reset();
  rays_
      .args(p, count, stride, camera, splats.slots(), subpaths.seen(), subpaths.light_paths(), subpaths.store(),
            subpaths.origins(), g.delta_points, g.delta_depths, pairs_, offset_rays_, counters.buffer(),
            in_.device_scene)
      .run(count);
  const cl_uint rays = counters.read()[GPT_COUNTER_LT_OFFSET_RAYS];
  if (rays > 0) {
    intersect(in_.embree, offset_rays_, rays, false, "light_tracing_offset");
    if (manifold_) {
      counters.reset();
      walk_kernel_
          ->args(p, rays, stride, offset_rays_, subpaths.seen(), subpaths.light_paths(), subpaths.store(),
                 subpaths.origins(), g.delta_points, g.delta_depths, walk_of_, walks_, counters.buffer(),
                 in_.device_scene)
          .run(rays);
      const cl_uint walks = counters.read()[GPT_COUNTER_MANIFOLD_WALKS];
      if (walks > 0) manifold_->solve(walks_, walks, walk_results_, p.path);
    }
    counters.reset();
    eval_
        .args(p, o, rays, stride, camera, offset_rays_, subpaths.seen(), subpaths.light_paths(), subpaths.store(),
              subpaths.origins(), g.delta_points, g.delta_depths, walk_of_, walks_, walk_results_, pairs_,
              shadow_rays_, counters.buffer(), in_.device_scene)
        .run(rays);
    occlude(in_.embree, shadow_rays_, rays, "light_tracing_offset");
    blocked_.args(rays, shadow_rays_, pairs_, counters.buffer()).run(rays);
    counters.read();
  }
  const int height = in_.scene.camera.height;
  splats.sort(camera, height, count);
  gather_.args(camera, splats.starts(), splats.sorted(), splats.slots(), pairs_, layers_).run(size_t(height));
  splats.clear();
}

void LightTracingShifts::end_pass(GradientGroups& groups) {
  const cl_uint pixels = cl_uint(layers_.size() / GBDPT_LT_LAYERS);
  add_.args(pixels, layers_, groups.acc()).run(pixels);
}

}  // namespace gdr
