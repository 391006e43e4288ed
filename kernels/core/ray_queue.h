// Writing rays into the queues Embree traverses (layouts of kernels/shared/ray_types.h), and the
// random-number blocks of a path, shared by every path-based integrator so that gradient-domain
// shifts replay exactly the numbers the path tracer uses.
#pragma once
#include "core/geometry.h"
#include "shared/ray_types.h"

// Random-number blocks (4 dimensions each) of a path: block 0 for the camera, then two per
// bounce (light sample, BSDF sample + Russian roulette).
#define RNG_BLOCK_CAMERA 0u
#define RNG_BLOCK_LIGHT(depth) (1u + 2u * (uint)(depth))
#define RNG_BLOCK_BSDF(depth) (2u + 2u * (uint)(depth))

inline void write_ray(__global GdrRay* r, float3 o, float3 d, float tnear, float tfar, uint id) {
  r->org_x = o.x;
  r->org_y = o.y;
  r->org_z = o.z;
  r->tnear = tnear;
  r->dir_x = d.x;
  r->dir_y = d.y;
  r->dir_z = d.z;
  r->time = 0.0f;
  r->tfar = tfar;
  r->mask = 0xFFFFFFFFu;
  r->id = id;
  r->flags = 0u;
}

inline void write_ray_hit(__global GdrRayHit* r, float3 o, float3 d, float tnear, float tfar, uint id) {
  write_ray(&r->ray, o, d, tnear, tfar, id);
  r->hit.geomID = GDR_INVALID_ID;
  r->hit.primID = GDR_INVALID_ID;
  r->hit.instID = GDR_INVALID_ID;
}

// A ray from surface point p (geometric normal ng) toward point q, starting off the surface on
// the side it leaves and stopping just short of q, so neither end occludes it.
inline void write_segment_ray(__global GdrRay* r, float3 p, float3 ng, float3 q, uint id) {
  float3 d = q - p;
  float3 o = offset_ray_origin(p, dot(d, ng) > 0.0f ? ng : -ng);
  float3 to_q = q - o;
  float len = length(to_q);
  write_ray(r, o, len > 0.0f ? to_q / len : d, 0.0f, len * (1.0f - 1e-4f), id);
}

// A shadow ray from p toward a light sample (direction wi at distance dist; INFINITY for lights
// at infinity).
inline void write_light_ray(__global GdrRay* r, float3 p, float3 ng, float3 wi, float dist, uint id) {
  if (isinf(dist)) {
    write_ray(r, offset_ray_origin(p, dot(wi, ng) > 0.0f ? ng : -ng), wi, 0.0f, INFINITY, id);
  } else {
    write_segment_ray(r, p, ng, p + wi * dist, id);
  }
}
