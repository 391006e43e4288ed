// The ray queues of a wavefront, double-buffered: a step's kernels read queue `cur` and write
// the next bounce into queue 1 - cur. Embree traverses them on the host in place (zero-copy
// mappings on CPU devices).
#pragma once
#include <string>

#include "accel/embree_scene.h"
#include "device/context.h"
#include "shared/ray_types.h"

namespace gdr {

// Host-mapped memory, so that Embree reads and writes the device's rays without a copy on CPUs.
constexpr cl_mem_flags kRayQueueFlags = CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR;

struct RayQueues {
  // `slots`: also a slot per ray (the path state it continues), for integrators whose rays do
  // not name their path in ray.id.
  RayQueues(Context& context, size_t capacity, bool slots);

  Buffer<GdrRayHit> rays[2];
  Buffer<cl_uint> slots[2];
};

// Closest hits of the first `count` rays (`coherent`: camera rays) and occlusion of the first
// `count` segments, through the queue's host mapping; `kind` names the rays in the stats.
void intersect(EmbreeScene& embree, const Buffer<GdrRayHit>& rays, size_t count, bool coherent, const char* kind);
void occlude(EmbreeScene& embree, const Buffer<GdrRay>& rays, size_t count, const char* kind);

}  // namespace gdr
