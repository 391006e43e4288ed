// Checked film writes: a contribution that is NaN or Inf is dropped and counted (*nonfinite), so
// it never reaches a film.
#pragma once
#include "core/math.h"

inline int finite_or_count(float3 c, __global uint* nonfinite) {
  if (is_finite3(c)) return 1;
  atomic_inc(nonfinite);
  return 0;
}

// c where finite, else zero.
inline float3 checked(float3 c, __global uint* nonfinite) {
  return finite_or_count(c, nonfinite) ? c : (float3)(0.0f);
}

inline void film_add(__global float4* film, uint pixel, float3 c, __global uint* nonfinite) {
  if (finite_or_count(c, nonfinite)) film[pixel] += (float4)(c, 0.0f);
}
