// Warps of the unit square onto the disk and the hemisphere, with their densities.
#pragma once
#include "core/math.h"

// Shirley-Chiu concentric map: low distortion, continuous.
inline float2 square_to_uniform_disk_concentric(float2 u) {
  float x = 2.0f * u.x - 1.0f, y = 2.0f * u.y - 1.0f;
  if (x == 0.0f && y == 0.0f) return (float2)(0.0f);
  float r, phi;
  if (fabs(x) > fabs(y)) {
    r = x;
    phi = (M_PI_F / 4.0f) * (y / x);
  } else {
    r = y;
    phi = (M_PI_F / 2.0f) - (M_PI_F / 4.0f) * (x / y);
  }
  // sincos shares one argument reduction between the two (same values as sin and cos).
  float c;
  float sn = sincos(phi, &c);
  return (float2)(r * c, r * sn);
}

// Cosine-weighted hemisphere around +z (Malley's method).
inline float3 square_to_cosine_hemisphere(float2 u) {
  float2 d = square_to_uniform_disk_concentric(u);
  float z = safe_sqrt(1.0f - d.x * d.x - d.y * d.y);
  return (float3)(d.x, d.y, z);
}

inline float square_to_cosine_hemisphere_pdf(float3 w) { return fmax(w.z, 0.0f) * M_1_PI_F; }
