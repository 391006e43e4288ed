// The sampler seam: a path's random numbers come through sampler_block() only, so another
// integrator can feed other streams without touching the stages. Two streams exist: the
// counter-based generator of core/rng.h keyed by (seed, pixel, sample), and primary-sample-space
// numbers, the states of Metropolis chains (kernels/mlt), which a kernel reads where it declares
// PRIMARY_SAMPLE_ARGS and the host binds chains there (engine/integrators/mlt).
#pragma once
#include "core/rng.h"
#include "sampling/dimensions.h"
#include "shared/sampler_types.h"

// Which path's numbers: (seed, pixel, sample) keys the generator; under chains `pixel` is the
// chain and its state holds the numbers.
typedef struct PathSampler {
  uint seed;
  uint pixel;
  uint sample;
  __global const float* primary;  // the chains' states, or 0
  GdrPrimaryLayout layout;
} PathSampler;

// A kernel's primary-sample-space numbers (layout.chains == 0: none are bound).
#define PRIMARY_SAMPLE_ARGS __global const float *primary_numbers, GdrPrimaryLayout primary_layout
#define PRIMARY_SAMPLE_NAMES primary_numbers, primary_layout

inline PathSampler path_sampler(uint seed, uint pixel, uint sample) {
  PathSampler ps;
  ps.seed = seed;
  ps.pixel = pixel;
  ps.sample = sample;
  ps.primary = 0;
  ps.layout.chains = ps.layout.blocks = ps.layout.camera_only = ps.layout.pad0 = 0u;
  return ps;
}

// The path's sampler in a kernel that declares PRIMARY_SAMPLE_ARGS.
inline PathSampler path_sampler_bound(uint seed, uint pixel, uint sample, __global const float* numbers,
                                      GdrPrimaryLayout layout) {
  PathSampler ps = path_sampler(seed, pixel, sample);
  if (layout.chains > 0u) {
    ps.primary = numbers;
    ps.layout = layout;
  }
  return ps;
}

inline int sampler_is_primary(const PathSampler* ps) { return ps->primary != 0; }

// Four uniforms in [0, 1): dimensions 4*block .. 4*block+3 (blocks: sampling/dimensions.h). A
// chain's state holds the blocks its paths can read; one past it (never read while the layout
// matches the path lengths) comes fresh from the generator at each evaluation, which keeps the
// chain's stationary distribution (the target then is an unbiased estimate, kept with the state).
__attribute__((always_inline)) inline float4 sampler_block(const PathSampler* ps, uint block) {
  if (ps->primary != 0) {
    uint i = primary_block_index(block, &ps->layout);
    if (i != RNG_BLOCK_NOT_HELD) {
      size_t d = (size_t)(4u * i) * ps->layout.chains + ps->pixel, c = ps->layout.chains;
      return (float4)(ps->primary[d], ps->primary[d + c], ps->primary[d + 2 * c], ps->primary[d + 3 * c]);
    }
  }
  return rng_block(ps->seed, ps->pixel, ps->sample, block);
}
