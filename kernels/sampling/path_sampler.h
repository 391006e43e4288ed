// The sampler seam: a path's random numbers come through sampler_block() only, so another
// integrator can feed other streams (light subpaths, primary-sample-space numbers) without
// touching the stages. Today's stream is the counter-based generator of core/rng.h.
#pragma once
#include "core/rng.h"
#include "sampling/dimensions.h"

// Which path's numbers: (seed, pixel, sample) keys the stream.
typedef struct PathSampler {
  uint seed;
  uint pixel;
  uint sample;
} PathSampler;

inline PathSampler path_sampler(uint seed, uint pixel, uint sample) {
  PathSampler ps;
  ps.seed = seed;
  ps.pixel = pixel;
  ps.sample = sample;
  return ps;
}

// Four uniforms in [0, 1): dimensions 4*block .. 4*block+3 (blocks: sampling/dimensions.h).
inline float4 sampler_block(const PathSampler* ps, uint block) {
  return rng_block(ps->seed, ps->pixel, ps->sample, block);
}
