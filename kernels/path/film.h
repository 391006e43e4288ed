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

// Adds one pass's value x to a pixel's running sum and to its sum of squared deviations `m2`
// (Welford's update, with the running mean read from the sum: passes = passes so far, this one
// included). Float is enough here where a float sum of squares is not: each term is a squared
// deviation from the current mean, so nothing cancels.
inline void film_add_moments(__global float4* sum, __global float4* m2, uint pixel, float3 x, int passes) {
  float3 s = sum[pixel].xyz;
  float3 mean_before = passes > 1 ? s / (float)(passes - 1) : x;
  float3 mean_after = (s + x) / (float)passes;
  sum[pixel] = (float4)(s + x, 0.0f);
  m2[pixel] += (float4)((x - mean_before) * (x - mean_after), 0.0f);
}
