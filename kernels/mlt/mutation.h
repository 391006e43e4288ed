// The two mutations of primary-sample-space MLT (Kelemen et al. 2002; pbrt-v4's MLTSampler):
// a large step draws a fresh uniform state; a small step moves every dimension by a Gaussian of
// standard deviation sigma, wrapped around [0, 1). Both are symmetric (the proposal density from
// x to y equals that from y to x), so the acceptance is min(1, f(y) / f(x)).
#pragma once
#include "core/rng.h"
#include "shared/mlt_types.h"

// Blocks of the chains' random numbers for one step (rng_block's last argument): the step kind
// and the acceptance, then four dimensions per block of four uniforms.
#define MLT_BLOCK_CONTROL 0u
#define MLT_BLOCK_DIMS 1u

// x + delta on the circle [0, 1): the result never reaches 1 (a float sum can round up to it).
inline float mlt_wrap(float x) {
  x -= floor(x);
  return x < 1.0f ? x : 0.0f;
}

// Two independent standard normals from two uniforms (Box-Muller).
inline float2 mlt_normals(float2 u) {
  float r = sqrt(-2.0f * log(fmax(1.0f - u.x, 1e-30f)));
  float phi = 2.0f * M_PI_F * u.y;
  return (float2)(r * cos(phi), r * sin(phi));
}

// Chain c's step: whether it is a large one, and the uniform that decides its acceptance. Both
// kernels of the step derive it from the same block, so nothing about it is stored between them.
typedef struct MltControl {
  int large;
  float accept;
} MltControl;

inline MltControl mlt_control(const GdrMltParams* p, uint c) {
  float4 u = rng_block(p->seed, c, p->iteration, MLT_BLOCK_CONTROL);
  MltControl k = {u.x < p->large_step, u.y};
  return k;
}

// Dimensions 4k .. 4k + 3 of a large step of chain c at `iteration`: a function of those alone,
// so a state a large step drew can be drawn again (a chain seeded from the bootstrap).
inline float4 mlt_large_block(uint seed, uint c, uint iteration, uint k) {
  return rng_block(seed, c, iteration, MLT_BLOCK_DIMS + k);
}

// Dimensions 4k .. 4k + 3 of chain c's proposal from their current values x (one block of random
// numbers and two Box-Muller transforms serve all four).
inline float4 mlt_mutate_block(const GdrMltParams* p, uint c, uint k, int large, float4 x) {
  float4 u = mlt_large_block(p->seed, c, p->iteration, k);
  if (large) return u;
  float2 a = mlt_normals(u.xy), b = mlt_normals(u.zw);
  float s = p->sigma;
  return (float4)(mlt_wrap(x.x + s * a.x), mlt_wrap(x.y + s * a.y), mlt_wrap(x.z + s * b.x), mlt_wrap(x.w + s * b.y));
}
