#include "render/wavefront/ray_queues.h"

namespace gdr {

RayQueues::RayQueues(Context& ctx, size_t capacity, bool with_slots)
    : rays{Buffer<GdrRayHit>(ctx, capacity, kRayQueueFlags), Buffer<GdrRayHit>(ctx, capacity, kRayQueueFlags)},
      slots{Buffer<cl_uint>(ctx, with_slots ? capacity : 0), Buffer<cl_uint>(ctx, with_slots ? capacity : 0)} {}

void intersect(EmbreeScene& embree, const Buffer<GdrRayHit>& rays, size_t count, bool coherent, const char* kind) {
  if (count == 0) return;
  auto m = rays.map(count);
  embree.intersect(m.data(), count, coherent, kind);
}

void occlude(EmbreeScene& embree, const Buffer<GdrRay>& rays, size_t count, const char* kind) {
  if (count == 0) return;
  auto m = rays.map(count);
  embree.occluded(m.data(), count, kind);
}

}  // namespace gdr
