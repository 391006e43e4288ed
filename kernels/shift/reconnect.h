// Reconnection (Lehtinen et al. 2013): the offset connects to the base's next vertex z, for
// pairs of rough vertices.
#pragma once
#include "core/math.h"

// The base went x -> z, the offset goes y -> z (z fixed, with normal nz). The solid-angle
// Jacobian |d w_y / d w_x| = (cos_y' / d_y^2) / (cos_x / d_x^2), with the cosines at z toward y
// and toward x.
inline float reconnect_jacobian(float3 x, float3 y, float3 z, float3 nz) {
  float3 dx = x - z, dy = y - z;
  float lx2 = dot(dx, dx), ly2 = dot(dy, dy);
  if (!(lx2 > 0.0f) || !(ly2 > 0.0f)) return 0.0f;
  float cx = fabs(dot(dx, nz)) * rsqrt(lx2);
  float cy = fabs(dot(dy, nz)) * rsqrt(ly2);
  return safe_div(cy * lx2, cx * ly2);
}
