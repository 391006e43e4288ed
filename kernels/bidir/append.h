// What a subpath's vertex appends to the bidirectional queues, written once the work-group has
// reserved its slots (wavefront/group_reserve.h): a shadow ray (toward the camera or a light
// point), the vertex's entry in the connectable list, the ray that continues its subpath.
#pragma once
#include "core/ray_queue.h"
#include "path/spawn.h"
#include "shared/bidir_types.h"
#include "wavefront/group_reserve.h"

typedef struct {
  uint shadow, connectable, next;
  // The shadow ray from p (normal ng): toward point `to` (to_point) or along wi for dist.
  float3 shadow_p, shadow_ng, shadow_to, shadow_wi;
  float shadow_dist;
  int shadow_to_point;
  uint shadow_id;
  float3 next_p, next_ng, next_wi;  // the continuing ray
  uint slot;                        // the subpath's slot (connectable entry, continuing ray's id)
} BidirAppend;

inline void bidir_append_none(BidirAppend* a) { a->shadow = a->connectable = a->next = 0u; }

// Reserves the group's slots and writes item a's entries; slots[0] is its shadow ray's slot (for
// the caller's value beside it).
inline void bidir_append(__local uint* scratch, __global uint* counters, const BidirAppend* a,
                         __global GdrRay* shadow_rays, __global uint* connectable, __global uint* queue_out,
                         __global GdrRayHit* rays_out, uint* slots) {
  const uint which[3] = {BIDIR_COUNTER_SHADOW_RAYS, BIDIR_COUNTER_CONNECTABLE, BIDIR_COUNTER_NEXT_RAYS};
  slots[0] = a->shadow;
  slots[1] = a->connectable;
  slots[2] = a->next;
  group_reserve(scratch, counters, which, 3, slots);
  if (a->shadow) {
    if (a->shadow_to_point) {
      write_segment_ray(&shadow_rays[slots[0]], a->shadow_p, a->shadow_ng, a->shadow_to, a->shadow_id);
    } else {
      write_light_ray(&shadow_rays[slots[0]], a->shadow_p, a->shadow_ng, a->shadow_wi, a->shadow_dist, a->shadow_id);
    }
  }
  if (a->connectable) connectable[slots[1]] = a->slot;
  if (a->next) {
    queue_out[slots[2]] = a->slot;
    spawn_ray(&rays_out[slots[2]], a->next_p, a->next_ng, a->next_wi, a->slot);
  }
}
