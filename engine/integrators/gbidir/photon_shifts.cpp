#include "integrators/gbidir/photon_shifts.h"

#include <algorithm>
#include <vector>

#include "render/wavefront/ray_queues.h"

namespace gdr {
namespace {

// Shift rays in flight at most (each a GdrRayHit); with manifold walks, each ray may take a walk
// (about 0.5 KiB with the walk's state and rays), so fewer.
constexpr size_t kMaxShiftRays = size_t(1) << 19;
constexpr size_t kMaxWalkingShiftRays = size_t(1) << 17;

}  // namespace

PhotonShifts::PhotonShifts(const RenderInputs& in, const GradientGroups& groups, bool walks,
                           const ManifoldSettings& manifold)
    : in_(in),
      max_rays_(walks ? kMaxWalkingShiftRays : kMaxShiftRays),
      count_(groups.kernels().make(groups.program(), "gpm_count")),
      rays_(groups.kernels().make(groups.program(), "gpm_shift_rays")),
      merge_(groups.kernels().make(groups.program(), "gpm_merge")),
      primitives_(in.context),
      starts_(in.context, groups.capacity() + 1),
      lists_(in.context, groups.capacity() * GPM_LISTED),
      listed_(in.context, groups.capacity()),
      shift_rays_(in.context, max_rays_, ray_queue_flags(in.context)),
      walk_of_(in.context, walks ? max_rays_ : 1),
      walks_(in.context, walks ? max_rays_ : 1),
      walk_results_(in.context, walks ? max_rays_ : 1),
      reverse_rays_(in.context, walks ? max_rays_ : 1, ray_queue_flags(in.context)) {
  if (!walks) return;
  walk_kernel_.emplace(groups.kernels().make(groups.program(), "gpm_photon_walks"));
  reverse_kernel_.emplace(groups.kernels().make(groups.program(), "gpm_photon_reverse_rays"));
  manifold_.emplace(in, groups.kernels(), groups.program(), max_rays_, manifold);
}

void PhotonShifts::report(Stats* stats) {
  if (manifold_) manifold_->report(stats);
}

void PhotonShifts::merge_slice(const GdrGptParams& p, const GdrBidirOptions& o, cl_uint first, cl_uint count,
                               size_t shifted, GradientGroups& groups, const PhotonGrid& g) {
  const cl_uint capacity = cl_uint(max_rays_);
  if (shifted > 0) {
    rays_
        .args(p, o, first, count, groups.connectable(), groups.records(), g.store, g.points, g.starts, g.sorted,
              g.buckets, lists_, listed_, g.origins, g.delta_points, g.delta_depths, g.stride, starts_, shift_rays_,
              capacity, in_.device_scene)
        .run(count);
    intersect(in_.embree, shift_rays_, std::min(max_rays_, shifted * GPT_OFFSETS), false, "photon_shift");
    if (manifold_) {
      groups.counters().reset();
      walk_kernel_
          ->args(p, o, first, count, groups.connectable(), groups.records(), g.store, g.points, g.starts, g.sorted,
                 g.buckets, lists_, listed_, g.origins, g.delta_points, g.delta_depths, g.stride, starts_,
                 shift_rays_, capacity, walk_of_, walks_, groups.counters().buffer(), in_.device_scene)
          .run(count);
      groups.counters().read();
      const cl_uint walks = groups.counters()[GPT_COUNTER_MANIFOLD_WALKS];
      if (walks > 0) {
        manifold_->solve(walks_, walks, walk_results_, p.path);
        reverse_kernel_->args(p, walks, walks_, walk_results_, reverse_rays_, in_.device_scene).run(walks);
        occlude(in_.embree, reverse_rays_, walks, "photon_reverse");
      }
    }
  }
  groups.counters().reset();
  merge_
      .args(p, o, first, count, groups.connectable(), groups.records(), groups.bases(), g.store, g.points, g.starts,
            g.sorted, g.buckets, lists_, listed_, g.origins, g.delta_points, g.delta_depths, g.stride, starts_,
            shift_rays_, capacity, walk_of_, walks_, walk_results_, reverse_rays_, groups.acc(),
            groups.counters().buffer(), in_.device_scene)
      .run(count);
  groups.counters().read();
}

void PhotonShifts::merge(const GdrGptParams& p, const GdrBidirOptions& o, cl_uint recorded, GradientGroups& groups,
                         const PhotonGrid& g) {
  if (g.buckets == 0 || recorded == 0) return;
  ScopedTimer timer(in_.context.stats(), "render/merge");
  count_
      .args(p, o, recorded, groups.connectable(), groups.records(), g.store, g.points, g.starts, g.sorted, g.buckets,
            starts_, lists_, listed_, in_.device_scene)
      .run(recorded);
  // The photons whose shifts need rays; the merges of the other groups need none.
  const cl_uint total = primitives_.exclusive_scan(starts_, size_t(recorded) + 1);
  const size_t per_slice = max_rays_ / GPT_OFFSETS;
  if (total <= per_slice) {
    merge_slice(p, o, 0, recorded, total, groups, g);
    return;
  }
  // Slices of whole groups whose photons' rays fit (a visible point with more photons than that,
  // 2^17, has a slice of its own, and its photons past the bound get no ray: kernels/gbidir/merge.h).
  std::vector<cl_uint> starts(size_t(recorded) + 1);
  {
    auto m = starts_.map(starts.size());
    std::copy(m.data(), m.data() + starts.size(), starts.begin());
  }
  for (cl_uint first = 0; first < recorded;) {
    cl_uint end = first + 1;
    while (end < recorded && starts[end + 1] - starts[first] <= per_slice) ++end;
    merge_slice(p, o, first, end - first, starts[end] - starts[first], groups, g);
    first = end;
  }
}

}  // namespace gdr
