// Camera rays: Mitsuba's perspective camera (looks along +z, +x left, +y up) with the pixel
// filter importance-sampled, so every sample has weight 1 and lands in its own pixel only.
#pragma once
#include "core/geometry.h"
#include "shared/scene_types.h"

// Offset from the pixel centre drawn from the filter's distribution (in pixels).
inline float2 sample_filter(int filter, float radius, float2 u) {
  if (filter == FILTER_TENT) {
    float2 r;
    r.x = u.x < 0.5f ? -radius + radius * sqrt(2.0f * u.x) : radius - radius * sqrt(2.0f - 2.0f * u.x);
    r.y = u.y < 0.5f ? -radius + radius * sqrt(2.0f * u.y) : radius - radius * sqrt(2.0f - 2.0f * u.y);
    return r;
  }
  if (filter == FILTER_GAUSSIAN) {
    // Box-Muller with stddev = radius / 4 (Mitsuba truncates at 4 sigma; the tail is < 1e-3).
    float sigma = 0.25f * radius;
    float rr = sigma * sqrt(-2.0f * log(fmax(1.0f - u.x, 1e-12f)));
    float phi = 2.0f * M_PI_F * u.y;
    return (float2)(rr * cos(phi), rr * sin(phi));
  }
  return (float2)((2.0f * u.x - 1.0f) * radius, (2.0f * u.y - 1.0f) * radius);
}

// The ray through film position (fx, fy) in pixels from the top-left corner.
inline void camera_ray(const GdrCamera* cam, float fx, float fy, float3* origin, float3* dir, float* tnear, float* tfar) {
  float3 d = (float3)((1.0f - 2.0f * fx / (float)cam->width) * cam->tan_half_fov_x,
                          (1.0f - 2.0f * fy / (float)cam->height) * cam->tan_half_fov_y, 1.0f);
  d = normalize(d);
  *origin = xform_point(cam->to_world, (float3)(0.0f, 0.0f, 0.0f));
  *dir = normalize(xform_vector(cam->to_world, d));
  *tnear = cam->near_clip / d.z;
  *tfar = cam->far_clip / d.z;
}
