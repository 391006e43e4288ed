// Warps of the unit square onto the disk and the hemisphere, with their densities.
#pragma once
#include "core/math.h"

// Shirley-Chiu concentric map: low distortion, continuous.
inline float2 square_to_uniform_disk_concentric(float2 u) {
  float x = 2.0f * u.x - 1.0f, y = 2.0f * u.y - 1.0f;
  if (x == 0.0f && y == 0.0f) return (float2)(0.0f);
  float r, phi;  // phi in units of pi, within [-1/4, 3/4]
  if (fabs(x) > fabs(y)) {
    r = x;
    phi = 0.25f * (y / x);
  } else {
    r = y;
    phi = 0.5f - 0.25f * (x / y);
  }
  // sinpi and cospi need no argument reduction by pi (sincos's was 3.5% of pt's time on PoCL).
  return (float2)(r * cospi(phi), r * sinpi(phi));
}

// Cosine-weighted hemisphere around +z (Malley's method).
inline float3 square_to_cosine_hemisphere(float2 u) {
  float2 d = square_to_uniform_disk_concentric(u);
  float z = safe_sqrt(1.0f - d.x * d.x - d.y * d.y);
  return (float3)(d.x, d.y, z);
}

inline float square_to_cosine_hemisphere_pdf(float3 w) { return fmax(w.z, 0.0f) * M_1_PI_F; }
