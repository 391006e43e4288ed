// The gradient-domain gather: a pass's per-pixel sums into primal, gradient and direct-light films.
#pragma once
#include "gradient/accumulators.h"
#include "gradient/neighbours.h"
#include "gradient/seen_coverage.h"
#include "path/film.h"

// The sum of pixel p's four pairwise estimates: its base's share of each pair and the offset
// each neighbour shifted into it.
inline float3 gather_pairs(int width, int height, __global const float4* acc, uint p, int x, int y) {
  float3 pairs = (float3)(0.0f);
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    pairs += acc[p * GPT_ACC_COUNT + GPT_ACC_BASE(k)].xyz;
    int nx = x + OFFSET_PIXEL_DX(k), ny = y + OFFSET_PIXEL_DY(k);
    if (nx >= 0 && ny >= 0 && nx < width && ny < height) {
      uint n = (uint)(ny * width + nx);
      int opposite = OFFSET_OPPOSITE(k);
      pairs += acc[n * GPT_ACC_COUNT + GPT_ACC_OFFSET(opposite)].xyz;
    }
  }
  return pairs;
}

// One pass's sums into the film: the primal (each pixel the mean of its four pairwise
// estimates, or G-BDPT's own under --primal power: gbidir/weights.h), the forward-difference
// gradients, and the direct layer: the emission seen directly, the mean of the pass's camera
// samples of it (the base's, and `extra_samples` more where seen_coverage.h sent them: `taking`;
// it updates the pixels' flags), and the other paths kept out of the gradients; for the primal
// and both gradients also the sums of squared deviations (film_add_moments) from which the host
// estimates their per-pixel variance.
// The film layers are those of the pass's half (render/gradient_film.h); `passes` counts the
// passes they hold, this one included.
__kernel void gpt_gather(int width, int height, __global const float4* acc, int extra_samples,
                         __global uint* seen_flags, __global const uint* taking, int passes,
                         __global float4* primal, __global float4* dx, __global float4* dy,
                         __global float4* direct, __global float4* primal_m2, __global float4* dx_m2,
                         __global float4* dy_m2) {
  uint p = get_global_id(0);
  if (p >= (uint)(width * height)) return;
  int x = (int)(p % (uint)width), y = (int)(p / (uint)width);
  float4 s = acc[p * GPT_ACC_COUNT + GPT_ACC_SEEN];
  float samples = 1.0f;
  if (extra_samples > 0) {
    if (taking[p]) samples += (float)extra_samples;
    seen_flags[p] = seen_flags_after(seen_flags[p], s.w, samples);
  }
  float3 seen = s.xyz / samples;
  float3 d = acc[p * GPT_ACC_COUNT + GPT_ACC_DIRECT].xyz + seen;
#if defined(GDR_GBDPT_POWER_PRIMAL)
  float3 value = acc[p * GPT_ACC_COUNT + GPT_ACC_PRIMAL].xyz + seen;
#else
  float3 value = 0.25f * gather_pairs(width, height, acc, p, x, y) + d;
#endif
  float3 gx = (float3)(0.0f), gy = (float3)(0.0f);
  if (x + 1 < width) {
    uint n = p + 1u;
    gx = (acc[p * GPT_ACC_COUNT + GPT_ACC_OFFSET(GPT_DIR_PX)].xyz - acc[p * GPT_ACC_COUNT + GPT_ACC_BASE(GPT_DIR_PX)].xyz) +
         (acc[n * GPT_ACC_COUNT + GPT_ACC_BASE(GPT_DIR_NX)].xyz - acc[n * GPT_ACC_COUNT + GPT_ACC_OFFSET(GPT_DIR_NX)].xyz);
  }
  if (y + 1 < height) {
    uint n = p + (uint)width;
    gy = (acc[p * GPT_ACC_COUNT + GPT_ACC_OFFSET(GPT_DIR_PY)].xyz - acc[p * GPT_ACC_COUNT + GPT_ACC_BASE(GPT_DIR_PY)].xyz) +
         (acc[n * GPT_ACC_COUNT + GPT_ACC_BASE(GPT_DIR_NY)].xyz - acc[n * GPT_ACC_COUNT + GPT_ACC_OFFSET(GPT_DIR_NY)].xyz);
  }
  film_add_moments(primal, primal_m2, p, value, passes);
  film_add_moments(dx, dx_m2, p, gx, passes);
  film_add_moments(dy, dy_m2, p, gy, passes);
  direct[p] += (float4)(d, 0.0f);
}
