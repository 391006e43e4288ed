#include "render/wavefront/ray_queues.h"

#include <vector>

namespace gdr {
namespace {

// Runs `traverse` on the first `count` rays of `rays` on the host: mapped in place, or copied out
// and back.
template <class T, class F>
void on_host(Buffer<T>& rays, size_t count, F&& traverse) {
  if (rays.context().zero_copy()) {
    auto m = rays.map(count);
    traverse(m.data());
    return;
  }
  thread_local std::vector<T> copy;
  if (copy.size() < count) copy.resize(count);
  rays.read(copy.data(), count);
  traverse(copy.data());
  rays.write(copy.data(), count);
}

}  // namespace

cl_mem_flags ray_queue_flags(const Context& context) {
  return context.zero_copy() ? CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR : CL_MEM_READ_WRITE;
}

RayQueues::RayQueues(Context& ctx, size_t capacity, bool with_slots)
    : rays{Buffer<GdrRayHit>(ctx, capacity, ray_queue_flags(ctx)),
           Buffer<GdrRayHit>(ctx, capacity, ray_queue_flags(ctx))},
      slots{Buffer<cl_uint>(ctx, with_slots ? capacity : 0), Buffer<cl_uint>(ctx, with_slots ? capacity : 0)} {}

void intersect(EmbreeScene& embree, Buffer<GdrRayHit>& rays, size_t count, bool coherent, const char* kind) {
  if (count == 0) return;
  on_host(rays, count, [&](GdrRayHit* r) { embree.intersect(r, count, coherent, kind); });
}

void occlude(EmbreeScene& embree, Buffer<GdrRay>& rays, size_t count, const char* kind, bool coherent) {
  if (count == 0) return;
  on_host(rays, count, [&](GdrRay* r) { embree.occluded(r, count, coherent, kind); });
}

}  // namespace gdr
