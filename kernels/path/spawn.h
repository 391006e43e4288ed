// The ray that continues a path from surface point p (geometric normal ng) along w.
#pragma once
#include "core/ray_queue.h"

inline void spawn_ray(__global GdrRayHit* r, float3 p, float3 ng, float3 w, uint id) {
  write_ray_hit(r, leaving_origin(p, ng, w), w, 0.0f, INFINITY, id);
}
