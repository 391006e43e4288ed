#include "integrators/gbidir/photon_shifts.h"

#include <algorithm>
#include <vector>

#include "render/wavefront/ray_queues.h"

namespace gdr {
namespace {

// Shift rays in flight at most (each a GdrRayHit).
constexpr size_t kMaxShiftRays = size_t(1) << 19;

}  // namespace

PhotonShifts::PhotonShifts(const RenderInputs& in, const GradientGroups& groups)
    : in_(in),
      count_(groups.kernels().make(groups.program(), "gpm_count")),
      rays_(groups.kernels().make(groups.program(), "gpm_shift_rays")),
      merge_(groups.kernels().make(groups.program(), "gpm_merge")),
      primitives_(in.context),
      starts_(in.context, groups.capacity() + 1),
      shift_rays_(in.context, kMaxShiftRays, ray_queue_flags(in.context)) {}

void PhotonShifts::merge_slice(const GdrGptParams& p, const GdrBidirOptions& o, cl_uint first, cl_uint count,
                               size_t shifted, GradientGroups& groups, const PhotonGrid& g) {
  if (shifted > 0) {
    rays_
        .args(p, o, first, count, groups.connectable(), groups.records(), g.store, g.points, g.starts, g.sorted,
              g.buckets, g.origins, g.stride, starts_, shift_rays_, cl_uint(kMaxShiftRays), in_.device_scene)
        .run(count);
    intersect(in_.embree, shift_rays_, std::min(kMaxShiftRays, shifted * GPT_OFFSETS), false, "photon_shift");
  }
  groups.counters().reset();
  merge_
      .args(p, o, first, count, groups.connectable(), groups.records(), groups.bases(), g.store, g.points, g.starts,
            g.sorted, g.buckets, g.origins, g.stride, starts_, shift_rays_, cl_uint(kMaxShiftRays), groups.acc(),
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
            starts_, in_.device_scene)
      .run(recorded);
  // The photons whose shifts need rays; the merges of the other groups need none.
  const cl_uint total = primitives_.exclusive_scan(starts_, size_t(recorded) + 1);
  const size_t per_slice = kMaxShiftRays / GPT_OFFSETS;
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
