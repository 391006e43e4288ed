// Geometry used by every stage: affine transforms stored 3x4 row-major, robust ray origins,
// and the elementary samplers of the lights.
#pragma once
#include "core/frame.h"
#include "core/math.h"

#define GDR_INV_4PI 0.07957747154594766788f

inline float3 xform_point(const float* m, float3 p) {
  return (float3)(m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
                  m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]);
}
inline float3 xform_vector(const float* m, float3 v) {
  return (float3)(m[0] * v.x + m[1] * v.y + m[2] * v.z, m[4] * v.x + m[5] * v.y + m[6] * v.z,
                  m[8] * v.x + m[9] * v.y + m[10] * v.z);
}

inline float max3(float3 v) { return fmax(v.x, fmax(v.y, v.z)); }

// Moves a ray origin off the surface along the normal by a few ulps of the position (Wächter and
// Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems 2019): no
// epsilon to tune, and it works at every scene scale.
inline float offset_component(float p, float n) {
  const float origin = 1.0f / 32.0f, float_scale = 1.0f / 65536.0f, int_scale = 256.0f;
  int of = (int)(int_scale * n);
  float pi = as_float(as_int(p) + (p < 0.0f ? -of : of));
  return fabs(p) < origin ? p + float_scale * n : pi;
}
inline float3 offset_ray_origin(float3 p, float3 n) {
  return (float3)(offset_component(p.x, n.x), offset_component(p.y, n.y), offset_component(p.z, n.z));
}

inline float3 sample_uniform_sphere(float2 u) {
  float z = 1.0f - 2.0f * u.x;
  float r = safe_sqrt(1.0f - z * z);
  float phi = 2.0f * M_PI_F * u.y;
  return (float3)(r * cos(phi), r * sin(phi), z);
}

// Uniform point on a triangle as barycentrics (b1, b2) of vertices 1 and 2.
inline float2 sample_triangle_barycentrics(float2 u) {
  float su = sqrt(u.x);
  return (float2)(su * (1.0f - u.y), su * u.y);
}
