// The ray queues of a wavefront, double-buffered: a step's kernels read queue `cur` and write
// the next bounce into queue 1 - cur. Embree traverses them on the host: in place where the
// context is zero-copy (CPU devices: mapped), else on a host copy read before and written back
// after (a discrete GPU: the transfers are timed as such).
#pragma once
#include <string>

#include "accel/embree_scene.h"
#include "device/context.h"
#include "shared/ray_types.h"

namespace gdr {

// Zero-copy contexts: host-mapped memory, so that Embree reads and writes the device's rays in
// place; others: device memory, copied around each traversal.
cl_mem_flags ray_queue_flags(const Context& context);

struct RayQueues {
  // `slots`: also a slot per ray (the path state it continues), for integrators whose rays do
  // not name their path in ray.id.
  RayQueues(Context& context, size_t capacity, bool slots);

  Buffer<GdrRayHit> rays[2];
  Buffer<cl_uint> slots[2];
};

// Closest hits of the first `count` rays and occlusion of the first `count` segments, on the
// queue's host mapping or host copy; `kind` names the rays in the stats. `coherent`: rays whose
// neighbours in the queue start at neighbouring points (camera rays, their neighbour pixels' rays
// and the first vertices' shadow rays), which Embree traces faster in its coherent mode.
void intersect(EmbreeScene& embree, Buffer<GdrRayHit>& rays, size_t count, bool coherent, const char* kind);
void occlude(EmbreeScene& embree, Buffer<GdrRay>& rays, size_t count, const char* kind, bool coherent = false);

}  // namespace gdr
