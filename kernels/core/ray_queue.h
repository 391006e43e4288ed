// Writing rays into the queues Embree traverses (layouts of kernels/shared/ray_types.h).
#pragma once
#include "core/geometry.h"
#include "shared/ray_types.h"

// Origin of a ray leaving surface point p (geometric normal ng) along d: moved off the surface on
// the side d leaves, so the ray cannot hit the surface it starts on.
inline float3 leaving_origin(float3 p, float3 ng, float3 d) {
  return offset_ray_origin(p, dot(d, ng) > 0.0f ? ng : -ng);
}

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
__attribute__((always_inline)) inline void write_segment_ray(__global GdrRay* r, float3 p, float3 ng, float3 q,
                                                              uint id) {
  float3 d = q - p;
  float3 o = leaving_origin(p, ng, d);
  float3 to_q = q - o;
  float len = length(to_q);
  write_ray(r, o, len > 0.0f ? to_q / len : d, 0.0f, len * (1.0f - 1e-4f), id);
}

// A shadow ray from p toward a light sample (direction wi at distance dist; INFINITY for lights
// at infinity).
__attribute__((always_inline)) inline void write_light_ray(__global GdrRay* r, float3 p, float3 ng, float3 wi, float dist, uint id) {
  if (isinf(dist)) {
    write_ray(r, leaving_origin(p, ng, wi), wi, 0.0f, INFINITY, id);
  } else {
    write_segment_ray(r, p, ng, p + wi * dist, id);
  }
}
